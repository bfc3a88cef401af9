// Paper §3.1, first step (Fig. 2a): the art scaled into the unit square, and its outline offset by Δs so
// every element is surrounded by a channel of negative space. Polygon booleans and the offset use Clipper
// on int64 coordinates; the ring that comes out is checked to be simple with exact integer predicates.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <polyclipping/clipper.hpp>
#include <sstream>

#include "animpak/element.hpp"
#include "animpak/error.hpp"

namespace animpak {
namespace {

namespace cl = ClipperLib;

// Unit-square coordinates are scaled by 1e9 into int64: 1e-9 precision, far below any sample spacing,
// and far inside Clipper's 4.6e18 coordinate range even for art well outside the unit square.
constexpr double clipper_scale = 1e9;
// Largest distance between a round join and its polygon, in unit-square units (≈44 segments per full
// circle at Δs = 0.04; the last chord of a join spans up to 1.5 steps, so up to 2.25e-4 inside Δs). The
// outline is simplified to boundary_tolerance (80× this at its default) afterwards, so finer arcs buy
// nothing.
constexpr double arc_tolerance = 1e-4;
// Art with more points than this is a trace (docs/parameters.md "Thinning traced art"): its polylines are
// thinned within art_thinning before the booleans, as Clipper's union and offset grow quadratically with
// the pixel-sized steps of a trace, each a local extremum. A quarter of boundary_tolerance's default, so
// the sampled outline hardly shows it; the thinned art is offset by Δs plus this, so the outline still
// keeps Δs from every point of the art as drawn. Smaller art is offset exactly as drawn.
constexpr std::size_t thin_above_points = 10000;
constexpr double art_thinning = 2e-3;
// Closing radii tried, in unit-square units, to bridge detached art into one outline
// (docs/parameters.md "Bridging detached art").
constexpr double bridge_step = 0.005;
constexpr double max_bridge_radius = 0.25;

std::string source_name(const ArtShape& art) { return art.source.empty() ? std::string("<art>") : art.source.string(); }

cl::IntPoint to_int(Vec2 p) {
  return {static_cast<cl::cInt>(std::llround(p.x * clipper_scale)),
          static_cast<cl::cInt>(std::llround(p.y * clipper_scale))};
}

Vec2 to_unit(const cl::IntPoint& p) {
  return {static_cast<double>(p.X) / clipper_scale, static_cast<double>(p.Y) / clipper_scale};
}

cl::Path to_path(const std::vector<Vec2>& points) {
  cl::Path path;
  path.reserve(points.size());
  for (Vec2 p : points) path.push_back(to_int(p));
  return path;
}

cl::Paths union_of(const cl::Paths& paths, cl::PolyFillType rule) {
  cl::Clipper clipper;
  clipper.AddPaths(paths, cl::ptSubject, true);
  cl::Paths out;
  clipper.Execute(cl::ctUnion, out, rule, rule);
  return out;
}

// The visible area of one path drawn with `points` (its own, or replayed on a deformed slice) and
// `stroke_width`: its fill under its own fill rule (SVG fills open subpaths as if closed), plus its
// stroke, which is visible art too and so must lie inside the element.
cl::Paths painted_area(const ArtPath& path, const std::vector<std::vector<Vec2>>& points, double stroke_width,
                       double tolerance) {
  cl::Paths fill;
  cl::ClipperOffset stroke(2.0, tolerance * clipper_scale);
  bool stroked = path.stroke.enabled && stroke_width > 0.0;
  for (std::size_t q = 0; q < path.polylines.size() && q < points.size(); ++q) {
    const bool closed = path.polylines[q].closed;
    cl::Path p = to_path(points[q]);
    if (p.empty()) continue;
    if ((closed || path.fill.enabled) && p.size() >= 3) fill.push_back(p);
    if (stroked) stroke.AddPath(p, cl::jtRound, closed ? cl::etClosedLine : cl::etOpenRound);
  }
  cl::Paths area = union_of(fill, path.fill_rule == FillRule::evenodd ? cl::pftEvenOdd : cl::pftNonZero);
  if (stroked) {
    cl::Paths band;
    stroke.Execute(band, 0.5 * stroke_width * clipper_scale);
    area.insert(area.end(), band.begin(), band.end());
  }
  return area;
}

std::vector<std::vector<Vec2>> own_points(const ArtPath& path) {
  std::vector<std::vector<Vec2>> points;
  points.reserve(path.polylines.size());
  for (const Polyline& line : path.polylines) points.push_back(line.points);
  return points;
}

// Everything the art paints, as one union under the nonzero rule; each polyline thinned by `thinning`
// first when it is positive.
cl::Paths painted_union(const ArtShape& art, double thinning = 0.0) {
  cl::Paths all;
  for (const ArtPath& path : art.paths) {
    std::vector<std::vector<Vec2>> points = own_points(path);
    if (thinning > 0.0)
      for (auto& line : points) line = thin_polyline(line, thinning);
    cl::Paths area = painted_area(path, points, path.stroke_width, arc_tolerance);
    all.insert(all.end(), area.begin(), area.end());
  }
  return union_of(all, cl::pftNonZero);
}

cl::Paths offset_by(const cl::Paths& paths, double delta) {
  cl::ClipperOffset offset(2.0, arc_tolerance * clipper_scale);
  offset.AddPaths(paths, cl::jtRound, cl::etClosedPolygon);
  cl::Paths out;
  offset.Execute(out, delta * clipper_scale);
  return out;
}

struct Piece {
  double area = 0.0;  // int64 units²
  cl::Path contour;
};

// The outer contours of the union of `paths`, largest first; holes are dropped because the element is
// solid (§3.1 samples only "the outer boundary of the offset path"). Strictly simple output splits
// pieces that only touch at a vertex, so every contour is simple.
std::vector<Piece> outer_pieces(const cl::Paths& paths) {
  cl::Clipper clean;
  clean.StrictlySimple(true);
  clean.AddPaths(paths, cl::ptSubject, true);
  cl::PolyTree tree;
  clean.Execute(cl::ctUnion, tree, cl::pftNonZero, cl::pftNonZero);
  std::vector<Piece> pieces;
  for (const cl::PolyNode* node : tree.Childs) pieces.push_back({std::fabs(cl::Area(node->Contour)), node->Contour});
  std::stable_sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) { return a.area > b.area; });
  return pieces;
}

