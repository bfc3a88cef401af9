// Repulsion force, paper Eq. 1: F_rpl = k_rpl Σ_i u/|u| · 1/(ε + |u|²), u = x − x_i, on vertices of
// slice boundaries. The x_i are, in this order, the exact closest points on the near envelope
// triangles of other elements, then the centroids of the far ones (§5.1), or with far_cells one mean
// centroid per far cell and element, weighted by its triangle count (docs/parameters.md, "Far
// field"). Terms are taken in the grid's visiting order. The near terms go to four partial sums, by
// grid slot mod 4, joined as (p0 + p1) + (p2 + p3); the far terms are then added one by one. Four
// running sums instead of one let a CPU device add 16 lanes with four vector additions rather than 16
// dependent ones (docs/architecture.md, "The twin rule"). k_rpl multiplies the sum once at the end.
#include <cmath>

#include "animpak/reference/boundary.hpp"
#include "animpak/reference/grid.hpp"
#include "animpak/reference/repulsion.hpp"

namespace animpak::reference {

namespace {

// Adds one term of Eq. 1, `count` times (a far-field run stands for count triangles; 1 is exact). A
// point exactly at x has no direction, so it adds nothing rather than NaN.
void add_term(float ux, float uy, float ut, float eps, Vec3f& sum, float count = 1.0f) {
  const float d2 = ux * ux + uy * uy + ut * ut;
  if (!(d2 > 0.0f)) return;
  const float inv_len = 1.0f / std::sqrt(d2);
  const float w = inv_len * (1.0f / (eps + d2)) * count;
  sum.x = sum.x + ux * w;
  sum.y = sum.y + uy * w;
  sum.t = sum.t + ut * w;
}

// Eq. 1's sum at x: the near slots' exact closest points in four partials by slot mod 4, joined as
// (p0 + p1) + (p2 + p3), then the far slots one by one; closest2 is the least squared near distance.
Vec3f eq1_sum(const Topology& topo, const SimState& state, const CollisionGrid& grid, Vec3f x,
              const std::vector<std::int32_t>& near, const std::vector<std::int32_t>& far, float eps, float& closest2) {
  Vec3f part[4];
  closest2 = std::numeric_limits<float>::infinity();
  for (const std::int32_t k : near) {
    const std::int32_t tri = grid.sorted_triangles[k];
    const std::int32_t a = topo.env_a[tri], b = topo.env_b[tri], c = topo.env_c[tri];
    const Vec3f p =
        closest_point_on_triangle(x, {state.x[a], state.y[a], state.t[a]}, {state.x[b], state.y[b], state.t[b]},
                                  {state.x[c], state.y[c], state.t[c]});
    const float ux = x.x - p.x, uy = x.y - p.y, ut = x.t - p.t;
    const float d2 = ux * ux + uy * uy + ut * ut;
    if (d2 < closest2) closest2 = d2;
    add_term(ux, uy, ut, eps, part[k & 3]);
  }
  Vec3f sum{(part[0].x + part[1].x) + (part[2].x + part[3].x), (part[0].y + part[1].y) + (part[2].y + part[3].y),
            (part[0].t + part[1].t) + (part[2].t + part[3].t)};
  // Far slots: each triangle's centroid (§5.1), or each run's mean centroid for its triangles together.
  for (const std::int32_t k : far) {
    if (grid.far_cells) {
      const float count = static_cast<float>(grid.run_next[k] - k);
      add_term(x.x - grid.run_cx[k], x.y - grid.run_cy[k], x.t - grid.run_ct[k], eps, sum, count);
    } else {
      const std::int32_t tri = grid.sorted_triangles[k];
      add_term(x.x - grid.cx[tri], x.y - grid.cy[tri], x.t - grid.ct[tri], eps, sum);
    }
  }
  return sum;
}

}  // namespace

RepulsionResult repulsion_force(const Topology& topo, const SimState& state, const ForceParams& params,
                                const CollisionGrid& grid, std::int32_t v, const std::vector<std::int32_t>& near,
                                const std::vector<std::int32_t>& far, bool overlapping) {
  RepulsionResult r;
  if ((topo.flags[v] & vertex_boundary) == 0) return r;
  const Vec3f x{state.x[v], state.y[v], state.t[v]};
  float closest2 = 0.0f;
  const Vec3f sum = eq1_sum(topo, state, grid, x, near, far, params.repulsion_epsilon, closest2);
  // The closest distance feeds the stop test even while the vertex overlaps.
  r.closest = std::sqrt(closest2);
  if (overlapping) return r;
  const float k = params.k_repulsion;
  r.force = {k * sum.x, k * sum.y, k * sum.t};
  return r;
}

Vec3f wall_mirror_force(const Topology& topo, const SimState& state, const ForceParams& params,
                        const CollisionGrid& grid, std::int32_t v, const ContainerQuery& wall) {
  const float k = params.k_mirror;
  if (k == 0.0f || (topo.flags[v] & vertex_boundary) == 0 || !wall.inside) return {};
  if (!(wall.distance2 > 0.0f) || !(wall.distance2 < params.wall_range2)) return {};
  const float px = state.x[v], py = state.y[v];
  // The vertex's reflection in the wall, and Eq. 1 there from the element's own triangles: the force the
  // mirror image of the element puts on the vertex, seen from the other side.
  const Vec3f mirror{wall.qx + (wall.qx - px), wall.qy + (wall.qy - py), state.t[v]};
  std::vector<std::int32_t> near, far;
  repulsion_near_slots(grid, mirror, topo.element[v], near, true);
  repulsion_far_slots(grid, mirror, topo.element[v], far, true);
  float closest2 = 0.0f;
  const Vec3f s = eq1_sum(topo, state, grid, mirror, near, far, params.repulsion_epsilon, closest2);
  // Back across the wall's tangent: s − 2 (s·n) n with n = (x − q)/|x − q|, written with the unnormalised
  // normal over its squared length.
  const float nx = px - wall.qx, ny = py - wall.qy;
  const float twice = 2.0f * ((s.x * nx + s.y * ny) / wall.distance2);
  return {k * (s.x - twice * nx), k * (s.y - twice * ny), k * s.t};
}

}  // namespace animpak::reference
