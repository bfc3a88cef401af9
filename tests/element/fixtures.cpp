#include "element/fixtures.hpp"

#include <algorithm>
#include <cmath>
#include <polyclipping/clipper.hpp>

namespace animpak::test {

namespace {
namespace cl = ClipperLib;
constexpr double clipper_scale = 1e9;  // as element_outline: 1e-9 in unit coordinates

cl::Paths to_paths(const std::vector<std::vector<Vec2>>& rings) {
  cl::Paths paths;
  for (const auto& ring : rings) {
    cl::Path& path = paths.emplace_back();
    for (Vec2 p : ring)
      path.push_back({static_cast<cl::cInt>(std::llround(p.x * clipper_scale)),
                      static_cast<cl::cInt>(std::llround(p.y * clipper_scale))});
  }
  return paths;
}

double area_of(const cl::Paths& paths) {
  double area = 0.0;
  for (const cl::Path& p : paths) area += cl::Area(p);  // holes come out negative
  return area / (clipper_scale * clipper_scale);
}
}  // namespace

ArtShape star_art() { return load_art(std::string(ANIMPAK_SOURCE_DIR) + "/examples/default/star.svg"); }

ArtCoverage art_outside_boundary(const Built& b) {
  const cl::Paths art = to_paths(painted_region(b.art.art));
  const cl::Paths boundary =
      to_paths({std::vector<Vec2>(b.mesh.vertices.begin(), b.mesh.vertices.begin() + b.mesh.boundary_count)});
  cl::Clipper clipper;
  clipper.AddPaths(art, cl::ptSubject, true);
  clipper.AddPaths(boundary, cl::ptClip, true);
  cl::Paths outside;
  clipper.Execute(cl::ctDifference, outside, cl::pftNonZero, cl::pftNonZero);
  return {area_of(art), area_of(outside)};
}

std::string shape_path(const std::string& name) {
  return std::string(ANIMPAK_SOURCE_DIR) + "/examples/shapes/" + name + ".path";
}

Built build(const ArtShape& art, const Params& params, std::uint64_t seed) {
  Built b;
  b.art = normalize_art(art);
  b.outline = element_outline(b.art, params.element.offset);
  b.mesh = build_slice(b.outline, params, seed);
  return b;
}

namespace {
double orient(Vec2 a, Vec2 b, Vec2 c) { return cross(b - a, c - a); }
bool segments_meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (((o1 > 0) != (o2 > 0) && o1 != 0 && o2 != 0) && ((o3 > 0) != (o4 > 0) && o3 != 0 && o4 != 0)) return true;
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
