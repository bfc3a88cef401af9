#include <algorithm>
#include <cmath>

#include "animpak/render.hpp"

namespace animpak {
namespace {

// Colours of paper Fig. 2c: black slice edges, red shear edges, dashed blue negative-space edges.
constexpr Rgba edge_colour{0.15, 0.15, 0.15, 1};
constexpr Rgba shear_colour{0.85, 0.15, 0.15, 0.8};
constexpr Rgba negative_space_colour{0.1, 0.35, 0.9, 1};
constexpr Rgba boundary_colour{0, 0, 0, 1};

std::vector<Vec2> slice_positions(const SpacetimeElement& e, int s) {
  std::vector<Vec2> p(e.vertices_per_slice());
  for (int v = 0; v < e.vertices_per_slice(); ++v) p[v] = e.position(s, v);
  return p;
}

Box slice_box(const std::vector<Vec2>& positions) {
  Box box;
  for (const Vec2& p : positions) box.add(p);
  return box;
}

std::vector<Edge> boundary_edges(const SliceMesh& m) {
  std::vector<Edge> edges;
  for (int b = 0; b < m.boundary_count; ++b) edges.push_back({b, (b + 1) % m.boundary_count});
  return edges;
}

void draw_mesh(Picture& pic, const SliceMesh& m, const std::vector<Vec2>& pos, double scale, bool faint) {
  const double w = std::max(0.6, scale);
  if (faint) {
    pic.draw_edges(pos, m.edges, {0.3, 0.3, 0.3, 0.35}, 0.6 * w);
    return;
  }
  pic.draw_edges(pos, m.negative_space_edges, negative_space_colour, 1.2 * w, true);
  pic.draw_edges(pos, m.shear_edges, shear_colour, 0.7 * w);
  pic.draw_edges(pos, m.edges, edge_colour, 1.0 * w);
  pic.draw_edges(pos, boundary_edges(m), boundary_colour, 2.0 * w);
  pic.draw_dots(pos, boundary_colour, 2.2 * w);
}

}  // namespace

std::vector<std::filesystem::path> write_inspect_pictures(const SpacetimeElement& element,
                                                          const std::filesystem::path& dir, int size) {
  std::filesystem::create_directories(dir);
  std::vector<std::filesystem::path> written;
  const SliceMesh& mesh = element.slice;
  const double line_scale = size / 512.0;
  Box box = slice_box(mesh.vertices);

  {
    Picture pic(size, size, box);
    draw_mesh(pic, mesh, mesh.vertices, line_scale, false);
    written.push_back(dir / (element.name + "-slice.png"));
    pic.write(written.back());
  }
  {
    Picture pic(size, size, box);
    const ArtPoints art = replay_art(element.binding, mesh, mesh.vertices);
    pic.draw_art(element.art.art, art);
    draw_mesh(pic, mesh, mesh.vertices, line_scale, true);
    written.push_back(dir / (element.name + "-art.png"));
    pic.write(written.back());
  }
  {
    // Eight slices across the loop, all in one world box so motion reads as motion.
    const int panels = std::min(8, element.slice_count);
    Box all;
    for (int s = 0; s < element.slice_count; ++s)
      for (const Vec2& p : slice_positions(element, s)) all.add(p);
    const double span = std::max({all.width(), all.height(), 1e-9}) * 1.06;
    const Vec2 centre = 0.5 * (all.min + all.max);
    const int panel = std::max(16, size / 2);
    Picture strip(panel * panels, panel, {{0, 0}, {double(panels), 1}}, {1, 1, 1, 1}, 0.0);
    for (int i = 0; i < panels; ++i) {
      const int s =
          panels == 1 ? 0 : static_cast<int>(std::lround(double(i) * (element.slice_count - 1) / (panels - 1)));
      const std::vector<Vec2> pos = slice_positions(element, s);
      // Map this slice's world box into panel i of the strip's [0, panels] x [0, 1] world.
      auto place = [&](Vec2 p) { return Vec2{i + 0.5 + (p.x - centre.x) / span, 0.5 + (p.y - centre.y) / span}; };
      std::vector<Vec2> placed(pos.size());
      std::transform(pos.begin(), pos.end(), placed.begin(), place);
      ArtPoints art = replay_art(element.binding, mesh, pos);
      for (auto& path : art)
        for (auto& line : path)
          for (Vec2& p : line) p = place(p);
      strip.draw_art(element.art.art, art);
      draw_mesh(strip, mesh, placed, line_scale * 0.5, true);
      strip.draw_ring({{double(i), 0.0}, {i + 1.0, 0.0}, {i + 1.0, 1.0}, {double(i), 1.0}}, {0.8, 0.8, 0.8, 1}, 1.0);
    }
    written.push_back(dir / (element.name + "-strip.png"));
    strip.write(written.back());
  }
  return written;
}

Picture draw_art_preview(const ArtShape& art, int size) {
  Box box;
  if (art.viewport) {
    box = *art.viewport;
  } else {
    double half_stroke = 0.0;
    for (const ArtPath& path : art.paths)
      if (path.stroke.enabled) half_stroke = std::max(half_stroke, 0.5 * path.stroke_width);
    box = art.bounds();
    box.add(box.min - Vec2{half_stroke, half_stroke});
    box.add(box.max + Vec2{half_stroke, half_stroke});
  }
  // One scale for both axes, the shorter side rounded up and the viewport at the top-left corner, as
  // rsvg-convert sizes a document given its longer side.
  const double side = std::max(box.width(), box.height());
  const double scale = side > 0.0 ? size / side : 1.0;
  const auto pixels = [&](double length) { return std::max(1, static_cast<int>(std::ceil(length * scale - 1e-6))); };
  const int width = pixels(box.width()), height = pixels(box.height());
  box.add(box.min + Vec2{width / scale, height / scale});
  Picture pic(width, height, box, {0, 0, 0, 0}, 0.0);
  ArtPoints points;
  for (const ArtPath& path : art.paths) {
    auto& lines = points.emplace_back();
    for (const Polyline& line : path.polylines) lines.push_back(line.points);
  }
  pic.draw_art(art, points, 1.0, 1.0, 0.0);
  return pic;
}

}  // namespace animpak
