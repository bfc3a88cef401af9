#include <algorithm>
#include <cmath>
#include <limits>
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

// Gonzalez's farthest-point traversal (a 2-approximation of the k-centre covering among the
// candidates): no candidate is left farther from every pick than the last pick's distance was. Each candidate keeps its distance to the nearest pick so far: O(wanted × candidates).
std::vector<Vec2> spread_seeds(const Container& container, const std::vector<Vec2>& candidates, int wanted,
                               const std::vector<Vec2>& occupied, std::size_t first) {
  std::vector<double> room(candidates.size());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    double r = 2.0 * container.distance_to_boundary(candidates[i]);
    for (const Vec2 q : occupied) r = std::min(r, norm(candidates[i] - q));
    room[i] = r;
  }
  std::vector<Vec2> picks;
  std::vector<bool> taken(candidates.size(), false);
  while (static_cast<int>(picks.size()) < wanted && picks.size() < candidates.size()) {
    std::size_t best = first < candidates.size() ? first : 0;
    if (!picks.empty()) {
      best = candidates.size();
      for (std::size_t i = 0; i < candidates.size(); ++i)
        if (!taken[i] && (best == candidates.size() || room[i] > room[best])) best = i;
    }
    taken[best] = true;
    picks.push_back(candidates[best]);
    for (std::size_t i = 0; i < candidates.size(); ++i)
      room[i] = std::min(room[i], norm(candidates[i] - candidates[best]));
  }
  return picks;
}

std::vector<Vec2> relax_seeds(const Container& container, std::vector<Vec2> seeds, const std::vector<Vec2>& occupied,
                              double margin, double clearance, int iterations) {
  constexpr int n = 128;
  const Box box = container.bounds();
  std::vector<Vec2> points;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec2 p{box.min.x + (i + 0.5) / n * (box.max.x - box.min.x),
                   box.min.y + (j + 0.5) / n * (box.max.y - box.min.y)};
      if (container.contains(p)) points.push_back(p);
    }
  // The occupied points do not move: each grid point's squared distance to the nearest, once.
  std::vector<double> occupied_d2(points.size(), std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < points.size(); ++i)
    for (const Vec2 q : occupied) occupied_d2[i] = std::min(occupied_d2[i], dot(points[i] - q, points[i] - q));
  const auto allowed = [&](Vec2 p) {
    if (!container.contains(p) || container.distance_to_boundary(p) < margin) return false;
    return std::all_of(occupied.begin(), occupied.end(), [&](Vec2 q) { return !(norm(p - q) < clearance); });
  };
  for (int it = 0; it < iterations; ++it) {
    std::vector<Vec2> sum(seeds.size(), Vec2{0.0, 0.0});
    std::vector<int> count(seeds.size(), 0);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Vec2 p = points[i];
      double nearest = occupied_d2[i];
      int owner = -1;
      for (std::size_t k = 0; k < seeds.size(); ++k)
        if (const double d = dot(p - seeds[k], p - seeds[k]); d < nearest) nearest = d, owner = static_cast<int>(k);
      if (owner < 0) continue;
      sum[owner] = sum[owner] + p;
      ++count[owner];
    }
    for (std::size_t k = 0; k < seeds.size(); ++k) {
      if (count[k] == 0) continue;
      const Vec2 centroid = sum[k] * (1.0 / count[k]);
      if (allowed(centroid)) seeds[k] = centroid;
    }
  }
  return seeds;
}

}  // namespace animpak
