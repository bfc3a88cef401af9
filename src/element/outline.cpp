// Paper §3.1, first step (Fig. 2a): the art scaled into the unit square, and its outline offset by Δs so
// every element is surrounded by a channel of negative space. Polygon booleans and the offset use Clipper
// on int64 coordinates; the ring that comes out is checked to be simple with exact integer predicates.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
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
// Art whose paths cross themselves (each path with its subpaths) more than max_self_crossings times in
// all, or cross themselves and each other more than max_crossings, is refused before the booleans
// (docs/scene-format.md, "Art that crosses itself"): Clipper's union grows with the crossings (a stroke's
// band has about four for each), and the union's holes slow the offsets (max_hole_vertices). A path of
// 2,000 random points, 470,000 crossings, ran for minutes, and 10,000 points, 11.6 million, took 917 MB.
// Of the 7,898 openclipart files that import, the most within paths is 4,559 (a star polygon, {97/48};
// 1,920 for any other), and the most in all 542,585 (art of many overlapping paths; its union takes 0.6 s).
constexpr std::size_t max_self_crossings = 100000;
constexpr std::size_t max_crossings = 2000000;
// Vertices in the holes of the art's union above which the holes are dropped before the offsets: their
// offsets are what made such art slow (2,000 random points: 110,000 hole vertices, 0.4 s with them
// dropped against minutes), and a detached piece that must be bridged multiplies the offsets by up to 100
// (a random polygon of 80 points, 575 hole vertices, took 4.6 s). 400 of the 7,898 openclipart files
// have more; their outlines come out the same, up to a rounding on the 1e-9 grid in 2 of them.
constexpr std::size_t max_hole_vertices = 200;
// Cell entries plus segments met in cells that counting the crossings may spend on one art, about 0.1 s
// where it runs out (a line drawn back and forth 4,500 times) and 4 bytes a cell entry: 6 times the most
// an openclipart file needs (8.4 million), 8 times what 2,050 triangles crossing 1,980,000 times need.
// Art that needs more lays so many long segments over one another that it is refused too.
constexpr std::size_t crossing_work = 50'000'000;

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

// Every path's polylines, each thinned by `thinning` first when it is positive.
std::vector<std::vector<std::vector<Vec2>>> art_points(const ArtShape& art, double thinning) {
  std::vector<std::vector<std::vector<Vec2>>> all;
  all.reserve(art.paths.size());
  for (const ArtPath& path : art.paths) {
    std::vector<std::vector<Vec2>>& points = all.emplace_back(own_points(path));
    if (thinning > 0.0)
      for (auto& line : points) line = thin_polyline(line, thinning);
  }
  return all;
}

// Everything the art paints, drawn with `points` (art_points), as one union under the nonzero rule.
cl::Paths painted_union(const ArtShape& art, const std::vector<std::vector<std::vector<Vec2>>>& points) {
  cl::Paths all;
  for (std::size_t i = 0; i < art.paths.size(); ++i) {
    cl::Paths area = painted_area(art.paths[i], points[i], art.paths[i].stroke_width, arc_tolerance);
    all.insert(all.end(), area.begin(), area.end());
  }
  return union_of(all, cl::pftNonZero);
}

cl::Paths painted_union(const ArtShape& art) { return painted_union(art, art_points(art, 0.0)); }

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

// One polyline as the booleans get it: on Clipper's grid, closed when filled (SVG fills an open subpath
// as if closed) or closed in the file, and the index of its path.
struct Drawn {
  cl::Path points;
  bool closed = false;
  std::size_t path = 0;
};

struct Crossings {
  std::size_t within = 0;             // between segments of one path (its subpaths included)
  std::size_t total = 0;              // between any two segments
  std::vector<std::size_t> per_path;  // the crossings each path takes part in
  std::vector<std::size_t> own;       // the crossings within each path
  bool finished = true;               // false where the work ran out first
};

