#include "element/fixtures.hpp"

#include <algorithm>
#include <cmath>

namespace animpak::test {

std::string shape_path(const std::string& name) {
  return std::string(ANIMPAK_SOURCE_DIR) + "/examples/shapes/" + name + ".path";
}

Built build(const ArtShape& art, const Params& params, std::uint64_t seed) {
  Built b;
  b.art = normalize_art(art);
  b.outline = element_outline(b.art, params.offset);
  b.mesh = build_slice(b.outline, params, seed);
  return b;
}

namespace {
double orient(Vec2 a, Vec2 b, Vec2 c) {
  return cross(b - a, c - a);
}
bool segments_meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (((o1 > 0) != (o2 > 0) && o1 != 0 && o2 != 0) && ((o3 > 0) != (o4 > 0) && o3 != 0 && o4 != 0))
    return true;
  auto on = [](Vec2 p, Vec2 q, Vec2 r, double o) {
    return o == 0 && std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  return on(a, b, c, o1) || on(a, b, d, o2) || on(c, d, a, o3) || on(c, d, b, o4);
}
}  // namespace

bool ring_simple(const std::vector<Vec2>& ring) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (j == i + 1 || (i == 0 && j == n - 1)) continue;
      if (segments_meet(ring[i], ring[(i + 1) % n], ring[j], ring[(j + 1) % n])) return false;
    }
  return true;
}

}  // namespace animpak::test
