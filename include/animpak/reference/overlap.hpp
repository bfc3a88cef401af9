// The reference's overlap test and force, paper Eq. 3 (src/solver/reference/overlap.cpp, curve.cpp):
//   F_ovr = k_ovr Σ_i (p_i − x)
// over the centroids p_i of v's incident slice triangles, for a boundary vertex inside another element or
// whose edge crosses one, plus the depth term of docs/parameters.md, "Overlaps". The test walks every
// element's outline on the curve between slices (include/animpak/curve.hpp; docs/parameters.md, "Motion
// between slices"), so every step first takes each vertex's tangent, then the slice boxes and the
// broadphase over them (docs/architecture.md, "The overlap test"). kernels/curve.cl, overlap.cl and
// overlap_grid.cl are their twins.
#pragma once

#include <cstdint>
#include <vector>

#include "animpak/curve.hpp"
#include "animpak/solver/grids.hpp"
#include "animpak/state.hpp"
#include "animpak/step_params.hpp"

namespace animpak::reference {

/// Every vertex's tangent at its slice (include/animpak/curve.hpp), across the loop seam by the topology's
/// links and along its chains (Topology::curve, Topology::chains; std::invalid_argument without them), from
/// one snapshot: the C2 spline's (`mode` curve_spline), Steffen's (curve_monotone), or Steffen's weighed by
/// nothing (curve_linear: straight lines). curve.cpp.
void curve_tangents(const Topology& topo, const SimState& state, int mode, CurveTangents& out);

/// Fills `out` (SliceBoxes, include/animpak/solver/grids.hpp) from one snapshot of positions: per global
/// slice the box of its boundary polygon and its t; on the spline (`tangents` with mode curve_spline) the
/// box holds each boundary vertex's Bézier handles towards its element's neighbouring slices too
/// (curve_handle). overlap.cpp.
void slice_boxes(const Topology& topo, const SimState& state, const CurveTangents& tangents, SliceBoxes& out);

/// Builds the broadphase from this step's slice boxes: the pairs in increasing slice order, each in
/// every cell its box meets, then the stable counting sort (src/solver/counting_sort.cpp). The OpenCL
/// backend runs it on the boxes read back when it builds its grids on the host; on the device,
/// kernels/overlap_grid.cl builds a grid of its own rule, which gives the same forces. overlap.cpp.
void build_overlap_grid(const Topology& topo, const SliceBoxes& boxes, OverlapGrid& grid);

/// The elements, in increasing order and each once, whose slice-pair boxes may meet the query box
/// x ∈ [ex0, ex1], y ∈ [ey0, ey1] at time pt: the merged lists of the (at most four) cells the box
/// meets, or all `elements` when the box meets more cells or has a NaN. Every element whose pair
/// around pt passes the overlap test's box test is among them. overlap.cpp.
void overlap_candidates(const OverlapGrid& grid, std::int32_t elements, float ex0, float ex1, float ey0, float ey1,
                        float pt, std::vector<std::int32_t>& out);

/// What the overlap test found for one boundary vertex (docs/parameters.md, "Overlaps").
struct OverlapResult {
  bool overlap = false;              ///< v or a point between slices next to it lies inside another element, or
                                     ///< its edge crosses one
  bool inside = false;               ///< v or a point between slices next to it lies inside another element
  float out_x = 0.0f, out_y = 0.0f;  ///< when inside: from the deepest such point to its nearest way out
  bool yield = false;                ///< one of the elements it overlaps is, there, no larger than v's slice (g),
                                     ///< or is primary while v's element is secondary
  bool block = false;                ///< one of the elements it overlaps does not give way to v's element: any,
                                     ///< except a secondary one when v's element is primary
};

/// The overlap test of Eq. 3, at any depth: boundary vertex v (and its boundary edge to the next boundary
/// vertex of its slice) against every other element's boundary polygon on its curve at v's t (`tangents`),
/// skipping elements whose slice boxes miss the edge (only the broadphase's candidates, `grid`, are
/// tried, in increasing element order); then the same between slices, where the paper's discrete test
/// cannot see (§6, §8): each slice interval holds `interval_points` evenly spaced times, at fractions
/// j / (interval_points + 1), and v tests those of the two intervals next to it that lie in the half
/// nearer to v (v and its edge on their curves towards the neighbouring slice, at that time; the middle
/// is tested from both ends). Interior vertices and elements with fewer than two slices never overlap.
/// overlap.cpp.
OverlapResult overlap_test(const Topology& topo, const SimState& state, const SliceBoxes& boxes,
                           const OverlapGrid& grid, const CurveTangents& tangents, std::int32_t v,
                           std::int32_t interval_points);

/// Eq. 3, k_ovr Σ (p_i − x) over centroids p_i of v's incident slice triangles, plus, when v (or a point
/// between slices next to it) is inside another element, k_ovr_depth · (out_x, out_y), its way out, so
/// the push grows with depth (docs/parameters.md). overlap.cpp.
Vec3f overlap_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v,
                    const OverlapResult& overlap);

}  // namespace animpak::reference
