// Total force, paper Eq. 7, for every vertex from one snapshot of positions (design.md "One step",
// phase 2). Per vertex, in this order: the grid queries, the overlap test (Eq. 3 replaces Eq. 1 for a
// vertex inside another element), then each force. The sum is formed left to right in Eq. 7's order,
// with the target-point spring (an Eq. 2 spring) right after the edge springs:
//   F = ((((((F_rpl + F_edg) + F_tgt) + F_bdr) + F_ovr) + F_tor) + F_tmp)
// The kernels add in exactly this order.
#include "animpak/reference.hpp"

namespace animpak::reference {

void ForceField::assign(std::size_t n) {
  x.assign(n, 0.0f);
  y.assign(n, 0.0f);
  t.assign(n, 0.0f);
}

StepForces step_forces(const Topology& topo, const SimState& state, const Params& params,
                       const CollisionGrid& grid, ForceBreakdown* out) {
  const std::int32_t n = topo.vertex_count();
  StepForces r;
  r.total.assign(n);
  r.closest.assign(n, std::numeric_limits<float>::infinity());
  r.inside.assign(n, 0);
  if (out != nullptr) {
    for (ForceField* f : {&out->repulsion, &out->springs, &out->target, &out->boundary, &out->overlap,
                          &out->torsion, &out->temporal})
      f->assign(n);
  }

  // Slice centroids first: a per-slice pass whose result every vertex of the slice reads (Eq. 5).
  std::vector<float> cx, cy;
  slice_centroids(topo, state, cx, cy);

  std::vector<std::int32_t> near, far;
  for (std::int32_t v = 0; v < n; ++v) {
    near.clear();
    far.clear();
    if ((topo.flags[v] & vertex_boundary) != 0) {
      const Vec3f q{state.x[v], state.y[v], state.t[v]};
      near_triangles(grid, topo, q, topo.element[v], near);
      far_triangles(grid, topo, q, topo.element[v], far);
    }
    const bool inside = inside_other_element(topo, state, v, near);
    const RepulsionResult rpl = repulsion_force(topo, state, params, grid, v, near, far, inside);
    const Vec3f edg = spring_force(topo, state, params, v);
    const Vec3f tgt = target_force(topo, state, params, v);
    const Vec3f bdr = boundary_force(topo, state, params, v);
    const Vec3f ovr = inside ? overlap_force(topo, state, params, v) : Vec3f{};
    const std::int32_t s = topo.slice[v];
    const Vec3f tor = torsion_force(topo, state, params, v, cx[s], cy[s]);
    const Vec3f tmp = temporal_force(topo, state, params, v);

    r.total.x[v] = rpl.force.x + edg.x + tgt.x + bdr.x + ovr.x + tor.x + tmp.x;
    r.total.y[v] = rpl.force.y + edg.y + tgt.y + bdr.y + ovr.y + tor.y + tmp.y;
    r.total.t[v] = rpl.force.t + edg.t + tgt.t + bdr.t + ovr.t + tor.t + tmp.t;
    r.closest[v] = rpl.closest;
    r.inside[v] = inside ? 1 : 0;
    if (out != nullptr) {
      out->repulsion.set(v, rpl.force);
      out->springs.set(v, edg);
      out->target.set(v, tgt);
      out->boundary.set(v, bdr);
      out->overlap.set(v, ovr);
      out->torsion.set(v, tor);
      out->temporal.set(v, tmp);
    }
  }
  return r;
}

}  // namespace animpak::reference