// 128-bit products of int64 differences cannot overflow, so the predicates below are exact.
__extension__ typedef __int128 wide;

int orient(const cl::IntPoint& a, const cl::IntPoint& b, const cl::IntPoint& c) {
  const wide d = static_cast<wide>(b.X - a.X) * (c.Y - a.Y) - static_cast<wide>(b.Y - a.Y) * (c.X - a.X);
  return (d > 0) - (d < 0);
}

bool on_segment(const cl::IntPoint& a, const cl::IntPoint& b, const cl::IntPoint& c) {
  return std::min(a.X, b.X) <= c.X && c.X <= std::max(a.X, b.X) && std::min(a.Y, b.Y) <= c.Y &&
         c.Y <= std::max(a.Y, b.Y);
}

bool segments_touch(const cl::IntPoint& a, const cl::IntPoint& b, const cl::IntPoint& c, const cl::IntPoint& d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) || (o3 == 0 && on_segment(c, d, a)) ||
         (o4 == 0 && on_segment(c, d, b));
}

bool ring_is_simple(const cl::Path& ring) {
  const std::size_t n = ring.size();
  if (n < 3) return false;
  // Sweep over x: segments sorted by their left end; each is tested only against those whose x-range
  // overlaps it. Neighbours along the ring share exactly one end point and are not tested.
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  auto lo = [&](std::size_t i) { return std::min(ring[i].X, ring[(i + 1) % n].X); };
  auto hi = [&](std::size_t i) { return std::max(ring[i].X, ring[(i + 1) % n].X); };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return lo(a) < lo(b); });
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    for (std::size_t m = k + 1; m < n && lo(order[m]) <= hi(i); ++m) {
      const std::size_t j = order[m];
      const bool adjacent = (i + 1) % n == j || (j + 1) % n == i;
      if (adjacent) {
        // Adjacent segments may only meet at their shared end: reject a fold back onto itself.
        const std::size_t first = (i + 1) % n == j ? i : j;
        const cl::IntPoint& a = ring[first];
        const cl::IntPoint& s = ring[(first + 1) % n];
        const cl::IntPoint& c = ring[(first + 2) % n];
        const wide along = static_cast<wide>(c.X - s.X) * (a.X - s.X) + static_cast<wide>(c.Y - s.Y) * (a.Y - s.Y);
        if (n > 3 && orient(a, s, c) == 0 && along > 0) return false;
        continue;
      }
      if (segments_touch(ring[i], ring[(i + 1) % n], ring[j], ring[(j + 1) % n])) return false;
    }
  }
  return true;
}

}  // namespace

std::vector<std::vector<Vec2>> painted_region(const ArtPath& path, const std::vector<std::vector<Vec2>>& points,
                                              double stroke_width, double tolerance) {
  const cl::Paths region = union_of(painted_area(path, points, stroke_width, tolerance), cl::pftNonZero);
  std::vector<std::vector<Vec2>> rings;
  rings.reserve(region.size());
  for (const cl::Path& ring : region) {
    rings.emplace_back();
    rings.back().reserve(ring.size());
    for (const cl::IntPoint& p : ring) rings.back().push_back(to_unit(p));
  }
  return rings;
}

