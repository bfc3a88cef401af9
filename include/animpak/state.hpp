// The simulation's data (docs/architecture.md, "The solver's data"): a flat structure-of-arrays state that moves,
// and a topology that does not. Both backends (the scalar reference, the OpenCL kernels) read and write
// exactly these arrays. Units: the normalized container, x, y in [0, 1] (y down), t in [0, 1].
// All simulation arithmetic is float, in an order both backends share (equivalence by construction).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "animpak/params.hpp"

namespace animpak {

struct Vec3f {
  float x = 0.0f, y = 0.0f, t = 0.0f;
};

enum VertexFlag : std::uint8_t {
  vertex_boundary = 1,     ///< on its slice's outer boundary (repulsion, overlap, envelope)
  vertex_anchor = 2,       ///< a guided element's anchor on a slice with a target (has a target-point spring)
  vertex_hold_angle = 16,  ///< on a guided element's slice whose target gives an angle: Eq. 5 with k_target_angle
};

/// What the overlap and container tests found at a vertex (StepForces::contact), one bit each; the
/// kernels use the same values (shared_types.h, AP_CONTACT_*).
enum ContactBit : std::uint8_t {
  contact_overlap = 1,  ///< inside another element, or its boundary edge crosses one (growth shrinks)
  contact_outside = 2,  ///< outside the container (growth shrinks)
  contact_wall = 4,     ///< a boundary vertex nearer the container's boundary than stop_gap (growth pauses)
  contact_inside = 8,   ///< inside another element (the depth term of the overlap force)
  contact_yield = 16,   ///< overlaps an element no larger than its own slice there (growth shrinks; else pauses)
  /// overlaps an element that does not give way to it: any element, except a secondary one when this
  /// element is primary (docs/parameters.md, "Secondary elements"). Growth reads this bit, not
  /// contact_overlap; without secondary elements the two are equal.
  contact_block = 32,
};

/// The container query's index over the segments (docs/architecture.md, "The far field and the
/// container query"): an nx × ny cell grid over the segments' bounding box. Row j of the grid is a band
/// of y: its segments are those whose y range meets the band, the only ones the even–odd ray at a y in
/// the band can cross.
/// Cell (i, j) lists every segment that can be nearest to some point of the cell (its distance to the
/// cell is at most the smallest largest-distance of any segment to the cell). Lists ascend by segment
/// index. All lists live in `data`: band_start (ny + 1 entries) at 0, then the band lists from
/// `band_segments`, cell_start (nx · ny + 1) from `cell_start`, the cell lists from `cell_segments`.
/// nx = 0: no index, every query tries every segment.
struct ContainerIndex {
  float x0 = 0.0f, y0 = 0.0f, cell = 0.0f;
  std::int32_t nx = 0, ny = 0;
  std::int32_t band_segments = 0, cell_start = 0, cell_segments = 0;
  std::vector<std::int32_t> data;
};

/// The container extruded over t: line segments of the outline and of every hole.
struct ContainerGeometry {
  std::vector<float> ax, ay, bx, by;     ///< segment i runs from (ax[i], ay[i]) to (bx[i], by[i])
  std::vector<std::int32_t> ring_begin;  ///< ring r is segments [ring_begin[r], ring_begin[r+1]); ring 0 the outline
  ContainerIndex index;                  ///< built by index_container; empty: every query tries every segment
  /// Its motion (include/animpak/container_motion.hpp) as the solver reads it: kContainerMotionIntervals + 1
  /// entries over t in [0, 1] of the similarity w = [a −b; b a] p + e from the segments (the container at
  /// rest) to the container at t, linearly interpolated between entries (container_frame in
  /// src/solver/reference/boundary.cpp, kernels/boundary.cl). Empty: it does not move.
  std::vector<float> motion_a, motion_b, motion_ex, motion_ey;
  bool moves() const { return !motion_a.empty(); }
};

/// Cell of one coordinate on a uniform grid of n cells of edge `cell` from 0: clamp(floor(c / cell), 0,
/// n − 1) in float, NaN to 0. Every grid of the solver uses it (the collision grid, the overlap test's
/// broadphase and the container index, each with c measured from its corner), as does grid.cl: the
/// clamp happens in float so the conversion never sees an out-of-range value, and the function never
/// decreases as c grows, which is what lets an index list a segment or box in every cell a query can
/// land in.
inline std::int32_t grid_axis_cell(float c, float cell, std::int32_t n) {
  float f = std::floor(c / cell);
  if (!(f >= 0.0f)) f = 0.0f;
  const float last = static_cast<float>(n - 1);
  if (f > last) f = last;
  return static_cast<std::int32_t>(f);
}

/// The collision grid's linear cell of point (x, y, t) on its n × n × n cells of edge `cell`: t-major,
/// then y, then x (grid.cl's grid_linear_cell).
inline std::int32_t grid_linear_cell(float x, float y, float t, float cell, std::int32_t n) {
  return (grid_axis_cell(t, cell, n) * n + grid_axis_cell(y, cell, n)) * n + grid_axis_cell(x, cell, n);
}

// The curve every vertex follows between its slices (include/animpak/curve.hpp; docs/parameters.md, "Motion
// between slices") runs along these links and chains. They depend only on the element ranges and loop pairs,
// so a topology holds them (Topology::curve, Topology::chains), filled once where it is built (link_curves).

/// Where each global slice's vertices continue in time: the slice before and the slice after, vertex k
/// to vertex k, or -1 at an open end. Within an element, its neighbours; across a looping scene's seam
/// (t = 1 ≡ t = 0, §5.2's loop constraint), the last slice's next is the slice after its loop partner's
/// first, and the first slice's previous is the slice before the last of the element that loops into it.
struct CurveLinks {
  std::vector<std::int32_t> prev, next;
};

/// The spline's tracks: every slice, in time order, on chains that the C2 spline runs through. Within an
/// element a chain goes slice by slice; across a looping scene's seam it goes on from an element's last
/// slice to the slice after its loop partner's first (curve_links' `next`), so a looping chain closes on
/// itself and spans `period` loops (two penguins that swap places: one chain over both, two loops). A
/// looping element's first slice is its loop partner's last (the loop constraint, §5.2) and takes that
/// slice's tangents (`alias`). Vertex k of every slice on a chain is one track: one system to solve.
struct CurveChains {
  std::vector<std::int32_t> begin;  ///< chains + 1: chain c's entries are [begin[c], begin[c + 1])
  std::vector<std::int32_t> slice;  ///< per entry: its global slice, in time order
  std::vector<float> offset;        ///< per entry: the loops added to its slice's t along the chain
  std::vector<std::int32_t> alias;  ///< per entry: the slice that takes its tangents, or -1
  std::vector<float> period;        ///< per chain: the loops a closed chain spans, 0 for an open one
  std::vector<std::int32_t> entry;  ///< per slice: the entry whose tangents it has (its own or its alias's)
  std::vector<std::int32_t> chain;  ///< per slice: the chain of `entry`
  std::vector<std::int32_t> track_vertex, track_chain;  ///< per track: vertex k of its chain's first slice
};

/// Everything that does not move during a simulation. Vertex ids are global (all elements).
struct Topology {
  // per vertex
  std::vector<std::int32_t> element;          ///< element id
  std::vector<std::int32_t> slice;            ///< global slice id
  std::vector<std::uint8_t> flags;            ///< VertexFlag bits
  std::vector<float> rest_t;                  ///< t of its slice at creation (temporal force, Eq. 6)
  std::vector<float> rest_dir_x, rest_dir_y;  ///< unit rest orientation about the slice centroid (Eq. 5)
  std::vector<std::int32_t> target;           ///< target-point index, or -1

