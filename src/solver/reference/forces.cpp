// Total force, paper Eq. 7, for every vertex from one snapshot of positions (docs/parameters.md lists
// what we add to the paper). Per vertex, in this order: the grid queries, the overlap test (Eq. 3
// replaces Eq. 1 for a vertex that overlaps another element), the container query, then each force.
// The sum is formed left to right in the order of AP_FORCE_TERMS (kernels/shared_types.h), Eq. 7's,
// with the target-point spring (an Eq. 2 spring) right after the edge springs, the fold guard added to
// the springs' sum (F_edg = springs + fold), and the forces of AP_LOCAL_FORCES last:
//   F = ((((((F_rpl + F_edg) + F_tgt) + F_bdr) + F_ovr) + F_tor) + F_tmp)
// The kernels add in exactly this order. Each vertex's gap and contact bits come from the same queries
// (contact_gap, contact.cpp; the kernel contact_gap runs after step_forces).
#include <cmath>

#include "animpak/compare.hpp"
#include "animpak/reference/boundary.hpp"
#include "animpak/reference/grid.hpp"
#include "animpak/reference/local_forces.hpp"
#include "animpak/reference/overlap.hpp"
#include "animpak/reference/repulsion.hpp"
#include "animpak/reference/step.hpp"

namespace animpak::reference {

StepForces step_forces(const Topology& topo, const SimState& state, const ForceParams& params,
                       const CollisionGrid& grid, ForceBreakdown* out) {
  const std::int32_t n = topo.vertex_count();
  StepForces r;
  r.total.assign(n);
  r.closest.assign(n, std::numeric_limits<float>::infinity());
  r.contact.assign(n, 0);
  if (out != nullptr)
    for (const NamedForce& f : breakdown_forces) (out->*f.field).assign(n);

  // Per-slice passes first, whose results every vertex of the slice reads: the centroids (Eq. 5) and the
  // boxes of the boundary polygons with the overlap test's broadphase over them.
  std::vector<float> cx, cy;
  slice_centroids(topo, state, cx, cy);
  // The curve between slices that the overlap test walks, as the frames show it; the boxes hold it.
  CurveTangents tangents;
  curve_tangents(topo, state, params.motion_curve, tangents);
  SliceBoxes boxes;
  slice_boxes(topo, state, tangents, boxes);
  OverlapGrid overlap_grid;
  build_overlap_grid(topo, boxes, overlap_grid);
  const float k_mirror = params.k_mirror;

  std::vector<std::int32_t> near, far;
  for (std::int32_t v = 0; v < n; ++v) {
    near.clear();
    far.clear();
    const bool boundary = (topo.flags[v] & vertex_boundary) != 0;
    const float px = state.x[v], py = state.y[v];
    if (boundary) {
      const Vec3f q{px, py, state.t[v]};
      repulsion_near_slots(grid, q, topo.element[v], near);
      repulsion_far_slots(grid, q, topo.element[v], far);
    }
    const OverlapResult overlap = overlap_test(topo, state, boxes, overlap_grid, tangents, v, params.interval_points);
    const RepulsionResult rpl = repulsion_force(topo, state, params, grid, v, near, far, overlap.overlap);
    const ContainerQuery wall = container_query(topo.container, px, py, state.t[v], boundary);
    Vec3f part[AP_FORCE_COMPONENTS];  // by AP_FORCE_TERMS
    part[AP_FORCE_repulsion] = rpl.force;
    const Vec3f springs = spring_force(topo, state, params, v);
    const Vec3f fold = fold_force(topo, state, params, v);
    part[AP_FORCE_springs] = {springs.x + fold.x, springs.y + fold.y, springs.t};
    part[AP_FORCE_target] = target_force(topo, state, params, v);
    Vec3f bdr = boundary_force(params, wall, px, py, boundary);
    if (boundary && k_mirror != 0.0f && !overlap.overlap) {
      // The wall's mirror image joins the wall's point force (docs/parameters.md, "Containment"); like
      // Eq. 1, it gives way to Eq. 3 on a vertex that overlaps another element.
      const Vec3f mirror = wall_mirror_force(topo, state, params, grid, v, wall);
      bdr = {bdr.x + mirror.x, bdr.y + mirror.y, bdr.t + mirror.t};
    }
    part[AP_FORCE_boundary] = bdr;
    part[AP_FORCE_overlap] = overlap_force(topo, state, params, v, overlap);
    const std::int32_t s = topo.slice[v];
    part[AP_FORCE_torsion] = torsion_force(topo, state, params, v, cx[s], cy[s]);
#define AP_REFERENCE_LOCAL_FORCE(name, ...) part[AP_FORCE_##name] = name##_force(topo, state, params, v);
    AP_LOCAL_FORCES(AP_REFERENCE_LOCAL_FORCE)
#undef AP_REFERENCE_LOCAL_FORCE

    Vec3f total = part[0];
    for (int c = 1; c < AP_FORCE_COMPONENTS; ++c)
      total = {total.x + part[c].x, total.y + part[c].y, total.t + part[c].t};
    r.total.set(v, total);
    // What the step reads besides the forces: the gap and contact bits (contact.cpp).
    const ContactGap gap = contact_gap(topo, state, params, v, overlap, rpl.closest, wall);
    r.closest[v] = gap.closest;
    r.contact[v] = gap.contact;
    if (out != nullptr)
      for (int c = 0; c < AP_FORCE_COMPONENTS; ++c) (out->*breakdown_forces[c].field).set(v, part[c]);
  }
  return r;
}

}  // namespace animpak::reference
