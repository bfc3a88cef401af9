// Hand-made slices for the animation tests, so they do not depend on the sampling and triangulation
// stage: a regular grid of squares split into triangles, in unit coordinates.
#pragma once

#include <algorithm>
#include <set>

#include "animpak/element.hpp"

namespace animpak::testing {

/// nx × ny vertices spaced `h` apart from `origin`; each square split along one diagonal. Triangles are
/// counter-clockwise in y-up terms (positive signed area), as build_slice makes them.
inline SliceMesh grid_slice(int nx, int ny, double h, Vec2 origin = {0.0, 0.0}) {
  SliceMesh mesh;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) mesh.vertices.push_back({origin.x + i * h, origin.y + j * h});
  auto id = [nx](int i, int j) { return j * nx + i; };
  std::set<Edge> edges;
  auto add_edge = [&edges](int a, int b) { edges.insert({std::min(a, b), std::max(a, b)}); };
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      mesh.triangles.push_back({a, b, c});
      mesh.triangles.push_back({a, c, d});
      add_edge(a, b), add_edge(b, c), add_edge(c, a), add_edge(c, d), add_edge(d, a);
    }
  mesh.edges.assign(edges.begin(), edges.end());
  return mesh;
}

/// Vertices on the border of a grid_slice.
inline std::vector<int> grid_border(int nx, int ny) {
  std::vector<int> border;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (i == 0 || j == 0 || i == nx - 1 || j == ny - 1) border.push_back(j * nx + i);
  return border;
}

/// Largest distance between corresponding points of two equally long lists.
inline double max_distance(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, norm(a[i] - b[i]));
  return d;
}

}  // namespace animpak::testing
