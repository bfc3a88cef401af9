// Whether an art path crosses itself (animpak/element.hpp): `animpak check` warns of such paths, whose
// painted region depends on the fill rule. A sweep over x tests only the segments whose x-ranges overlap,
// which keeps traced art with thousands of points fast.
#include <algorithm>
#include <vector>

#include "animpak/element.hpp"

namespace animpak {

bool crosses_itself(const Polyline& line) {
  const std::vector<Vec2>& p = line.points;
  const std::size_t n = p.size(), segments = line.closed ? n : n - 1;
  if (n < 4) return false;
  const auto end = [&](std::size_t i) { return p[(i + 1) % n]; };
  std::vector<std::size_t> order(segments);
  for (std::size_t i = 0; i < segments; ++i) order[i] = i;
  const auto lo = [&](std::size_t i) { return std::min(p[i].x, end(i).x); };
  const auto hi = [&](std::size_t i) { return std::max(p[i].x, end(i).x); };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return lo(a) < lo(b); });
  for (std::size_t k = 0; k < segments; ++k) {
    const std::size_t i = order[k];
    for (std::size_t m = k + 1; m < segments && lo(order[m]) <= hi(i); ++m) {
      const std::size_t j = order[m];
      const bool neighbours = (i + 1) % n == j || (j + 1) % n == i;
      if (!neighbours && segments_cross(p[i], end(i), p[j], end(j))) return true;
    }
  }
  return false;
}

}  // namespace animpak
