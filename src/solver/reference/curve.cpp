// The curve between slices (include/animpak/curve.hpp; docs/parameters.md, "Motion between slices"):
// every vertex's tangent from one snapshot.
// kernels/curve.cl is the tangents' twin.
#include "animpak/curve.hpp"

#include "animpak/reference.hpp"

namespace animpak {

namespace reference {

namespace {

bool first_slice(const Topology& topo, std::int32_t s) { return s == topo.element_slice_begin[topo.slice_element[s]]; }

bool last_slice(const Topology& topo, std::int32_t s) {
  return s + 1 == topo.element_slice_begin[topo.slice_element[s] + 1];
}

}  // namespace

void curve_tangents(const Topology& topo, const CurveLinks& links, const SimState& state, bool cubic,
                    CurveTangents& out) {
  const std::int32_t n = topo.vertex_count();
  out.cubic = cubic;
  out.x.assign(n, 0.0f);
  out.y.assign(n, 0.0f);
  for (std::int32_t v = 0; v < n; ++v) {
    const std::int32_t s = topo.slice[v], k = v - topo.slice_begin[s];
    const std::int32_t p = links.prev[s], q = links.next[s];
    const float t0 = state.t[topo.slice_begin[s]];
    float hp = 0.0f, hn = 0.0f, xp = 0.0f, yp = 0.0f, xn = 0.0f, yn = 0.0f;
    if (p >= 0) {
      const std::int32_t a = topo.slice_begin[p] + k;
      // Across the seam the slice before lies one period earlier.
      const float tp = first_slice(topo, s) ? state.t[topo.slice_begin[p]] - 1.0f : state.t[topo.slice_begin[p]];
      hp = t0 - tp, xp = state.x[a], yp = state.y[a];
    }
    if (q >= 0) {
      const std::int32_t b = topo.slice_begin[q] + k;
      const float tn = last_slice(topo, s) ? state.t[topo.slice_begin[q]] + 1.0f : state.t[topo.slice_begin[q]];
      hn = tn - t0, xn = state.x[b], yn = state.y[b];
    }
    const float x0 = state.x[v], y0 = state.y[v];
    out.x[v] = curve_tangent(curve_slope(xp, x0, hp), curve_slope(x0, xn, hn), hp, hn, p >= 0, q >= 0);
    out.y[v] = curve_tangent(curve_slope(yp, y0, hp), curve_slope(y0, yn, hn), hp, hn, p >= 0, q >= 0);
  }
}

}  // namespace reference
}  // namespace animpak