// The proper crossings between segments of `lines` that are not neighbours on one polyline, counted
// until more than `within_bound` lie within paths or more than `total_bound` in all; segments that only
// touch or overlap do not count. Segments go into a uniform grid over the art's box, each into the cells
// it passes through, and each is tested once against every earlier segment that shares a cell with it,
// so the counts are exact up to where they stop. `work` pays one per cell entry and per segment met in
// a cell; the count stops unfinished where it runs out.
Crossings count_crossings(const std::vector<Drawn>& lines, std::size_t paths, std::size_t within_bound,
                          std::size_t total_bound, std::size_t work) {
  Crossings out;
  out.per_path.assign(paths, 0);
  out.own.assign(paths, 0);
  struct Segment {
    std::uint32_t line, index;  // the segment from point `index` of lines[line] to the next point
  };
  std::vector<Segment> segments;
  std::vector<std::uint32_t> segment_count(lines.size(), 0);
  bool any = false;
  cl::cInt min_x = 0, max_x = 0, min_y = 0, max_y = 0;
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const cl::Path& p = lines[l].points;
    if (p.size() < 2) continue;
    segment_count[l] = static_cast<std::uint32_t>(lines[l].closed && p.size() >= 3 ? p.size() : p.size() - 1);
    for (std::uint32_t k = 0; k < segment_count[l]; ++k) segments.push_back({static_cast<std::uint32_t>(l), k});
    for (const cl::IntPoint& q : p) {
      min_x = any ? std::min(min_x, q.X) : q.X, max_x = any ? std::max(max_x, q.X) : q.X;
      min_y = any ? std::min(min_y, q.Y) : q.Y, max_y = any ? std::max(max_y, q.Y) : q.Y;
      any = true;
    }
  }
  if (segments.size() < 2) return out;
  // About one cell per segment, at most 256 × 256.
  const double cells_per_side = std::ceil(std::sqrt(static_cast<double>(segments.size())));
  const int side = static_cast<int>(std::clamp(cells_per_side, 1.0, 256.0));
  const int nx = max_x > min_x ? side : 1, ny = max_y > min_y ? side : 1;
  const double cell_w = std::max(1.0, static_cast<double>(max_x - min_x) / nx);
  const double cell_h = std::max(1.0, static_cast<double>(max_y - min_y) / ny);
  const auto column = [&](double x) {
    return std::clamp(static_cast<int>(std::floor((x - static_cast<double>(min_x)) / cell_w)), 0, nx - 1);
  };
  const auto row = [&](double y) {
    return std::clamp(static_cast<int>(std::floor((y - static_cast<double>(min_y)) / cell_h)), 0, ny - 1);
  };
  const auto ends = [&](const Segment& s) {
    const cl::Path& p = lines[s.line].points;
    return std::pair<const cl::IntPoint&, const cl::IntPoint&>{p[s.index], p[(s.index + 1) % p.size()]};
  };
  std::vector<std::vector<std::uint32_t>> cells(static_cast<std::size_t>(nx) * ny);
  std::vector<std::size_t> tested_with(segments.size(), segments.size());  // the last segment tested against
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Segment& si = segments[i];
    const auto [a, b] = ends(si);
    const cl::cInt x0 = std::min(a.X, b.X), x1 = std::max(a.X, b.X), y0 = std::min(a.Y, b.Y), y1 = std::max(a.Y, b.Y);
    for (int c = column(static_cast<double>(x0)), c_end = column(static_cast<double>(x1)); c <= c_end; ++c) {
      // The segment's y-range within this column, a little wide so that rounding loses no cell.
      double lo = static_cast<double>(y0), hi = static_cast<double>(y1);
      if (a.X != b.X) {
        const double left = std::max(static_cast<double>(x0), static_cast<double>(min_x) + c * cell_w);
        const double right = std::min(static_cast<double>(x1), static_cast<double>(min_x) + (c + 1) * cell_w);
        const double slope = static_cast<double>(b.Y - a.Y) / static_cast<double>(b.X - a.X);
        const double y_left = static_cast<double>(a.Y) + slope * (left - static_cast<double>(a.X));
        const double y_right = static_cast<double>(a.Y) + slope * (right - static_cast<double>(a.X));
        const double margin = 1e-6 * cell_h + 1.0;
        lo = std::max(lo, std::min(y_left, y_right) - margin);
        hi = std::min(hi, std::max(y_left, y_right) + margin);
      }
      for (int r = row(lo), r_end = row(hi); r <= r_end; ++r) {
        std::vector<std::uint32_t>& cell = cells[static_cast<std::size_t>(r) * nx + c];
        for (const std::uint32_t j : cell) {
          if (work == 0) {
            out.finished = false;
            return out;
          }
          --work;
          if (tested_with[j] == i) continue;
          tested_with[j] = i;
          const Segment& sj = segments[j];
          // Neighbours on one polyline share an end point; j comes before i.
          if (sj.line == si.line && (sj.index + 1 == si.index || (lines[si.line].closed && sj.index == 0 &&
                                                                  si.index + 1 == segment_count[si.line])))
            continue;
          const auto [c0, c1] = ends(sj);
          if (std::max(c0.X, c1.X) < x0 || std::min(c0.X, c1.X) > x1 || std::max(c0.Y, c1.Y) < y0 ||
              std::min(c0.Y, c1.Y) > y1)
            continue;
          if (orient(a, b, c0) * orient(a, b, c1) >= 0 || orient(c0, c1, a) * orient(c0, c1, b) >= 0) continue;
          const std::size_t pi = lines[si.line].path, pj = lines[sj.line].path;
          ++out.per_path[pi];
          if (pj != pi) ++out.per_path[pj];
          if (pj == pi) ++out.own[pi], ++out.within;
          if (out.within > within_bound || ++out.total > total_bound) return out;
        }
        if (work == 0) {
          out.finished = false;
          return out;
        }
        --work;
        cell.push_back(static_cast<std::uint32_t>(i));
      }
    }
  }
  return out;
}

