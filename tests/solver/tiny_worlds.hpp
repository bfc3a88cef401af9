// Hand-built Topology and SimState values for the reference-solver tests: elements whose slices are
// boundary rings only (a fan of slice triangles, ring edge springs, time springs between slices and
// the envelope between consecutive rings), plus loose springs, target points and the container.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "animpak/element.hpp"
#include "animpak/reference.hpp"
#include "animpak/scene.hpp"

namespace animpak::test {

/// One growth step as both backends take it: each slice's proposal, then the element and neighbour limits.
/// `closest` is each vertex's gap (step_forces); without it every gap is 0, so a free slice grows at
/// growth_rate itself (growth_multiplier 1).
inline std::int32_t grow_step(const Topology& topo, const std::vector<std::uint8_t>& contact,
                              const std::vector<float>& closest, const Params& params, bool growing, SimState& state,
                              std::vector<std::uint8_t>& changed) {
  std::vector<float> proposed;
  const ForceParams step = step_params(params);
  reference::propose_growth(topo, contact, closest, step, growing, state, proposed);
  return reference::grow_slices(topo, proposed, step, state, changed);
}
inline std::int32_t grow_step(const Topology& topo, const std::vector<std::uint8_t>& contact, const Params& params,
                              bool growing, SimState& state, std::vector<std::uint8_t>& changed) {
  return grow_step(topo, contact, std::vector<float>(contact.size(), 0.0f), params, growing, state, changed);
}

/// The paper's constants as printed (§5), taken literally: round numbers that make the expected values
/// in these tests checkable by hand. The library's defaults are these converted to the unit container
/// (docs/parameters.md), which would hide the arithmetic behind factors of 500.
inline animpak::Params paper_params() {
  animpak::Params p;
  p.forces.k_repulsion = 10.0;
  p.forces.repulsion_epsilon = 1.0;
  p.forces.k_edge = 10.0;
  p.forces.k_shear = 10.0;
  p.forces.k_negative_space = 0.1;
  p.forces.k_time = 0.01;
  p.forces.k_target = 10.0;
  p.forces.k_overlap = 5.0;
  p.forces.k_boundary = 5.0;
  p.forces.k_torsion = 0.1;
  p.forces.k_temporal = 1.0;
  p.forces.dt = 0.01;
  p.forces.velocity_cap = 10.0;
  p.growth.growth_rate = 0.001;
  p.forces.far_cells = 0;  // the paper's far shell: every triangle's centroid (Params{} covers the cell aggregates)
  return p;
}

using Ring = std::vector<std::array<float, 2>>;

struct TinySlice {
  Ring ring;
  float t = 0.0f;
};

struct TinyWorld {
  Topology topo;
  SimState state;
};

/// Axis-aligned square ring of half-size h about (cx, cy), in polygon order.
inline Ring square(float cx, float cy, float h) {
  return {{cx - h, cy - h}, {cx + h, cy - h}, {cx + h, cy + h}, {cx - h, cy + h}};
}

class WorldBuilder {
 public:
  WorldBuilder() {
    topo_.element_slice_begin.push_back(0);
    topo_.slice_begin.push_back(0);
    set_container({square(0.5f, 0.5f, 0.5f)});
  }

  /// Adds an element; every slice's ring must have the same size. Returns the element id.
  std::int32_t add_element(const std::vector<TinySlice>& slices, bool ring_springs = true) {
    const std::int32_t e = topo_.element_count();
    const std::int32_t first_vertex = static_cast<std::int32_t>(state_.x.size());
    const std::int32_t per_slice = static_cast<std::int32_t>(slices.front().ring.size());
    for (std::size_t s = 0; s < slices.size(); ++s) {
      const std::int32_t slice_id = topo_.slice_count();
      float mx = 0.0f, my = 0.0f;
      for (const auto& p : slices[s].ring) mx += p[0], my += p[1];
      mx /= static_cast<float>(per_slice);
      my /= static_cast<float>(per_slice);
      for (const auto& p : slices[s].ring) {
        const std::uint8_t flags = vertex_boundary;
        const float dx = p[0] - mx, dy = p[1] - my, len = std::sqrt(dx * dx + dy * dy);
        add_vertex(e, slice_id, flags, p[0], p[1], slices[s].t, len > 0.0f ? dx / len : 0.0f,
                   len > 0.0f ? dy / len : 0.0f);
      }
      const std::int32_t base = first_vertex + static_cast<std::int32_t>(s) * per_slice;
      for (std::int32_t k = 1; k + 1 < per_slice; ++k) tris_.push_back({base, base + k, base + k + 1});
      if (ring_springs)
        for (std::int32_t k = 0; k < per_slice; ++k)
          add_spring(base + k, base + (k + 1) % per_slice, SpringClass::edge);
      if (s > 0) {
        const std::int32_t below = base - per_slice;
        for (std::int32_t k = 0; k < per_slice; ++k) {
          add_spring(below + k, base + k, SpringClass::time);
          const std::int32_t j = (k + 1) % per_slice;
          add_envelope(below + k, below + j, base + k, e);
          add_envelope(below + j, base + j, base + k, e);
        }
      }
      topo_.slice_boundary.push_back(per_slice);
      topo_.slice_element.push_back(e);
      topo_.slice_begin.push_back(static_cast<std::int32_t>(state_.x.size()));
    }
    topo_.element_slice_begin.push_back(topo_.slice_count());
    return e;
  }

