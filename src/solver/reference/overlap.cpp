// Overlap detection and the overlap force, paper Eq. 3: F_ovr = k_ovr Σ_i (p_i − x), p_i the
// centroids of the slice triangles incident on x. Unlike the authors' code (which tests only the
// element of the single nearest closest point, notes §3.5), every other element owning a near
// envelope triangle is tested, so a nearer third element cannot hide the one x is inside.
#include <algorithm>

#include "animpak/reference.hpp"

namespace animpak::reference {

namespace {

// Slices are stacked along t; a slice's t is its first vertex's t (simultaneity keeps the slice's
// vertices at one t after every step).
float slice_t(const Topology& topo, const SimState& state, std::int32_t s) { return state.t[topo.slice_begin[s]]; }

// Even–odd test of (px, py) against element e's boundary polygon interpolated linearly at t between
// the first pair of consecutive slices whose t values bracket t. Outside the element's t range: no.
bool inside_element_at(const Topology& topo, const SimState& state, std::int32_t e, float px, float py, float t) {
  for (std::int32_t s = topo.element_slice_begin[e]; s + 1 < topo.element_slice_begin[e + 1]; ++s) {
    const float t0 = slice_t(topo, state, s), t1 = slice_t(topo, state, s + 1);
    if (!(std::min(t0, t1) <= t && t <= std::max(t0, t1))) continue;
    // Equal slice times (a flat pair) take the lower slice's polygon.
    const float w = t1 != t0 ? (t - t0) / (t1 - t0) : 0.0f;
    const std::int32_t lo = topo.slice_begin[s], hi = topo.slice_begin[s + 1];
    const std::int32_t count = topo.slice_boundary[s];
    bool inside = false;
    for (std::int32_t k = 0; k < count; ++k) {
      const std::int32_t j = k + 1 == count ? 0 : k + 1;
      const float ax = state.x[lo + k] + (state.x[hi + k] - state.x[lo + k]) * w;
      const float ay = state.y[lo + k] + (state.y[hi + k] - state.y[lo + k]) * w;
      const float bx = state.x[lo + j] + (state.x[hi + j] - state.x[lo + j]) * w;
      const float by = state.y[lo + j] + (state.y[hi + j] - state.y[lo + j]) * w;
      if (ray_crosses_segment(px, py, ax, ay, bx, by)) inside = !inside;
    }
    return inside;
  }
  return false;
}

}  // namespace

bool inside_other_element(const Topology& topo, const SimState& state, std::int32_t v,
                          const std::vector<std::int32_t>& near) {
  if ((topo.flags[v] & vertex_boundary) == 0) return false;
  std::vector<std::int32_t> tested;
  for (const std::int32_t tri : near) {
    const std::int32_t e = topo.env_element[tri];
    if (e == topo.element[v] || std::find(tested.begin(), tested.end(), e) != tested.end()) continue;
    tested.push_back(e);
    if (inside_element_at(topo, state, e, state.x[v], state.y[v], state.t[v])) return true;
  }
  return false;
}

Vec3f overlap_force(const Topology& topo, const SimState& state, const Params& params, std::int32_t v) {
  const float x = state.x[v], y = state.y[v], t = state.t[v];
  Vec3f sum;
  for (std::int32_t k = topo.tri_begin[v]; k < topo.tri_begin[v + 1]; ++k) {
    const std::int32_t i = topo.tri_list[k];
    const std::int32_t a = topo.tri_a[i], b = topo.tri_b[i], c = topo.tri_c[i];
    const float px = (state.x[a] + state.x[b] + state.x[c]) / 3.0f;
    const float py = (state.y[a] + state.y[b] + state.y[c]) / 3.0f;
    const float pt = (state.t[a] + state.t[b] + state.t[c]) / 3.0f;
    sum.x = sum.x + (px - x);
    sum.y = sum.y + (py - y);
    sum.t = sum.t + (pt - t);
  }
  const float k_ovr = static_cast<float>(params.k_overlap);
  return {k_ovr * sum.x, k_ovr * sum.y, k_ovr * sum.t};
}

}  // namespace animpak::reference
