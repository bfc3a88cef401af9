// Edge forces, paper Eq. 2: F_edg = k_edg · u/|u| · s (|u| − ℓ)², u = x_b − x_a, s = sign(|u| − ℓ),
// a non-physical quadratic spring. Gathered: vertex a sums its own CSR slots in slot order; each
// spring is stored at both ends, so the other end computes the opposite force from its own slot.
// The fold guard (beyond the paper, docs/parameters.md, "Folds"): Eq. 2's springs keep edge lengths, and a
// boundary vertex mirrored across its triangle's opposite edge keeps them all, so a slice triangle can fold
// over at no cost in Eq. 2; the art bound in it (§3.1) then leaves the element's outline, which is all the
// overlap test sees. fold_force pushes each vertex of a triangle squeezed below fold_area of its rest area
// back along the triangle's height.
#include <cmath>

#include "animpak/reference/local_forces.hpp"

namespace animpak::reference {

float spring_stiffness(const ForceParams& params, SpringClass c) {
  const int i = static_cast<int>(c);
  return i < AP_SPRING_CLASSES ? params.k_spring[i] : 0.0f;
}

Vec3f spring_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v) {
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

Vec3f fold_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v) {
  const float k_fold = params.k_fold;
  Vec3f sum;
  if (!(k_fold > 0.0f)) return sum;
  const float floor_share = params.fold_area;
  const float g = state.growth[topo.slice[v]];
  const float g2 = g * g;
  const float vx = state.x[v], vy = state.y[v];
  const float rvx = topo.rest_copy_x[v], rvy = topo.rest_copy_y[v];
  for (std::int32_t k = topo.tri_begin[v]; k < topo.tri_begin[v + 1]; ++k) {
    const std::int32_t i = topo.tri_list[k];
    // v first, the triangle's cyclic order kept.
    const std::int32_t a = topo.tri_a[i], b = topo.tri_b[i], c = topo.tri_c[i];
    const std::int32_t p = v == a ? b : (v == b ? c : a);
    const std::int32_t q = v == a ? c : (v == b ? a : b);
    // Twice the signed areas, at rest (the rest copy, scaled by g² below) and now.
    const float rest = (topo.rest_copy_x[p] - rvx) * (topo.rest_copy_y[q] - rvy) -
                       (topo.rest_copy_y[p] - rvy) * (topo.rest_copy_x[q] - rvx);
    const float now = (state.x[p] - vx) * (state.y[q] - vy) - (state.y[p] - vy) * (state.x[q] - vx);
    const float s = rest < 0.0f ? -1.0f : 1.0f;
    const float deficit = floor_share * (s * rest) * g2 - s * now;
    if (!(deficit > 0.0f)) continue;
    // The gradient of s · now in v: s · (p − q)⊥; |∇|² is the opposite edge's squared length, so the push
    // is k_fold times the height missing.
    const float gx = s * (state.y[p] - state.y[q]), gy = s * (state.x[q] - state.x[p]);
    const float gg = gx * gx + gy * gy;
    if (!(gg > 0.0f)) continue;
    const float w = k_fold * deficit / gg;
    sum.x = sum.x + gx * w;
    sum.y = sum.y + gy * w;
  }
  return sum;
}

}  // namespace animpak::reference
