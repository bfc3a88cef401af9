// Paper §3.1: "every path control point is represented using barycentric coordinates within one
// triangle", so deformed slices carry the art along (rendering, §6). Points outside every triangle (the
// resampled boundary cuts corners, dropped outline pieces) bind to the nearest triangle by extrapolation.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "animpak/element.hpp"

namespace animpak {
namespace {

// Barycentric coordinates of p in triangle abc (any sign: outside points extrapolate).
std::array<double, 3> barycentric(Vec2 p, Vec2 a, Vec2 b, Vec2 c) {
  const double area = cross(b - a, c - a);
  const double wb = cross(p - a, c - a) / area;
  const double wc = cross(b - a, p - a) / area;
  return {1.0 - wb - wc, wb, wc};
}

// Uniform bucket grid over the triangles' boxes: art has thousands of points, slices a few dozen
// triangles, and each point then tests only the triangles of its cell.
class TriangleGrid {
 public:
  explicit TriangleGrid(const SliceMesh& mesh) : mesh_(mesh) {
    for (Vec2 p : mesh.vertices) box_.add(p);
    side_ = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(mesh.triangles.size())))));
    cells_.resize(static_cast<std::size_t>(side_) * side_);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      Box tb;
      for (int v : mesh.triangles[t]) tb.add(mesh.vertices[v]);
      const auto [x0, y0] = cell(tb.min);
      const auto [x1, y1] = cell(tb.max);
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) cells_[static_cast<std::size_t>(y) * side_ + x].push_back(static_cast<int>(t));
    }
  }

  BoundPoint bind(Vec2 p) const {
    if (p.x >= box_.min.x && p.x <= box_.max.x && p.y >= box_.min.y && p.y <= box_.max.y) {
      const auto [x, y] = cell(p);
      for (int t : cells_[static_cast<std::size_t>(y) * side_ + x]) {
        const auto w = weights(t, p);
        if (w[0] >= 0.0 && w[1] >= 0.0 && w[2] >= 0.0) return {t, w};
      }
    }
    // Outside every triangle: the nearest one, by point–triangle distance (ties to the lower index).
    int best = 0;
    double best_d = 1e300;
    for (int t = 0; t < static_cast<int>(mesh_.triangles.size()); ++t) {
      const Triangle& tri = mesh_.triangles[t];
      double d = 1e300;
      for (int k = 0; k < 3; ++k)
        d = std::min(d, segment_distance(p, mesh_.vertices[tri[k]], mesh_.vertices[tri[(k + 1) % 3]]));
      if (d < best_d) best_d = d, best = t;
    }
    return {best, weights(best, p)};
  }

 private:
  std::pair<int, int> cell(Vec2 p) const {
    const double w = std::max(box_.width(), 1e-300), h = std::max(box_.height(), 1e-300);
    return {std::clamp(static_cast<int>((p.x - box_.min.x) / w * side_), 0, side_ - 1),
            std::clamp(static_cast<int>((p.y - box_.min.y) / h * side_), 0, side_ - 1)};
  }
  std::array<double, 3> weights(int t, Vec2 p) const {
    const Triangle& tri = mesh_.triangles[t];
    return barycentric(p, mesh_.vertices[tri[0]], mesh_.vertices[tri[1]], mesh_.vertices[tri[2]]);
  }

  const SliceMesh& mesh_;
  Box box_;
  int side_ = 1;
  std::vector<std::vector<int>> cells_;
};

}  // namespace

ArtBinding bind_art(const ArtShape& unit_art, const SliceMesh& mesh) {
  if (mesh.triangles.empty()) throw std::invalid_argument("bind_art: the slice has no triangle");
  const TriangleGrid grid(mesh);
  ArtBinding binding;
  binding.points.resize(unit_art.paths.size());
  for (std::size_t p = 0; p < unit_art.paths.size(); ++p) {
    const auto& lines = unit_art.paths[p].polylines;
    binding.points[p].resize(lines.size());
    for (std::size_t q = 0; q < lines.size(); ++q)
      for (Vec2 point : lines[q].points) binding.points[p][q].push_back(grid.bind(point));
  }
  return binding;
}

std::vector<std::vector<std::vector<Vec2>>> replay_art(const ArtBinding& binding, const SliceMesh& mesh,
                                                       const std::vector<Vec2>& positions) {
  if (positions.size() != mesh.vertices.size())
    throw std::invalid_argument("replay_art: one position per slice vertex expected");
  std::vector<std::vector<std::vector<Vec2>>> out(binding.points.size());
  for (std::size_t p = 0; p < binding.points.size(); ++p) {
    out[p].resize(binding.points[p].size());
    for (std::size_t q = 0; q < binding.points[p].size(); ++q) {
      out[p][q].reserve(binding.points[p][q].size());
      for (const BoundPoint& b : binding.points[p][q]) {
        const Triangle& tri = mesh.triangles.at(static_cast<std::size_t>(b.triangle));
        out[p][q].push_back(positions[tri[0]] * b.weights[0] + positions[tri[1]] * b.weights[1] +
                            positions[tri[2]] * b.weights[2]);
      }
    }
  }
  return out;
}

}  // namespace animpak