  // springs as CSR: vertex v's springs are [spring_begin[v], spring_begin[v+1]); rest lengths live in
  // SimState::spring_rest because growth changes them
  std::vector<std::int32_t> spring_begin;
  std::vector<std::int32_t> spring_other;
  std::vector<std::uint8_t> spring_class;  ///< SpringClass

  // slice triangles (overlap force, Eq. 3): vertex v's incident triangles are
  // tri_list[tri_begin[v] .. tri_begin[v+1]), indices into tri_a/b/c
  std::vector<std::int32_t> tri_a, tri_b, tri_c;
  std::vector<std::int32_t> tri_begin, tri_list;

  // slices: global slice s holds vertices [slice_begin[s], slice_begin[s+1]); its boundary vertices
  // come first, slice_boundary[s] of them
  std::vector<std::int32_t> slice_begin;
  std::vector<std::int32_t> slice_boundary;
  std::vector<std::int32_t> slice_element;
  // elements: element e holds slices [element_slice_begin[e], element_slice_begin[e+1])
  std::vector<std::int32_t> element_slice_begin;
  /// per element: 1 for a secondary element (docs/parameters.md, "Secondary elements"): it gives way to
  /// every primary element and grows only once the primary ones have stopped.
  std::vector<std::uint8_t> element_secondary;

  // envelope triangles, index triples, with their element
  std::vector<std::int32_t> env_a, env_b, env_c, env_element;

  // target points of guided elements
  std::vector<float> target_x, target_y, target_t;

  // loop constraint: vertex loop_end[i] (on a t = 1 slice) coincides with loop_start[i] (t = 0 slice)
  std::vector<std::int32_t> loop_end, loop_start;

