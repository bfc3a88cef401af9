// The curve every vertex of an element follows between its slices, at any time (paper §6;
// include/animpak/curve.hpp): the frames draw it, the quality measures read it, and the coarse-to-fine
// refinement puts the new slices on it (docs/parameters.md, "Coarse to fine").
#include <algorithm>
#include <cmath>

#include "animpak/curve.hpp"
#include "animpak/scene.hpp"

namespace animpak {

std::vector<Vec2> element_tangents(const World& world, const SimState& state, int element) {
  const ElementInstance& inst = world.elements[element];
  const SpacetimeElement& lib = world.library[inst.library];
  const int P = lib.vertices_per_slice(), n = lib.slice_count;
  std::vector<Vec2> out(static_cast<std::size_t>(P) * n);
  const int mode = world.params.forces.motion_curve;
  if (mode == curve_linear || n < 2) return out;
  const Topology& topo = world.topology;
  // build_world fills the topology's links and chains (link_curves).
  require_curve_links(topo, "element_tangents");
  const CurveLinks& links = topo.curve;
  if (mode == curve_monotone) {
    for (int s = 0; s < n; ++s)
      for (int v = 0; v < P; ++v) {
        Vec2& m = out[static_cast<std::size_t>(s) * P + v];
        curve_vertex_tangent(topo, links, state, inst.slice_begin + s, v, m.x, m.y);
      }
    return out;
  }
  // The spline: every track of the chain this element's slices lie on, solved in double as the solver
  // solves it in float (include/animpak/curve.hpp, spline_tangents).
  const CurveChains& chains = topo.chains;
  const std::int32_t c = chains.chain[inst.slice_begin], b = chains.begin[c], len = chains.begin[c + 1] - b;
  std::vector<double> mx(len), my(len), cp(len), z(len);
  for (int v = 0; v < P; ++v) {
    const auto vertex = [&](std::int32_t i) { return topo.slice_begin[chains.slice[b + i]] + v; };
    const auto tau = [&](std::int32_t i) {
      return double(state.t[topo.slice_begin[chains.slice[b + i]]]) + double(chains.offset[b + i]);
    };
    const auto x = [&](std::int32_t i) { return double(state.x[vertex(i)]); };
    const auto y = [&](std::int32_t i) { return double(state.y[vertex(i)]); };
    spline_tangents<double>(len, double(chains.period[c]), tau, x, y, mx, my, cp, z);
    for (int s = 0; s < n; ++s) {
      const std::int32_t i = chains.entry[inst.slice_begin + s] - b;
      out[static_cast<std::size_t>(s) * P + v] = {mx[i], my[i]};
    }
  }
  return out;
}

std::vector<Vec2> element_at(const World& world, const SimState& state, int element, double tf) {
  return element_at(world, state, element, tf, element_tangents(world, state, element));
}

SliceInterval slice_interval(const World& world, const SimState& state, int element, double tf) {
  const ElementInstance& inst = world.elements[element];
  const SpacetimeElement& lib = world.library[inst.library];
  const int P = lib.vertices_per_slice(), n = lib.slice_count;
  auto slice_t = [&](int s) { return double(state.t[inst.vertex_begin + s * P]); };
  // Slices stay ordered (time springs) and flat (simultaneity), so the first vertex's t is the slice's.
  int s = 0;
  while (s < n - 2 && slice_t(s + 1) < tf) ++s;
  const double t0 = slice_t(s), t1 = slice_t(s + 1);
  return {s, t1 > t0 ? std::clamp((tf - t0) / (t1 - t0), 0.0, 1.0) : 0.0, t1 - t0};
}

std::vector<Vec2> element_at(const World& world, const SimState& state, int element, double tf,
                             const std::vector<Vec2>& tangents) {
  const ElementInstance& inst = world.elements[element];
  const SpacetimeElement& lib = world.library[inst.library];
  const int P = lib.vertices_per_slice(), n = lib.slice_count;
  std::vector<Vec2> out(P);
  if (n < 2) {
    for (int v = 0; v < P; ++v) out[v] = {state.x[inst.vertex_begin + v], state.y[inst.vertex_begin + v]};
    return out;
  }
  const SliceInterval at = slice_interval(world, state, element, tf);
  const int s = at.slice;
  // The curve the overlap test walks (include/animpak/curve.hpp), in double, with the tangents at this
  // interval's two slices.
  const CurveBasis<double> basis = curve_basis(at.share, at.length, world.params.forces.motion_curve);
  for (int v = 0; v < P; ++v) {
    const int a = inst.vertex_begin + s * P + v, b = a + P;
    const Vec2 ma = tangents[static_cast<std::size_t>(s) * P + v],
               mb = tangents[static_cast<std::size_t>(s + 1) * P + v];
    out[v] = {curve_value<double>(state.x[a], state.x[b], ma.x, mb.x, basis),
              curve_value<double>(state.y[a], state.y[b], ma.y, mb.y, basis)};
  }
  return out;
}

}  // namespace animpak
