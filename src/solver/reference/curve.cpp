// The curve between slices (include/animpak/curve.hpp; docs/parameters.md, "Motion between slices"):
// every vertex's tangent from one snapshot: Steffen's from its neighbours (the monotone cubic), or the C2
// spline's from a solve along its track.
// kernels/curve.cl is the tangents' twin.
#include "animpak/curve.hpp"

#include "animpak/reference/overlap.hpp"

namespace animpak {

namespace reference {

void curve_tangents(const Topology& topo, const SimState& state, int mode, CurveTangents& out) {
  require_curve_links(topo, "curve_tangents");
  const std::int32_t n = topo.vertex_count();
  out.mode = mode;
  out.x.assign(n, 0.0f);
  out.y.assign(n, 0.0f);
  if (mode != curve_spline) {
    for (std::int32_t v = 0; v < n; ++v)
      curve_vertex_tangent(topo, topo.curve, state, topo.slice[v], v - topo.slice_begin[topo.slice[v]], out.x[v],
                           out.y[v]);
    return;
  }
  // The spline: one system per track (vertex k of every slice on a chain), solved in the order
  // kernels/curve.cl's curve_spline_tangents solves it.
  const CurveChains& chains = topo.chains;
  std::vector<float> mx, my, cp, z;
  for (std::size_t track = 0; track < chains.track_vertex.size(); ++track) {
    const std::int32_t c = chains.track_chain[track], b = chains.begin[c], len = chains.begin[c + 1] - b;
    const std::int32_t k = chains.track_vertex[track] - topo.slice_begin[chains.slice[b]];
    const auto vertex = [&](std::int32_t i) { return topo.slice_begin[chains.slice[b + i]] + k; };
    const auto tau = [&](std::int32_t i) {
      return state.t[topo.slice_begin[chains.slice[b + i]]] + chains.offset[b + i];
    };
    const auto x = [&](std::int32_t i) { return state.x[vertex(i)]; };
    const auto y = [&](std::int32_t i) { return state.y[vertex(i)]; };
    mx.assign(len, 0.0f), my.assign(len, 0.0f), cp.assign(len, 0.0f), z.assign(len, 0.0f);
    spline_tangents<float>(len, chains.period[c], tau, x, y, mx, my, cp, z);
    for (std::int32_t i = 0; i < len; ++i) {
      out.x[vertex(i)] = mx[i], out.y[vertex(i)] = my[i];
      const std::int32_t alias = chains.alias[b + i];
      if (alias >= 0) out.x[topo.slice_begin[alias] + k] = mx[i], out.y[topo.slice_begin[alias] + k] = my[i];
    }
  }
}

}  // namespace reference
}  // namespace animpak
