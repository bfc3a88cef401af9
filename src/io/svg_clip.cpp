// The clip of a nested viewport (an inner <svg>, or a <symbol> drawn by <use>): SVG 1.1 14.3.3 clips what
// such an element draws to its viewport unless `overflow` is visible. A path that crosses the edge is cut
// with Clipper, as the outline is (src/element/outline.cpp): its fill becomes the fill inside the clip, and
// its stroke, drawn with round joins and caps as everywhere in animpak, becomes a filled band inside the
// clip (docs/scene-format.md, "SVG structure").
#include <algorithm>
#include <cmath>
#include <polyclipping/clipper.hpp>

#include "svg_internal.hpp"

namespace animpak::svg {
namespace {

namespace cl = ClipperLib;

// The signed distance from p to the inside of edge a→b of a convex polygon wound `sign` (positive inside).
double inside_distance(Vec2 p, Vec2 a, Vec2 b, double sign) {
  const Vec2 ab = b - a;
  const double len = norm(ab);
  if (len == 0.0) return 0.0;
  return sign * cross(ab, p - a) / len;
}

double winding_sign(const std::vector<Vec2>& quad) { return signed_area(quad) >= 0.0 ? 1.0 : -1.0; }

// Every point at least `margin` inside the convex polygon.
bool all_inside(const std::vector<Polyline>& lines, const std::vector<Vec2>& clip, double margin) {
  const double sign = winding_sign(clip);
  for (const Polyline& line : lines)
    for (Vec2 p : line.points)
      for (size_t k = 0; k < clip.size(); ++k) {
        // Art drawn up to the edge (a symbol filling its viewBox) is inside despite rounding.
        const Vec2 a = clip[k], b = clip[(k + 1) % clip.size()];
        if (inside_distance(p, a, b, sign) < margin - 1e-9 * (norm(a) + norm(b) + margin)) return false;
      }
  return true;
}

struct Scale {
  double s = 1.0;
  cl::IntPoint to(Vec2 p) const {
    return {static_cast<cl::cInt>(std::llround(p.x * s)), static_cast<cl::cInt>(std::llround(p.y * s))};
  }
  Vec2 from(const cl::IntPoint& p) const { return {static_cast<double>(p.X) / s, static_cast<double>(p.Y) / s}; }
};

cl::Path to_path(const std::vector<Vec2>& points, const Scale& scale) {
  cl::Path path;
  path.reserve(points.size());
  for (Vec2 p : points) path.push_back(scale.to(p));
  return path;
}

cl::Paths intersect(const cl::Paths& subject, cl::PolyFillType rule, const cl::Paths& clip) {
  cl::Clipper clipper;
  clipper.AddPaths(subject, cl::ptSubject, true);
  clipper.AddPaths(clip, cl::ptClip, true);
  cl::Paths out;
  clipper.Execute(cl::ctIntersection, out, rule, cl::pftNonZero);
  return out;
}

std::vector<Polyline> to_polylines(const cl::Paths& paths, const Scale& scale) {
  std::vector<Polyline> out;
  for (const cl::Path& path : paths) {
    if (path.size() < 3) continue;
    Polyline line;
    line.closed = true;
    for (const cl::IntPoint& p : path) line.points.push_back(scale.from(p));
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace

std::vector<ArtPath> clip_to_viewports(ArtPath path, const std::vector<std::vector<Vec2>>& clips, double tolerance) {
  const bool stroked = path.stroke.enabled && path.stroke_width > 0.0;
  const double half = stroked ? 0.5 * path.stroke_width : 0.0;
  if (std::all_of(clips.begin(), clips.end(),
                  [&](const std::vector<Vec2>& clip) { return all_inside(path.polylines, clip, half); })) {
    std::vector<ArtPath> out;
    out.push_back(std::move(path));
    return out;
  }
  // Integer coordinates about 1e9 times finer than the art's extent.
  double extent = 1.0;
  for (const Polyline& line : path.polylines)
    for (Vec2 p : line.points) extent = std::max({extent, std::abs(p.x) + half, std::abs(p.y) + half});
  for (const auto& clip : clips)
    for (Vec2 p : clip) extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
  const Scale scale{1e9 / extent};

  cl::Paths window = {to_path(clips.front(), scale)};
  for (size_t k = 1; k < clips.size(); ++k) window = intersect(window, cl::pftNonZero, {to_path(clips[k], scale)});

  std::vector<ArtPath> out;
  ArtPath fill = path, band = path;
  fill.stroke.enabled = false;
  band.fill = path.stroke;
  band.stroke.enabled = false;
  band.fill_rule = fill.fill_rule = FillRule::evenodd;  // Clipper's output never overlaps itself
  if (path.fill.enabled) {
    cl::Paths subject;
    for (const Polyline& line : path.polylines)
      if (line.points.size() >= 3) subject.push_back(to_path(line.points, scale));  // open ones filled as closed
    fill.polylines = to_polylines(
        intersect(subject, path.fill_rule == FillRule::evenodd ? cl::pftEvenOdd : cl::pftNonZero, window), scale);
  } else {
    fill.polylines.clear();
  }
  if (stroked) {
    cl::ClipperOffset offset(2.0, tolerance * scale.s);
    for (const Polyline& line : path.polylines)
      offset.AddPath(to_path(line.points, scale), cl::jtRound, line.closed ? cl::etClosedLine : cl::etOpenRound);
    cl::Paths stroke;
    offset.Execute(stroke, half * scale.s);
    band.polylines = to_polylines(intersect(stroke, cl::pftNonZero, window), scale);
  } else {
    band.polylines.clear();
  }
  const bool stroke_first = path.paint_order == PaintOrder::stroke_then_fill;
  for (ArtPath* piece : stroke_first ? std::vector<ArtPath*>{&band, &fill} : std::vector<ArtPath*>{&fill, &band})
    if (!piece->polylines.empty()) out.push_back(std::move(*piece));
  return out;
}

}  // namespace animpak::svg
