// Edge forces, paper Eq. 2: F_edg = k_edg · u/|u| · s (|u| − ℓ)², u = x_b − x_a, s = sign(|u| − ℓ),
// a non-physical quadratic spring. Gathered: vertex a sums its own CSR slots in slot order; each
// spring is stored at both ends, so the other end computes the opposite force from its own slot.
#include <cmath>

#include "animpak/reference.hpp"

namespace animpak::reference {

float spring_stiffness(const Params& params, SpringClass c) {
  switch (c) {
    case SpringClass::edge:
      return static_cast<float>(params.forces.k_edge);
    case SpringClass::shear:
      return static_cast<float>(params.forces.k_shear);
    case SpringClass::negative_space:
      return static_cast<float>(params.forces.k_negative_space);
    case SpringClass::time:
      return static_cast<float>(params.forces.k_time);
    case SpringClass::target:
      return static_cast<float>(params.forces.k_target);
  }
  return 0.0f;
}

Vec3f spring_force(const Topology& topo, const SimState& state, const Params& params, std::int32_t v) {
  const float xa = state.x[v], ya = state.y[v], ta = state.t[v];
  Vec3f sum;
  for (std::int32_t k = topo.spring_begin[v]; k < topo.spring_begin[v + 1]; ++k) {
    const std::int32_t b = topo.spring_other[k];
    const float ux = state.x[b] - xa, uy = state.y[b] - ya, ut = state.t[b] - ta;
    const float d2 = ux * ux + uy * uy + ut * ut;
    // Coincident ends give no direction; the spring waits until they separate.
    if (!(d2 > 0.0f)) continue;
    const float len = std::sqrt(d2);
    const float inv_len = 1.0f / len;
    const float stretch = len - state.spring_rest[k];
    const float s = stretch > 0.0f ? 1.0f : (stretch < 0.0f ? -1.0f : 0.0f);
    const float w =
        spring_stiffness(params, static_cast<SpringClass>(topo.spring_class[k])) * inv_len * s * (stretch * stretch);
    sum.x = sum.x + ux * w;
    sum.y = sum.y + uy * w;
    sum.t = sum.t + ut * w;
  }
  return sum;
}

}  // namespace animpak::reference
