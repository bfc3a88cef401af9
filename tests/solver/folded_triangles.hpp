// Slice triangles folded over (docs/parameters.md, "Folds"), counted for the solver and render tests.
#pragma once

#include <cstddef>
#include <vector>

#include "animpak/state.hpp"

namespace animpak::test {

/// Twice the signed area of triangle (a, b, c) over these coordinates, in double.
inline double signed_area2(const std::vector<float>& x, const std::vector<float>& y, int a, int b, int c) {
  return (double(x[b]) - x[a]) * (double(y[c]) - y[a]) - (double(y[b]) - y[a]) * (double(x[c]) - x[a]);
}

/// Slice triangles of `state` whose signed area has the opposite sign of their rest copy's (or is 0).
inline int folded_triangles(const Topology& topo, const SimState& state) {
  int folded = 0;
  for (std::size_t i = 0; i < topo.tri_a.size(); ++i) {
    const int a = topo.tri_a[i], b = topo.tri_b[i], c = topo.tri_c[i];
    folded +=
        signed_area2(topo.rest_copy_x, topo.rest_copy_y, a, b, c) * signed_area2(state.x, state.y, a, b, c) <= 0.0;
  }
  return folded;
}

}  // namespace animpak::test
