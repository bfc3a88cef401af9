// The reference's collision grid, paper §5.1 (src/solver/reference/grid.cpp): envelope-triangle centroids
// binned into a uniform grid over the unit cube (CollisionGrid, include/animpak/solver/grids.hpp), queried
// by the 3×3×3 block ("near": Eq. 1's exact closest points) and the outer shell of the 5×5×5 block ("far":
// Eq. 1's centroids, or with far_cells one mean centroid per cell and element; docs/parameters.md, "Far
// field"). The grid's cell size and far-field switch shape the grid rather than the step's arithmetic, so
// they come from Params (docs/architecture.md, "One block of step constants"). kernels/grid.cl is its twin.
#pragma once

#include <cstdint>
#include <vector>

#include "animpak/params.hpp"
#include "animpak/solver/grids.hpp"
#include "animpak/state.hpp"

namespace animpak::reference {

/// Cells per axis for a cell edge: the smallest n with n · cell ≥ 1 (25 for 0.04). Throws
/// std::invalid_argument unless 0 < cell_size ≤ 1.
std::int32_t grid_cells_per_axis(double cell_size);

/// Cell index of one coordinate: clamp(floor(c / cell), 0, n − 1); NaN goes to cell 0 (state.hpp).
using animpak::grid_axis_cell;

/// Centroid (a + b + c) / 3 of envelope triangle i, summed left to right.
Vec3f envelope_centroid(const Topology& topo, const SimState& state, std::int32_t i);

CollisionGrid build_collision_grid(const Topology& topo, const SimState& state, const Params& params);

/// Fills slot_element of a grid whose sorted_triangles are set; build_collision_grid calls it, and a
/// device backend's read-back grid too.
void fill_slot_elements(const Topology& topo, CollisionGrid& grid);

/// Fills the far-field runs of a built grid (run_next, run_cx/cy/ct; slot_element must be filled) and
/// sets far_cells; build_collision_grid calls it when params.forces.far_cells is 1, and a device backend's
/// read-back grid too.
void build_far_runs(CollisionGrid& grid);

/// Envelope triangles of elements other than `own_element` whose centroids lie in the 3×3×3 block of
/// cells around q's cell ("near"), or in the 98 cells of the outer shell of the 5×5×5 block ("far").
/// Cells outside the grid are skipped. Order: cells by dz, dy, dx ascending, then sorted order within
/// a cell. `out` is cleared first.
void near_triangles(const CollisionGrid& grid, Vec3f q, std::int32_t own_element, std::vector<std::int32_t>& out);
void far_triangles(const CollisionGrid& grid, Vec3f q, std::int32_t own_element, std::vector<std::int32_t>& out);

/// The near triangles as grid slots, in the same order (the triangle is sorted_triangles[k]): Eq. 1
/// adds each one's term to the partial sum of its slot mod 4 (repulsion_force). With `own_only`, the
/// slots of own_element's triangles instead (the wall's mirror image, wall_mirror_force).
void repulsion_near_slots(const CollisionGrid& grid, Vec3f q, std::int32_t own_element, std::vector<std::int32_t>& out,
                          bool own_only = false);

/// What Eq. 1 visits in the outer shell, as grid slots in the same order: with grid.far_cells the first
/// slot of every run (one per cell and other element), otherwise the slot of every far triangle; with
/// `own_only`, those of own_element instead.
void repulsion_far_slots(const CollisionGrid& grid, Vec3f q, std::int32_t own_element, std::vector<std::int32_t>& out,
                         bool own_only = false);

}  // namespace animpak::reference
