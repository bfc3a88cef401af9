// Target-point springs of guided elements, paper Eq. 2 with class "target": a spring of rest length
// ℓ = 0 from the anchor vertex to its target point in (x, y, t), so F = k_target · u/|u| · |u|².
// Only the anchors of the slices nearest the artist's targets have one (paper §4); the slices in
// between are left to the other forces (docs/scene-format.md, docs/parameters.md `k_target`).
#include <cmath>

#include "animpak/reference/local_forces.hpp"

namespace animpak::reference {

Vec3f target_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v) {
  const std::int32_t p = topo.target[v];
  if (p < 0 || (topo.flags[v] & vertex_anchor) == 0) return {};
  const float ux = topo.target_x[p] - state.x[v], uy = topo.target_y[p] - state.y[v],
              ut = topo.target_t[p] - state.t[v];
  const float d2 = ux * ux + uy * uy + ut * ut;
  if (!(d2 > 0.0f)) return {};
  const float len = std::sqrt(d2);
  const float inv_len = 1.0f / len;
  // Eq. 2 with ℓ = 0: s = +1 and (|u| − ℓ)² = |u|².
  const float w = params.k_target * inv_len * (len * len);
  return {ux * w, uy * w, ut * w};
}

}  // namespace animpak::reference
