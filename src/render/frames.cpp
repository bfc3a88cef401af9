#include <algorithm>
#include <cmath>

#include "animpak/curve.hpp"
#include "animpak/render.hpp"

namespace animpak {

std::vector<double> frame_times(int count, bool loop) {
  std::vector<double> t(count);
  for (int i = 0; i < count; ++i) t[i] = loop ? double(i) / count : (count > 1 ? double(i) / (count - 1) : 0.0);
  return t;
}

double element_scale(const World& world, int element, const std::vector<Vec2>& positions) {
  const SliceMesh& rest = world.library[world.elements[element].library].slice;
  const int B = rest.boundary_count;
  const std::vector<Vec2> now(positions.begin(), positions.begin() + B),
      before(rest.vertices.begin(), rest.vertices.begin() + B);
  return std::sqrt(std::abs(signed_area(now)) / std::max(std::abs(signed_area(before)), 1e-300));
}

int raster_width(const Box& box, int height) {
  return std::max(1, static_cast<int>(std::lround(height * box.width() / std::max(box.height(), 1e-9))));
}

ElementArt element_art(const World& world, int element, const std::vector<Vec2>& positions) {
  const SpacetimeElement& lib = world.library[world.elements[element].library];
  return {replay_art(lib.binding, lib.slice, positions), element_scale(world, element, positions)};
}

Vec2 art_centroid(const ElementArt& art) {
  Vec2 sum;
  std::size_t n = 0;
  for (const auto& path : art.points)
    for (const auto& line : path)
      for (const Vec2& p : line) sum = sum + p, ++n;
  return n > 0 ? sum * (1.0 / double(n)) : sum;
}

std::vector<Vec2> element_path(const World& world, const SimState& state, int element,
                               const std::vector<double>& times) {
  const std::vector<Vec2> tangents = element_tangents(world, state, element);
  std::vector<Vec2> path;
  path.reserve(times.size());
  for (double t : times)
    path.push_back(art_centroid(element_art(world, element, element_at(world, state, element, t, tangents))));
  return path;
}

std::vector<std::vector<Vec2>> frame_tangents(const World& world, const SimState& state) {
  std::vector<std::vector<Vec2>> tangents(world.elements.size());
  for (std::size_t i = 0; i < world.elements.size(); ++i) tangents[i] = element_tangents(world, state, int(i));
  return tangents;
}

std::vector<ElementArt> frame_art(const World& world, const SimState& state, double tf,
                                  const std::vector<std::vector<Vec2>>& tangents) {
  const std::size_t n = world.elements.size();
  std::vector<ElementArt> art(drawn_count(world));
  for (std::size_t i = 0; i < n; ++i)
    art[i] = element_art(world, int(i), element_at(world, state, int(i), tf, tangents[i]));
  // Mirror symmetry: each element's art reflected across the line (docs/scene-format.md, "Mirror").
  if (const std::optional<MirrorLine>& line = world.container.mirror)
    for (std::size_t i = 0; i < n; ++i) {
      art[n + i] = art[i];
      for (auto& path : art[n + i].points)
        for (auto& polyline : path)
          for (Vec2& p : polyline) p = line->reflect(p);
    }
  return art;
}

std::vector<ElementArt> frame_art(const World& world, const SimState& state, double tf) {
  return frame_art(world, state, tf, frame_tangents(world, state));
}

ArtPoints own_points(const ArtShape& art) {
  ArtPoints points(art.paths.size());
  for (std::size_t p = 0; p < art.paths.size(); ++p)
    for (const Polyline& line : art.paths[p].polylines) points[p].push_back(line.points);
  return points;
}

Picture draw_frame(const World& world, const std::vector<ElementArt>& art, const FrameStyle& style) {
  const Box box = world.container.shown_bounds();
  const int height = style.size;
  const int width = raster_width(box, height);
  Picture pic(width, height, box, style.background, 0.02 * style.size);
  if (style.container == ContainerDrawing::fill) pic.draw_art(world.container.art, own_points(world.container.art));
  for (std::size_t i = 0; i < art.size(); ++i)
    pic.draw_art(world.library[world.elements[drawn_source(world, int(i))].library].art.art, art[i].points, 1.0,
                 art[i].stroke_scale);
  if (style.container == ContainerDrawing::outline) {
    const double w = std::max(1.0, style.size / 400.0);
    pic.draw_ring(world.container.shown_outline(), {0.55, 0.55, 0.55, 1}, w);
    for (const auto& hole : world.container.shown_holes()) pic.draw_ring(hole, {0.55, 0.55, 0.55, 1}, w);
  }
  return pic;
}

Picture draw_frame(const World& world, const SimState& state, double tf, const FrameStyle& style) {
  return draw_frame(world, frame_art(world, state, tf), style);
}

}  // namespace animpak
