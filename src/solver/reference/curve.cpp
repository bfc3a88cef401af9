// The curve between slices (include/animpak/curve.hpp; docs/parameters.md, "Motion between slices"):
// every vertex's tangent from one snapshot.
// kernels/curve.cl is the tangents' twin.
#include "animpak/curve.hpp"

#include "animpak/reference.hpp"

namespace animpak {

namespace reference {

void curve_tangents(const Topology& topo, const CurveLinks& links, const SimState& state, bool cubic,
                    CurveTangents& out) {
  const std::int32_t n = topo.vertex_count();
  out.cubic = cubic;
  out.x.assign(n, 0.0f);
  out.y.assign(n, 0.0f);
  for (std::int32_t v = 0; v < n; ++v)
    curve_vertex_tangent(topo, links, state, topo.slice[v], v - topo.slice_begin[topo.slice[v]], out.x[v], out.y[v]);
}

}  // namespace reference
}  // namespace animpak
