// The reference's repulsion force, paper Eq. 1 (src/solver/reference/repulsion.cpp):
//   F_rpl = k_rpl Σ_i u/|u| · 1/(ε + |u|²),  u = x − x_i,
// on slice-boundary vertices, over the collision grid's near triangles (exact closest points,
// closest_point_on_triangle) and far shell (centroids, §5.1; grid.hpp), summed in the order
// kernels/repulsion.cl sums it (docs/architecture.md, "The near block in lanes"). The wall's mirror image,
// Eq. 1 again from the element's own triangles, is in boundary.hpp.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "animpak/closest_point.hpp"
#include "animpak/solver/grids.hpp"
#include "animpak/state.hpp"
#include "animpak/step_params.hpp"

namespace animpak::reference {

struct RepulsionResult {
  Vec3f force;
  float closest = std::numeric_limits<float>::infinity();  ///< distance to the nearest other element
};

/// Eq. 1 on a boundary vertex: k_rpl Σ u/|u| · 1/(ε + |u|²), u = x − x_i over exact closest points on
/// the triangles of the `near` slots (repulsion_near_slots), summed in four partials by slot mod 4 and joined as
/// (p0 + p1) + (p2 + p3), then one by one over the `far` slots (repulsion_far_slots): a triangle's centroid, or
/// with grid.far_cells a run's mean centroid counted once per triangle of the run. The force is zero when
/// `overlapping` (Eq. 3 takes over) or v is not a boundary vertex; `closest` is computed for every
/// boundary vertex.
/// repulsion.cpp.
RepulsionResult repulsion_force(const Topology& topo, const SimState& state, const ForceParams& params,
                                const CollisionGrid& grid, std::int32_t v, const std::vector<std::int32_t>& near,
                                const std::vector<std::int32_t>& far, bool overlapping);

}  // namespace animpak::reference