std::string path_label(const ArtPath& path) {
  return "path " + std::to_string(path.source_index) + (path.id.empty() ? "" : " ('" + path.id + "')");
}

// Refuses art whose paths cross themselves more than max_self_crossings times, or each other more than
// max_crossings, before the booleans would spend minutes and gigabytes on it. `points` are what the
// booleans get (art_points).
void refuse_crossing_art(const ArtShape& art, const std::vector<std::vector<std::vector<Vec2>>>& points,
                         const std::string& name) {
  std::vector<Drawn> lines;
  for (std::size_t i = 0; i < art.paths.size(); ++i)
    for (std::size_t q = 0; q < points[i].size() && q < art.paths[i].polylines.size(); ++q)
      lines.push_back({to_path(points[i][q]), art.paths[i].polylines[q].closed || art.paths[i].fill.enabled, i});
  const Crossings c = count_crossings(lines, art.paths.size(), max_self_crossings, max_crossings, crossing_work);
  if (c.finished && c.within <= max_self_crossings && c.total <= max_crossings) return;
  const auto path_of = [&](const std::vector<std::size_t>& counts) {
    const std::size_t i = static_cast<std::size_t>(std::max_element(counts.begin(), counts.end()) - counts.begin());
    std::size_t n = 0;
    for (const std::vector<Vec2>& line : points[i]) n += line.size();
    return path_label(art.paths[i]) + ", " + std::to_string(n) + " points, " + std::to_string(counts[i]) + " times";
  };
  const std::string advice = "; simplify the path in your editor. A path that crosses itself more than " +
                             std::to_string(max_self_crossings) +
                             " times, or art whose paths cross each other more than " + std::to_string(max_crossings) +
                             " times, is refused: its outline would take minutes and gigabytes to build";
  if (!c.finished)
    throw InputError(name + ": the art has so many long segments lying over one another that counting where its " +
                     "paths cross would take too long (" + std::to_string(c.total) + " crossings so far" +
                     (c.total > 0 ? "; most in " + path_of(c.per_path) : std::string()) + ")" + advice);
  if (c.within > max_self_crossings)
    throw InputError(name + ": its paths cross themselves more than " + std::to_string(max_self_crossings) +
                     " times (most: " + path_of(c.own) + ")" + advice);
  throw InputError(name + ": its paths cross each other more than " + std::to_string(max_crossings) +
                   " times (most: " + path_of(c.per_path) + ")" + advice);
}

