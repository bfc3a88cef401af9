#include <algorithm>
#include <cmath>
#include <limits>

#include "animpak/render.hpp"

namespace animpak {
namespace {

constexpr int coverage_size = 256;  // raster height for coverage: ±0.5 % at typical packings

// Every element's art painted opaque (colours do not matter, only coverage).
void paint_opaque(Picture& pic, const World& world, const SimState& state, double tf, int element) {
  const SpacetimeElement& lib = world.library[world.elements[element].library];
  ArtShape opaque = lib.art.art;
  for (ArtPath& p : opaque.paths) {
    p.fill.color.a = 1.0;
    p.stroke.color.a = 1.0;
  }
  const std::vector<Vec2> positions = element_at(world, state, element, tf);
  pic.draw_art(opaque, replay_art(lib.binding, lib.slice, positions), 1.0, element_scale(world, element, positions));
}

std::pair<int, int> raster_size(const Box& box) {
  return {raster_width(box, coverage_size), coverage_size};
}

// Coverage on a raster: the container (outline minus holes, even–odd) against every element's art;
// the ratio of covered container pixels.
double coverage(const World& world, const SimState& state, double tf) {
  const Box box = world.container.bounds();
  const auto [w, h] = raster_size(box);
  ArtShape region;
  ArtPath path;
  path.fill = {true, {0, 0, 0, 1}};
  path.fill_rule = FillRule::evenodd;
  path.polylines.push_back({world.container.outline, true});
  for (const auto& hole : world.container.holes) path.polylines.push_back({hole, true});
  region.paths.push_back(path);
  ArtPoints region_points(1);
  for (const Polyline& l : path.polylines) region_points[0].push_back(l.points);

  Picture inside(w, h, box, {0, 0, 0, 0}, 0.0);
  inside.draw_art(region, region_points);
  Picture art(w, h, box, {0, 0, 0, 0}, 0.0);
  for (std::size_t i = 0; i < world.elements.size(); ++i) paint_opaque(art, world, state, tf, int(i));
  const std::vector<unsigned char> a = inside.rgba8(), b = art.rgba8();
  std::size_t container_pixels = 0, covered = 0;
  for (std::size_t k = 3; k < a.size(); k += 4) {
    if (a[k] < 128) continue;
    ++container_pixels;
    covered += b[k] >= 128;
  }
  return container_pixels ? double(covered) / double(container_pixels) : 0.0;
}

// Whether two elements' art shares pixels: their offset outlines may overlap by up to the channel
// without the art touching, so only the art decides.
bool art_overlaps(const World& world, const SimState& state, double tf, int i, int j) {
  const Box box = world.container.bounds();
  const auto [w, h] = raster_size(box);
  Picture a(w, h, box, {0, 0, 0, 0}, 0.0), b(w, h, box, {0, 0, 0, 0}, 0.0);
  paint_opaque(a, world, state, tf, i);
  paint_opaque(b, world, state, tf, j);
  const std::vector<unsigned char> pa = a.rgba8(), pb = b.rgba8();
  for (std::size_t k = 3; k < pa.size(); k += 4)
    if (pa[k] >= 128 && pb[k] >= 128) return true;
  return false;
}

}  // namespace

FrameMetrics measure_frame(const World& world, const SimState& state, double tf) {
  FrameMetrics m;
  m.t = tf;
  m.coverage = coverage(world, state, tf);
  const std::size_t n = world.elements.size();
  std::vector<std::vector<Vec2>> rings(n);
  std::vector<Box> boxes(n);
  for (std::size_t i = 0; i < n; ++i) {
    const int B = world.library[world.elements[i].library].slice.boundary_count;
    std::vector<Vec2> all = element_at(world, state, int(i), tf);
    rings[i].assign(all.begin(), all.begin() + B);
    for (Vec2 p : rings[i]) boxes[i].add(p);
  }
  std::vector<double> nearest(n, std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      // Boxes farther apart than both current nearest distances cannot change either.
      const double dx = std::max({0.0, boxes[j].min.x - boxes[i].max.x, boxes[i].min.x - boxes[j].max.x});
      const double dy = std::max({0.0, boxes[j].min.y - boxes[i].max.y, boxes[i].min.y - boxes[j].max.y});
      if (std::hypot(dx, dy) > std::max(nearest[i], nearest[j])) continue;
      const double gap = ring_gap(rings[i], rings[j]);
      if (gap == 0.0) m.overlapping_pairs += art_overlaps(world, state, tf, int(i), int(j));
      nearest[i] = std::min(nearest[i], gap);
      nearest[j] = std::min(nearest[j], gap);
    }
  if (n >= 2) {
    m.min_gap = *std::min_element(nearest.begin(), nearest.end());
    double sum = 0.0;
    for (double d : nearest) sum += d;
    m.mean_gap = sum / double(n);
  }
  return m;
}

}  // namespace animpak