NormalizedArt normalize_art(const ArtShape& art) {
  const Box box = art.bounds();
  for (const ArtPath& path : art.paths)
    for (const Polyline& line : path.polylines)
      for (Vec2 p : line.points)
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
          throw InputError(source_name(art) + ": path '" + path.id + "' has a non-finite coordinate");
  if (box.empty())
    throw InputError(source_name(art) +
                     ": the art has no drawable point; an element needs at least one "
                     "filled or stroked path");
  const double side = std::max(box.width(), box.height());
  if (!(side > 0.0) || !std::isfinite(side))
    throw InputError(source_name(art) +
                     ": the art's bounding box has zero size; an element needs an "
                     "area to pack");
  NormalizedArt out;
  out.frame.art_origin = box.min;
  out.frame.scale = 1.0 / side;
  // §3.1: "we scale the shape to fit a unit square"; the shorter side is centred.
  out.frame.unit_origin = {0.5 * (1.0 - box.width() / side), 0.5 * (1.0 - box.height() / side)};
  out.art = art;
  for (ArtPath& path : out.art.paths) {
    for (Polyline& line : path.polylines)
      for (Vec2& p : line.points) p = out.frame.to_unit(p);
    path.stroke_width *= out.frame.scale;
  }
  return out;
}

std::vector<std::vector<Vec2>> painted_region(const ArtShape& art) {
  std::vector<std::vector<Vec2>> rings;
  for (const cl::Path& path : painted_union(art)) {
    std::vector<Vec2>& ring = rings.emplace_back();
    ring.reserve(path.size());
    for (const cl::IntPoint& p : path) ring.push_back(to_unit(p));
  }
  return rings;
}

Outline element_outline(const NormalizedArt& art, double offset) {
  const std::string name = source_name(art.art);
  std::size_t points = 0;
  for (const ArtPath& path : art.art.paths)
    for (const Polyline& line : path.polylines) points += line.points.size();
  const double thinning = points > thin_above_points ? art_thinning : 0.0;
  const cl::Paths shape = painted_union(art.art, thinning);
  double shape_area = 0.0;
  for (const cl::Path& p : shape) shape_area += cl::Area(p);
  if (!(shape_area > 0.0))
    throw InputError(name + ": the art encloses no area (no filled region and no stroke with a width)");

  // §3.1, Fig. 2a: offset by Δs with round joins so the channel of negative space has constant width.
  // A thinned shape is within `thinning` of the art, so growing it by that much more keeps Δs.
  const double grow = offset + thinning;
  const cl::Paths grown = offset_by(shape, grow);
  std::vector<Piece> pieces = outer_pieces(grown);
  if (pieces.empty() || !(pieces.front().area > 0.0)) throw InputError(name + ": the offset outline has no area");
  // Art apart from the main body (a whisker, a fin filament, a detached eye) must stay inside the
  // element, or the solver never sees it (docs/parameters.md "Bridging detached art"): close the offset
  // outline (offset out by r, offset back) with the smallest radius r, in steps, that joins the pieces.
  // The union with the plain offset keeps every point of the outline at least Δs from the art.
  const std::size_t separate = pieces.size();
  double radius = 0.0;
  while (pieces.size() > 1 && radius < max_bridge_radius) {
    radius = std::min(radius + bridge_step, max_bridge_radius);
    cl::Paths closed = offset_by(offset_by(shape, grow + radius), -radius);
    closed.insert(closed.end(), grown.begin(), grown.end());
    pieces = outer_pieces(closed);
  }

  Outline out;
  out.source = name;
  std::ostringstream note;
  if (separate > 1 && pieces.size() < separate)
    note << name << ": bridged " << separate << " disjoint outline pieces with a closing of radius " << radius
         << (pieces.size() > 1 ? "; " : "");
  if (pieces.size() > 1) {
    note << (note.tellp() > 0 ? "" : name + ": ") << "kept the largest of " << pieces.size()
         << " disjoint outline pieces (area " << pieces.front().area / (clipper_scale * clipper_scale) << "); dropped "
         << pieces.size() - 1 << " with area";
    for (std::size_t i = 1; i < pieces.size(); ++i)
      note << (i > 1 ? ", " : " ") << pieces[i].area / (clipper_scale * clipper_scale);
    note << " (farther than a closing of radius " << max_bridge_radius
         << " bridges; their art is still drawn, bound to the nearest triangle)";
  }
  if (note.tellp() > 0) out.notes.push_back(note.str());

  cl::Path ring = std::move(pieces.front().contour);
  // Drop repeated and collinear points (within 2 integer units, i.e. 2e-9).
  cl::CleanPolygon(ring, 2.0);
  if (ring.size() < 3 || !ring_is_simple(ring))
    throw InputError(name +
                     ": the outline stays self-intersecting after cleaning; simplify the art's "
                     "paths");
  out.ring.reserve(ring.size());
  for (const cl::IntPoint& p : ring) out.ring.push_back(to_unit(p));
  if (signed_area(out.ring) < 0.0) std::reverse(out.ring.begin(), out.ring.end());
  return out;
}

}  // namespace animpak
