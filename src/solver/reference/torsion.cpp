// Torsional force, paper Eq. 5: F_tor = ±k_tor u⊥ with u = x − c, c the slice's current centroid,
// u⊥ the unit vector 90° counter-clockwise from u, and the sign from θ, the signed angle between the
// rest direction u_r and u. The force has constant magnitude and always turns u back towards u_r
// (as in the authors' code; docs/architecture.md, "Where the code departs from the paper's text"):
// with θ measured from u_r to u, F = −sign(θ) k_tor u⊥.
//
// "Counter-clockwise" is in the math sense of the stored coordinates: u⊥ = (−u_y, u_x), and θ > 0
// when cross(u_r, u) = r_x u_y − r_y u_x > 0. Our y axis points down (as in the art files and
// images), so what is counter-clockwise here looks clockwise on screen; the restoring direction does
// not depend on that convention.
//
// Paper §4 lets the artist give a guided element's orientation at its targets; the slice of such a
// target holds it with the same force at the larger k_target_angle (vertex_hold_angle), since the
// rest direction already carries the target's angle (src/scene/placement.cpp places the slice so).
#include <cmath>

#include "animpak/reference/local_forces.hpp"

namespace animpak::reference {

void slice_centroids(const Topology& topo, const SimState& state, std::vector<float>& cx, std::vector<float>& cy) {
  const std::int32_t slices = topo.slice_count();
  cx.assign(slices, 0.0f);
  cy.assign(slices, 0.0f);
  for (std::int32_t s = 0; s < slices; ++s) {
    float sx = 0.0f, sy = 0.0f;
    for (std::int32_t v = topo.slice_begin[s]; v < topo.slice_begin[s + 1]; ++v) {
      sx = sx + state.x[v];
      sy = sy + state.y[v];
    }
    const float count = static_cast<float>(topo.slice_begin[s + 1] - topo.slice_begin[s]);
    if (count > 0.0f) {
      cx[s] = sx / count;
      cy[s] = sy / count;
    }
  }
}

Vec3f torsion_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v, float cx,
                    float cy) {
  const float ux = state.x[v] - cx, uy = state.y[v] - cy;
  const float cross = topo.rest_dir_x[v] * uy - topo.rest_dir_y[v] * ux;
  // θ = 0 (and θ = π, where the turning direction is undefined) give no force; so does a vertex at
  // the centroid or one without a rest direction, since cross is 0 there.
  if (cross == 0.0f) return {};
  const float inv_len = 1.0f / std::sqrt(ux * ux + uy * uy);
  const float k = (topo.flags[v] & vertex_hold_angle) != 0 ? params.k_target_angle : params.k_torsion;
  const float signed_k = cross > 0.0f ? -k : k;
  return {signed_k * (-uy * inv_len), signed_k * (ux * inv_len), 0.0f};
}

}  // namespace animpak::reference
