#include <algorithm>
#include <cmath>
#include <numbers>

#include "animpak/scene.hpp"

namespace animpak {

// Bridson's algorithm (SIGGRAPH 2007 sketch): a background grid with cells of r/√2 holds at most one
// sample, so a candidate needs to check only the 5×5 cells around it.
std::vector<Vec2> poisson_disk(const Container& container, double min_distance, double margin, Rng& rng) {
  constexpr int attempts = 30;
  const double cell = min_distance / std::numbers::sqrt2;
  const int n = static_cast<int>(std::ceil(1.0 / cell));
  std::vector<int> grid(static_cast<std::size_t>(n) * n, -1);
  std::vector<Vec2> samples;
  std::vector<int> active;

  auto cell_of = [&](Vec2 p) {
    return std::pair{std::clamp(static_cast<int>(p.x / cell), 0, n - 1),
                     std::clamp(static_cast<int>(p.y / cell), 0, n - 1)};
  };
  auto acceptable = [&](Vec2 p) {
    if (p.x < 0 || p.y < 0 || p.x >= 1 || p.y >= 1) return false;
    // The neighbour test first: it reads 25 cells, the container tests walk every boundary segment.
    const auto [cx, cy] = cell_of(p);
    for (int y = std::max(0, cy - 2); y <= std::min(n - 1, cy + 2); ++y)
      for (int x = std::max(0, cx - 2); x <= std::min(n - 1, cx + 2); ++x) {
        const int s = grid[static_cast<std::size_t>(y) * n + x];
        if (s >= 0 && norm(samples[s] - p) < min_distance) return false;
      }
    return container.contains(p) && !(container.distance_to_boundary(p) < margin);
  };
  auto add = [&](Vec2 p) {
    const auto [cx, cy] = cell_of(p);
    grid[static_cast<std::size_t>(cy) * n + cx] = static_cast<int>(samples.size());
    active.push_back(static_cast<int>(samples.size()));
    samples.push_back(p);
  };

  // The first sample: uniform tries inside the container (a thin container may need many).
  for (int i = 0; i < 10000 && samples.empty(); ++i) {
    const Vec2 p{rng.uniform(), rng.uniform()};
    if (acceptable(p)) add(p);
  }
  while (!active.empty()) {
    const std::size_t pick = rng.below(active.size());
    const Vec2 origin = samples[active[pick]];
    bool placed = false;
    for (int k = 0; k < attempts && !placed; ++k) {
      const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
      const double radius = min_distance * std::sqrt(rng.uniform(1.0, 4.0));  // uniform in the annulus [r, 2r]
      const Vec2 p = origin + Vec2{radius * std::cos(angle), radius * std::sin(angle)};
      if (acceptable(p)) add(p), placed = true;
    }
    if (!placed) {
      active[pick] = active.back();
      active.pop_back();
    }
  }
  return samples;
}

}  // namespace animpak
