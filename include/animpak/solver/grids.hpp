// The solver's spatial indexes as both backends hold them (docs/architecture.md, "One step"): the collision
// grid of §5.1 and the overlap test's broadphase over the slice boxes (docs/architecture.md, "The overlap
// test"). The reference builds them on the host (include/animpak/reference/grid.hpp, reference/overlap.hpp);
// the OpenCL backend builds the same arrays on the device or reads them back to compare
// (include/animpak/opencl.hpp). kernels/shared_types.h holds their scalar parts as the kernels take them
// (GridInfo, OverlapGridInfo).
#pragma once

#include <cstdint>
#include <vector>

namespace animpak {

/// Envelope-triangle centroids binned into cubic cells over the unit cube (x, y, t), sorted by cell
/// with a stable counting sort (count → exclusive scan → scatter; src/solver/counting_sort.hpp).
struct CollisionGrid {
  std::int32_t n = 0;                       ///< cells per axis
  float cell = 0.0f;                        ///< cell edge
  std::vector<float> cx, cy, ct;            ///< centroid of envelope triangle i
  std::vector<std::int32_t> triangle_cell;  ///< linear cell of envelope triangle i
  std::vector<std::int32_t>
      cell_start;  ///< n³ + 1 entries: cell c holds sorted_triangles[cell_start[c], cell_start[c+1])
  std::vector<std::int32_t> sorted_triangles;  ///< triangle ids, by cell, increasing id within a cell
  /// The element of each slot: env_element[sorted_triangles[k]], laid out in slot order (the kernels'
  /// slot_element), so the cell walks test ownership from one array instead of through two.
  std::vector<std::int32_t> slot_element;
  /// The far field's cell aggregates (docs/parameters.md, "Far field"): a run is the slots of one cell
  /// that belong to one element (consecutive, since ids are element-major). For a run's first slot k,
  /// run_next[k] is one past its last slot and run_cx/cy/ct[k] the mean of its centroids (summed in slot
  /// order, then divided by the count); other slots hold 0. Filled when far_cells is set.
  bool far_cells = false;
  std::vector<std::int32_t> run_next;
  std::vector<float> run_cx, run_cy, run_ct;
};

/// Per global slice, the box of its boundary polygon (x0 ≤ x ≤ x1, y0 ≤ y ≤ y1) and its t (its first
/// vertex's), from one snapshot of positions. On the spline (`tangents` with mode curve_spline) the box
/// also holds each boundary vertex's Bézier handles towards its element's neighbouring slices
/// (curve_handle), so that the union of two slices' boxes holds the curve between them.
/// reference::slice_boxes fills it (overlap.cpp); kernels/overlap.cl is its twin.
struct SliceBoxes {
  std::vector<float> x0, y0, x1, y1, t;
};

/// The overlap test's broadphase (docs/architecture.md, "The overlap test"): a uniform (x, y, t) cell
/// grid over every slice pair's box (the union of its two slices' boxes, from t of one slice to t of
/// the other), listing per cell the elements owning a pair whose box meets the cell, in increasing
/// element order, each once. A grid without cells (nx = 0: a box or slice t is not finite) sends every query
/// to every element.
struct OverlapGrid {
  std::int32_t nx = 0, ny = 0, nt = 0;    ///< cells per axis
  float x0 = 0.0f, y0 = 0.0f, t0 = 0.0f;  ///< the grid's low corner
  float cell = 1.0f, cell_t = 1.0f;       ///< cell edge in x and y, in t
  std::vector<std::int32_t>
      cell_start;  ///< nx · ny · nt + 1 entries: cell c lists elements[cell_start[c], cell_start[c+1])
  std::vector<std::int32_t> elements;  ///< element ids, by cell, increasing within a cell
};

}  // namespace animpak