  /// A spring between two vertices; a negative rest length means "as placed".
  void add_spring(std::int32_t a, std::int32_t b, SpringClass c, float rest = -1.0f) {
    if (rest < 0.0f) {
      const float dx = state_.x[b] - state_.x[a], dy = state_.y[b] - state_.y[a], dt = state_.t[b] - state_.t[a];
      rest = std::sqrt(dx * dx + dy * dy + dt * dt);
    }
    springs_.push_back({a, b, c, rest});
  }

  void add_target(std::int32_t v, float x, float y, float t) {
    topo_.target[v] = static_cast<std::int32_t>(topo_.target_x.size());
    topo_.flags[v] |= vertex_anchor;
    topo_.target_x.push_back(x);
    topo_.target_y.push_back(y);
    topo_.target_t.push_back(t);
  }

  void add_loop(std::int32_t end, std::int32_t start) {
    topo_.loop_end.push_back(end);
    topo_.loop_start.push_back(start);
  }

  /// Ring 0 is the outline, the others holes.
  void set_container(const std::vector<Ring>& rings) {
    ContainerGeometry c;
    for (const Ring& r : rings) {
      c.ring_begin.push_back(static_cast<std::int32_t>(c.ax.size()));
      for (std::size_t k = 0; k < r.size(); ++k) {
        const auto& a = r[k];
        const auto& b = r[(k + 1) % r.size()];
        c.ax.push_back(a[0]), c.ay.push_back(a[1]), c.bx.push_back(b[0]), c.by.push_back(b[1]);
      }
    }
    c.ring_begin.push_back(static_cast<std::int32_t>(c.ax.size()));
    index_container(c);  // as a scene's world does, so every test world queries through the index
    topo_.container = c;
  }

  TinyWorld build() const {
    TinyWorld w{topo_, state_};
    const std::int32_t n = topo_.vertex_count();
    // Springs: CSR with each spring at both ends, slots in insertion order.
    std::vector<std::vector<LooseSpring>> slots(n);
    for (const LooseSpring& s : springs_) {
      slots[s.a].push_back(s);
      slots[s.b].push_back({s.b, s.a, s.c, s.rest});
    }
    w.topo.spring_begin.assign(1, 0);
    for (std::int32_t v = 0; v < n; ++v) {
      for (const LooseSpring& s : slots[v]) {
        w.topo.spring_other.push_back(s.b);
        w.topo.spring_class.push_back(static_cast<std::uint8_t>(s.c));
        w.state.spring_rest.push_back(s.rest);
      }
      w.topo.spring_begin.push_back(static_cast<std::int32_t>(w.topo.spring_other.size()));
    }
    // Slice triangles and each vertex's incident list.
    std::vector<std::vector<std::int32_t>> incident(n);
    for (std::size_t i = 0; i < tris_.size(); ++i) {
      w.topo.tri_a.push_back(tris_[i][0]);
      w.topo.tri_b.push_back(tris_[i][1]);
      w.topo.tri_c.push_back(tris_[i][2]);
      for (const std::int32_t v : tris_[i]) incident[v].push_back(static_cast<std::int32_t>(i));
    }
    w.topo.tri_begin.assign(1, 0);
    for (std::int32_t v = 0; v < n; ++v) {
      w.topo.tri_list.insert(w.topo.tri_list.end(), incident[v].begin(), incident[v].end());
      w.topo.tri_begin.push_back(static_cast<std::int32_t>(w.topo.tri_list.size()));
    }
    w.state.vx.assign(n, 0.0f);
    w.state.vy.assign(n, 0.0f);
    w.state.vt.assign(n, 0.0f);
    w.state.growth.assign(topo_.slice_count(), 1.0f);
    // The rest copy (growth's reference, and the fold guard's rest areas): the shape as placed.
    w.topo.rest_copy_x = w.state.x;
    w.topo.rest_copy_y = w.state.y;
    w.topo.rest_copy_t = w.state.t;
    reference::slice_centroids(w.topo, w.state, w.topo.slice_rest_copy_cx, w.topo.slice_rest_copy_cy);
    link_curves(w.topo);  // as build_world does: the curve's links and chains, once
    return w;
  }

 private:
  struct LooseSpring {
    std::int32_t a, b;
    SpringClass c;
    float rest;
  };

  void add_vertex(std::int32_t e, std::int32_t s, std::uint8_t flags, float x, float y, float t, float rx, float ry) {
    topo_.element.push_back(e);
    topo_.slice.push_back(s);
    topo_.flags.push_back(flags);
    topo_.rest_t.push_back(t);
    topo_.rest_dir_x.push_back(rx);
    topo_.rest_dir_y.push_back(ry);
    topo_.target.push_back(-1);
    state_.x.push_back(x);
    state_.y.push_back(y);
    state_.t.push_back(t);
  }

  void add_envelope(std::int32_t a, std::int32_t b, std::int32_t c, std::int32_t e) {
    topo_.env_a.push_back(a);
    topo_.env_b.push_back(b);
    topo_.env_c.push_back(c);
    topo_.env_element.push_back(e);
  }

  Topology topo_;
  SimState state_;
  std::vector<LooseSpring> springs_;
  std::vector<std::array<std::int32_t, 3>> tris_;
};

/// A square element of half-size h about (cx, cy), extruded straight over the given slice times.
inline std::vector<TinySlice> square_tube(float cx, float cy, float h, const std::vector<float>& times) {
  std::vector<TinySlice> slices;
  for (const float t : times) slices.push_back({square(cx, cy, h), t});
  return slices;
}

/// The curve tangents of a world's state as the step computes them (default Params: the spline).
inline CurveTangents tangents(const TinyWorld& w, int mode = Params{}.forces.motion_curve) {
  CurveTangents m;
  reference::curve_tangents(w.topo, w.state, mode, m);
  return m;
}

}  // namespace animpak::test