// Where each piece of the offset outline comes from (`pieces`, before bridging, largest first): its
// share of the painted area (the rings of the art's union, each lying in one piece, holes negative),
// the paths that paint in it (each polyline lies in one), and whether the closing left it out of `kept`,
// the outline's contour.
std::vector<OutlinePiece> trace_pieces(const ArtShape& art, const std::vector<std::pair<cl::IntPoint, double>>& rings,
                                       const std::vector<Piece>& pieces, const cl::Path& kept) {
  const auto piece_of = [&](const cl::IntPoint& p) {
    for (std::size_t k = 0; k < pieces.size(); ++k)
      if (cl::PointInPolygon(p, pieces[k].contour) != 0) return static_cast<int>(k);
    return -1;
  };
  std::vector<OutlinePiece> out(pieces.size());
  double total = 0.0;
  for (const auto& [point, area] : rings) {
    total += area;
    if (const int k = piece_of(point); k >= 0) out[k].share += area;
  }
  for (OutlinePiece& piece : out) piece.share = total > 0.0 ? piece.share / total : 0.0;
  for (std::size_t i = 0; i < art.paths.size(); ++i)
    for (const Polyline& line : art.paths[i].polylines) {
      if (line.points.empty()) continue;
      const int k = piece_of(to_int(line.points.front()));
      if (k >= 0 && std::find(out[k].paths.begin(), out[k].paths.end(), static_cast<int>(i)) == out[k].paths.end())
        out[k].paths.push_back(static_cast<int>(i));
    }
  for (std::size_t k = 1; k < pieces.size(); ++k)
    out[k].dropped = !pieces[k].contour.empty() && cl::PointInPolygon(pieces[k].contour.front(), kept) == 0;
  return out;
}

// "path 43 ('shadow') 3.9 %" for a piece of one path; "3 paths (path 4, path 5 ('eye'), …) 0.5 %" for more.
std::string piece_text(const ArtShape& art, const OutlinePiece& piece) {
  std::ostringstream text;
  if (piece.paths.size() == 1) {
    text << path_label(art.paths[piece.paths.front()]);
  } else {
    text << piece.paths.size() << " paths (";
    const std::size_t shown = std::min<std::size_t>(piece.paths.size(), 3);
    for (std::size_t i = 0; i < shown; ++i) text << (i ? ", " : "") << path_label(art.paths[piece.paths[i]]);
    if (piece.paths.size() > shown) text << " and " << piece.paths.size() - shown << " more";
    text << ")";
  }
  text.precision(2);
  text << " " << std::fixed << 100.0 * piece.share << " %";
  return text.str();
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
  const std::vector<std::vector<std::vector<Vec2>>> drawn = art_points(art.art, thinning);
  refuse_crossing_art(art.art, drawn, name);
  cl::Paths shape = painted_union(art.art, drawn);
  double shape_area = 0.0;
  std::size_t hole_vertices = 0;
  std::vector<std::pair<cl::IntPoint, double>> rings;  // a point and the signed area of each ring
  for (const cl::Path& p : shape) {
    shape_area += cl::Area(p);
    hole_vertices += cl::Orientation(p) ? 0 : p.size();
    if (!p.empty()) rings.emplace_back(p.front(), cl::Area(p));
  }
  if (!(shape_area > 0.0))
    throw InputError(name + ": the art encloses no area (no filled region and no stroke with a width)");
  // The union's holes do not shape the outline: growing the art never reaches out of a hole, and only
  // outer contours are kept (outer_pieces: the element is solid). But the offsets spend time on every
  // one of their vertices, minutes where they crowd, as in art that crosses itself; so many are dropped
  // first (docs/scene-format.md, "Art that crosses itself").
  if (hole_vertices > max_hole_vertices) std::erase_if(shape, [](const cl::Path& p) { return !cl::Orientation(p); });

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
  const std::vector<Piece> apart = separate > 1 ? pieces : std::vector<Piece>{};
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
  if (separate > 1) {
    // Which art each piece is: a drop shadow or a stray mark that became part of the outline is left out
    // by the element's `exclude` (docs/scene-format.md, "Leaving pieces of the art out").
    out.pieces = trace_pieces(art.art, rings, apart, pieces.front().contour);
    out.bridge_radius = pieces.size() < separate ? radius : 0.0;
    note << ". The largest piece is " << std::fixed << std::setprecision(2) << 100.0 * out.pieces.front().share
         << " % of the art's area; apart from it:";
    for (std::size_t k = 1; k < out.pieces.size(); ++k)
      note << (k > 1 ? "," : "") << " " << piece_text(art.art, out.pieces[k])
           << (out.pieces[k].dropped ? " (dropped)" : "");
    note << "; `animpak check` names each piece and the element's \"exclude\" entry that leaves it out";
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