  // the curve between slices, from the slice and element ranges and the loop pairs above: link_curves
  // (include/animpak/curve.hpp) fills both once they are set; the reference's tangents, the OpenCL
  // backend's buffers and the frames read them
  CurveLinks curve;    ///< curve_links(*this): where each slice's curve continues
  CurveChains chains;  ///< curve_chains(*this, curve): the spline's tracks

  ContainerGeometry container;

  // the rest copy: the paper's shrunken "reference" duplicate of each element (§5.3), named apart from
  // the reference solver. Rest lengths are measured on it, each slice scaled by its g
  // about the slice's rest copy centroid
  std::vector<float> rest_copy_x, rest_copy_y, rest_copy_t;   ///< per vertex
  std::vector<float> slice_rest_copy_cx, slice_rest_copy_cy;  ///< per global slice

  std::int32_t vertex_count() const { return static_cast<std::int32_t>(element.size()); }
  std::int32_t slice_count() const { return static_cast<std::int32_t>(slice_boundary.size()); }
  std::int32_t element_count() const { return static_cast<std::int32_t>(element_slice_begin.size()) - 1; }
  std::int32_t envelope_count() const { return static_cast<std::int32_t>(env_a.size()); }
  /// Element e is secondary; a topology without the array (built by hand in tests) has none.
  bool secondary(std::int32_t e) const {
    return static_cast<std::size_t>(e) < element_secondary.size() && element_secondary[e] != 0;
  }
  bool has_secondary() const {
    for (const std::uint8_t s : element_secondary)
      if (s != 0) return true;
    return false;
  }
};

/// Everything that moves.
struct SimState {
  std::vector<float> x, y, t;      ///< positions, per vertex
  std::vector<float> vx, vy, vt;   ///< velocities, per vertex
  std::vector<float> spring_rest;  ///< rest length per CSR slot (both ends of a spring hold the same value)
  std::vector<float> growth;       ///< g per global slice (§5.3)
  std::uint64_t iteration = 0;
  /// The iteration at which growth stopped for the settling phase (docs/parameters.md, "Stop test"),
  /// or 0 while slices still grow.
  std::uint64_t settling_since = 0;
  /// The iteration at which the secondary elements began to grow (docs/parameters.md, "Secondary
  /// elements"), or 0 while they are held at their start size (or the world has none).
  std::uint64_t secondary_since = 0;
  /// The run's last progress mark (docs/parameters.md, "Stop test"): the iteration (0: none yet) and the
  /// mean g of all slices then. The stall test runs stall_tests times per stall_window, one test's
  /// spacing after the last mark, and compares the mean g with the mark one window back.
  std::uint64_t mark_iteration = 0;
  double mark_growth = 0.0;
  /// The mean g at the marks one, two and three tests before the last (0: no such mark yet).
  double mark_growth_1 = 0.0, mark_growth_2 = 0.0, mark_growth_3 = 0.0;
};

/// Copies the stall test's progress marks (mark_iteration, mark_growth, mark_growth_1 … 3) of `from`
/// into `to`, the rest of `to` as it is.
inline void copy_progress_marks(const SimState& from, SimState& to) {
  to.mark_iteration = from.mark_iteration;
  to.mark_growth = from.mark_growth;
  to.mark_growth_1 = from.mark_growth_1;
  to.mark_growth_2 = from.mark_growth_2;
  to.mark_growth_3 = from.mark_growth_3;
}

/// §5.3: the rest length of CSR slot `slot` of vertex `v`: the distance between the spring's two ends
/// in the rest copy, each end's slice scaled by its g about that slice's rest copy centroid. Time
/// springs join two slices with different g; the t distance is not scaled.
inline float rest_copy_length(const Topology& topo, const std::vector<float>& growth, std::int32_t v,
                              std::int32_t slot) {
  const std::int32_t w = topo.spring_other[slot];
  const std::int32_t sv = topo.slice[v], sw = topo.slice[w];
  const float xv = topo.slice_rest_copy_cx[sv] + growth[sv] * (topo.rest_copy_x[v] - topo.slice_rest_copy_cx[sv]);
  const float yv = topo.slice_rest_copy_cy[sv] + growth[sv] * (topo.rest_copy_y[v] - topo.slice_rest_copy_cy[sv]);
  const float xw = topo.slice_rest_copy_cx[sw] + growth[sw] * (topo.rest_copy_x[w] - topo.slice_rest_copy_cx[sw]);
  const float yw = topo.slice_rest_copy_cy[sw] + growth[sw] * (topo.rest_copy_y[w] - topo.slice_rest_copy_cy[sw]);
  const float dx = xw - xv, dy = yw - yv, dt = topo.rest_copy_t[w] - topo.rest_copy_t[v];
  return std::sqrt(dx * dx + dy * dy + dt * dt);
}

}  // namespace animpak
