// The reference's container, in x, y only at each vertex's own t: the container at rest (the segments)
// moved by its motion at that t (ContainerGeometry::motion_*; docs/scene-format.md, "A container that moves")
// (src/solver/reference/boundary.cpp; kernels/boundary.cl is its twin):
//   Eq. 4, F_bdr = k_bdr (p_b − x) on a vertex outside the container, p_b the nearest point of its boundary;
// inside, the wall's repulsion on a boundary vertex in Eq. 1's form, and the wall as the element's mirror
// image (Eq. 1 from the element's own triangles, repulsion.cpp); and the containment projection that backs
// them up, a hard constraint applied after those of §5.2 (docs/parameters.md, "Containment"). Holes count:
// the even–odd rule over every ring puts a point inside a hole outside the container.
#pragma once

#include <cstdint>
#include <limits>

#include "animpak/solver/grids.hpp"
#include "animpak/solver/step.hpp"
#include "animpak/state.hpp"
#include "animpak/step_params.hpp"

namespace animpak::reference {

/// Where a point lies against the container (x, y only: the container is the same at every t).
struct ContainerQuery {
  bool inside = true;  ///< inside the outline and outside every hole (even–odd over all rings)
  float distance2 = std::numeric_limits<float>::infinity();  ///< squared distance to the nearest segment
  float qx = 0.0f, qy = 0.0f;  ///< that nearest point (the first segment reaching the minimum wins)
};

/// The even–odd test always; the nearest boundary point only when `nearest` or the point is outside.
/// A world without a container has every point inside. boundary.cpp.
ContainerQuery container_query(const ContainerGeometry& box, float px, float py, bool nearest);

/// The container's motion at time t (ContainerGeometry::motion_*): the two table entries around t
/// (clamped to the table) interpolated linearly in float, w = [a −b; b a] p + e (kernels/boundary.cl,
/// container_frame). Only for a container that moves.
struct ContainerFrame {
  float a = 1.0f, b = 0.0f, ex = 0.0f, ey = 0.0f;
  /// The point w of the plane at this time, taken back to the container at rest.
  void to_rest(float wx, float wy, float& px, float& py) const;
  /// The point p of the container at rest, brought to this time.
  void from_rest(float px, float py, float& wx, float& wy) const;
};
ContainerFrame container_frame(const ContainerGeometry& box, float t);

/// The query of (px, py) at time pt: against the container at rest when it does not move (the same bits as
/// the query above); otherwise the point is taken to the container at rest, queried there, and its nearest
/// point brought back to pt, its squared distance measured there. boundary.cpp.
ContainerQuery container_query(const ContainerGeometry& box, float px, float py, float pt, bool nearest);
/// edge_crosses_container at time pt, both ends taken to the container at rest by the motion at pt.
bool edge_crosses_container(const ContainerGeometry& box, float px, float py, float nx, float ny, float pt);

/// Whether the boundary edge p → n properly crosses a segment of the container's boundary (touching does
/// not count). Both ends may be inside: a reflex corner of the container, such as the heart's notch,
/// then pokes into the element between them (docs/parameters.md, "Containment"). boundary.cpp.
bool edge_crosses_container(const ContainerGeometry& box, float px, float py, float nx, float ny);

/// The container's force on a point, from its query: outside, Eq. 4, k_bdr (p_b − x) in x, y; inside, for
/// a boundary vertex (`boundary`), the wall repels like a neighbour, wall_repulsion · k_rpl · u/|u| ·
/// 1/(ε + |u|²) with u = x − p_b (Eq. 1's form; docs/parameters.md, "Containment"). boundary.cpp.
Vec3f boundary_force(const ForceParams& params, const ContainerQuery& q, float px, float py, bool boundary);

/// The container's force on vertex v. boundary.cpp.
Vec3f boundary_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v);

/// The wall as the mirror image of the element (docs/parameters.md, "Containment"): for a boundary vertex
/// inside the container within wall_range of its nearest wall point q (`wall`, its query with the nearest
/// point), Eq. 1 at the reflection x' = 2q − x from the element's own triangles, summed as
/// repulsion_force sums (near slots of x' in four partials, then far slots, own_only), reflected back
/// across the wall's tangent at q (s − 2 (s·n) n in x, y with n = (x − q)/|x − q|; t unchanged) and
/// weighted wall_mirror · k_rpl. The reflected element is a neighbour at twice the wall distance, so the
/// wall presses as a neighbour would. Zero otherwise, and when wall_mirror is 0. repulsion.cpp.
Vec3f wall_mirror_force(const Topology& topo, const SimState& state, const ForceParams& params,
                        const CollisionGrid& grid, std::int32_t v, const ContainerQuery& wall);

/// Containment: every vertex outside the container moves to the nearest point of the container's boundary,
/// a hair (containment_margin, include/animpak/solver/step.hpp) inside, and stops in x, y. A hard
/// constraint like those of §5.2, because the linear Eq. 4 loses against the stiff springs of a grown
/// element (docs/parameters.md). boundary.cpp, beside the container query it uses (kernels/boundary.cl holds
/// the kernel).
void apply_containment(const Topology& topo, SimState& state);

}  // namespace animpak::reference
