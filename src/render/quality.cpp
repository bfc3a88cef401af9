// Frame quality on exact geometry (docs/quality.md): areas from polygon booleans with Clipper on int64
// coordinates, distances from a uniform grid of the regions' boundary segments; the evenness measures
// add a raster of the free space with its distance transform. Nothing here knows a World:
// measure_regions takes plain regions, so it is tested on hand-made squares.
#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "animpak/render.hpp"

namespace animpak {
namespace {

namespace cl = ClipperLib;

// Unit coordinates scaled by 1e9 into int64, the grid painted_region rounds to, so its rings come back
// exactly; areas of elements about 0.1 across are then exact to far below the 1e-6 the tests ask.
constexpr double clipper_scale = 1e9;
// Channel widths are sampled about this far apart (container units) along every element's outline.
constexpr double channel_sample_spacing = 0.005;

constexpr double infinity = std::numeric_limits<double>::infinity();

cl::IntPoint to_int(Vec2 p) {
  return {static_cast<cl::cInt>(std::llround(p.x * clipper_scale)),
          static_cast<cl::cInt>(std::llround(p.y * clipper_scale))};
}

Vec2 to_unit(const cl::IntPoint& p) {
  return {static_cast<double>(p.X) / clipper_scale, static_cast<double>(p.Y) / clipper_scale};
}

// A region as disjoint rings: outer rings positive, holes negative, so that any number of such
// regions together are one region under the non-zero rule.
cl::Paths clean(const Region& region) {
  cl::Clipper clipper;
  for (const std::vector<Vec2>& ring : region.rings) {
    if (ring.size() < 3) continue;
    cl::Path path;
    path.reserve(ring.size());
    for (Vec2 p : ring) path.push_back(to_int(p));
    clipper.AddPath(path, cl::ptSubject, true);
  }
  const cl::PolyFillType rule = region.rule == FillRule::evenodd ? cl::pftEvenOdd : cl::pftNonZero;
  cl::Paths out;
  clipper.Execute(cl::ctUnion, out, rule, rule);
  return out;
}

double area(const cl::Paths& paths) {
  double a = 0.0;
  for (const cl::Path& p : paths) a += cl::Area(p);
  return a / (clipper_scale * clipper_scale);
}

double boolean_area(const cl::Paths& subject, const cl::Paths& clip, cl::ClipType type) {
  cl::Clipper clipper;
  clipper.AddPaths(subject, cl::ptSubject, true);
  clipper.AddPaths(clip, cl::ptClip, true);
  cl::Paths out;
  clipper.Execute(type, out, cl::pftNonZero, cl::pftNonZero);
  return area(out);
}

struct IntBox {
  cl::cInt x0 = std::numeric_limits<cl::cInt>::max(), y0 = x0;
  cl::cInt x1 = std::numeric_limits<cl::cInt>::min(), y1 = x1;
  bool overlaps(const IntBox& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
};

IntBox bounds(const cl::Paths& paths) {
  IntBox b;
  for (const cl::Path& path : paths)
    for (const cl::IntPoint& p : path) {
      b.x0 = std::min(b.x0, p.X), b.x1 = std::max(b.x1, p.X);
      b.y0 = std::min(b.y0, p.Y), b.y1 = std::max(b.y1, p.Y);
    }
  return b;
}

// Inside under the non-zero rule of disjoint rings: inside an odd number of them.
bool inside(const cl::Paths& region, Vec2 p) {
  const cl::IntPoint q = to_int(p);
  int crossings = 0;
  for (const cl::Path& ring : region) {
    const int where = cl::PointInPolygon(q, ring);
    if (where < 0) return true;  // on the boundary
    crossings += where;
  }
  return crossings % 2 == 1;
}

struct Segment {
  Vec2 a, b;
  int owner = -1;  // element id; −1 for the container
};

double point_segment_distance2(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  const double s = len2 > 0.0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  const Vec2 d = p - (a + ab * s);
  return dot(d, d);
}

// Between two segments: 0 when they cross, else the smallest distance from an end to the other segment
// (touching and collinear overlaps have an end at distance 0).
double segment_distance(Vec2 p, Vec2 q, Vec2 a, Vec2 b) {
  const double o1 = cross(q - p, a - p), o2 = cross(q - p, b - p), o3 = cross(b - a, p - a), o4 = cross(b - a, q - a);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return 0.0;
  return std::sqrt(std::min({point_segment_distance2(p, a, b), point_segment_distance2(q, a, b),
                             point_segment_distance2(a, p, q), point_segment_distance2(b, p, q)}));
}

// Every boundary segment filed under each grid cell its box touches. A query searches square rings of
// cells around its own box, nearest first, and stops once the next ring lies farther away than the
// best distance found: cells k rings out are at least k cell widths from the query's box.
class SegmentGrid {
 public:
  explicit SegmentGrid(std::vector<Segment> segments) : segments_(std::move(segments)), seen_(segments_.size(), 0) {
    for (const Segment& s : segments_) box_.add(s.a), box_.add(s.b);
    if (segments_.empty()) return;
    // About one segment per cell, but no more than 1024 cells a side.
    const double extent = std::max({box_.width(), box_.height(), 1e-9});
    cell_ = std::max(
        {std::sqrt(std::max(box_.width() * box_.height(), 1e-18) / double(segments_.size())), extent / 1024.0, 1e-9});
    nx_ = std::max(1, static_cast<int>(std::ceil(box_.width() / cell_)));
    ny_ = std::max(1, static_cast<int>(std::ceil(box_.height() / cell_)));
    begin_.assign(std::size_t(nx_) * ny_ + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<int> fill(begin_.begin(), begin_.end() - 1);
      for (std::size_t i = 0; i < segments_.size(); ++i) {
        const auto [x0, y0, x1, y1] = cells(segments_[i].a, segments_[i].b);
        for (int y = y0; y <= y1; ++y)
          for (int x = x0; x <= x1; ++x) {
            const std::size_t c = std::size_t(y) * nx_ + x;
            if (pass == 0)
              ++begin_[c + 1];
            else
              items_[fill[c]++] = int(i);
          }
      }
      if (pass == 0) {
        for (std::size_t c = 1; c < begin_.size(); ++c) begin_[c] += begin_[c - 1];
        items_.resize(std::size_t(begin_.back()));
      }
    }
  }

  /// The smallest distance from segment pq to a segment whose owner `accept`s, or `cap` when none is
  /// nearer than that.
  template <class Accept>
  double nearest(Vec2 p, Vec2 q, double cap, Accept accept) {
    double best = cap;
    if (segments_.empty() || !(best > 0.0)) return best;
    ++stamp_;
    const auto [x0, y0, x1, y1] = cells(p, q);
    auto visit = [&](int x, int y) {
      if (x < 0 || y < 0 || x >= nx_ || y >= ny_) return;
      const std::size_t c = std::size_t(y) * nx_ + x;
      for (int k = begin_[c]; k < begin_[c + 1]; ++k) {
        const int i = items_[k];
        if (seen_[i] == stamp_) continue;
        seen_[i] = stamp_;
        const Segment& s = segments_[i];
        if (accept(s.owner)) best = std::min(best, segment_distance(p, q, s.a, s.b));
      }
    };
    for (int k = 0;; ++k) {
      const int xa = x0 - k, xb = x1 + k, ya = y0 - k, yb = y1 + k;
      if (k == 0) {
        for (int y = ya; y <= yb; ++y)
          for (int x = xa; x <= xb; ++x) visit(x, y);
      } else {
        for (int x = xa; x <= xb; ++x) visit(x, ya), visit(x, yb);
        for (int y = ya + 1; y < yb; ++y) visit(xa, y), visit(xb, y);
      }
      const bool everything = xa <= 0 && ya <= 0 && xb >= nx_ - 1 && yb >= ny_ - 1;
      if (everything || best <= k * cell_) return best;
    }
  }

 private:
  struct CellRange {
    int x0, y0, x1, y1;
  };
  CellRange cells(Vec2 a, Vec2 b) const {
    auto cx = [&](double x) { return std::clamp(static_cast<int>(std::floor((x - box_.min.x) / cell_)), 0, nx_ - 1); };
    auto cy = [&](double y) { return std::clamp(static_cast<int>(std::floor((y - box_.min.y) / cell_)), 0, ny_ - 1); };
    return {cx(std::min(a.x, b.x)), cy(std::min(a.y, b.y)), cx(std::max(a.x, b.x)), cy(std::max(a.y, b.y))};
  }

  std::vector<Segment> segments_;
  std::vector<unsigned> seen_;  // the query that last tested each segment (segments span several cells)
  unsigned stamp_ = 0;
  Box box_;
  double cell_ = 1.0;
  int nx_ = 0, ny_ = 0;
  std::vector<int> begin_, items_;  // cell c holds items_[begin_[c] .. begin_[c + 1])
};

void add_segments(const cl::Paths& region, int owner, std::vector<Segment>& out) {
  for (const cl::Path& ring : region)
    for (std::size_t k = 0; k < ring.size(); ++k)
      out.push_back({to_unit(ring[k]), to_unit(ring[(k + 1) % ring.size()]), owner});
}

// Points evenly spaced along a closed ring, about channel_sample_spacing apart, the first on its first
// vertex.
std::vector<Vec2> samples_along(const cl::Path& ring) {
  std::vector<Vec2> points(ring.size());
  for (std::size_t k = 0; k < ring.size(); ++k) points[k] = to_unit(ring[k]);
  double perimeter = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k) perimeter += norm(points[(k + 1) % points.size()] - points[k]);
  const long count = std::max(1L, std::lround(perimeter / channel_sample_spacing));
  const double step = perimeter / double(count);
  std::vector<Vec2> out;
  out.reserve(std::size_t(count));
  double start = 0.0;  // arc length at the current edge's first point
  for (std::size_t k = 0; k < points.size() && long(out.size()) < count; ++k) {
    const Vec2 a = points[k], b = points[(k + 1) % points.size()];
    const double length = norm(b - a);
    for (double s = double(out.size()) * step; s < start + length && long(out.size()) < count;
         s = double(out.size()) * step)
      out.push_back(a + (b - a) * ((s - start) / length));
    start += length;
  }
  return out;
}

// The free-space raster has this many pixels along the container's longer side: the contact function's
// distances are within about one pixel, and the largest empty disc starts from its best pixels.
constexpr int raster_cells = 512;
// The largest empty disc climbs from at most this many of the raster's local maxima.
constexpr int disc_candidates = 4;
// The climb stops when its step is below this (container units).
constexpr double climb_tolerance = 1e-7;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 == 1 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// Pixel centres h apart over the container's box with one pixel to spare on every side, so that every
// free centre has a centre that is not free in the raster. A centre is free when it lies inside the
// container and outside all art; a free one's distance approximates its distance to the nearest art or
// wall: the distance to the nearest centre that is not free, less h / 2, since a boundary lies between.
struct FreeSpace {
  Vec2 origin;  // centre of pixel (0, 0)
  double h = 1.0;
  int nx = 0, ny = 0;
  long inside = 0;               // centres inside the container
  std::vector<double> distance;  // per pixel, row-major; −1 when not free
  Vec2 centre(std::size_t i) const {
    return origin + Vec2{double(i % std::size_t(nx)) * h, double(i / std::size_t(nx)) * h};
  }
};

struct Crossing {
  double x;
  int art, wall;  // the steps of the art's and of the container's winding numbers
};

// Which centres are free, and how many lie inside the container: every boundary segment's crossings
// of each row's centre line (half-open in y, so that a vertex on the line counts once), swept left to
// right with the winding numbers of the art and of the container (the cleaned rings wind once around
// what they enclose, so non-zero is inside).
std::vector<char> free_centres(const std::vector<Segment>& segments, FreeSpace& r) {
  std::vector<std::vector<Crossing>> rows(std::size_t(r.ny));
  for (const Segment& s : segments) {
    const double lo = std::min(s.a.y, s.b.y), hi = std::max(s.a.y, s.b.y);
    const int y0 = std::max(0, static_cast<int>(std::floor((lo - r.origin.y) / r.h)));
    const int y1 = std::min(r.ny - 1, static_cast<int>(std::ceil((hi - r.origin.y) / r.h)));
    for (int y = y0; y <= y1; ++y) {
      const double cy = r.origin.y + y * r.h;
      if ((s.a.y <= cy) == (s.b.y <= cy)) continue;
      const double x = s.a.x + (cy - s.a.y) * (s.b.x - s.a.x) / (s.b.y - s.a.y);
      const int step = s.b.y > s.a.y ? 1 : -1;
      rows[std::size_t(y)].push_back(s.owner < 0 ? Crossing{x, 0, step} : Crossing{x, step, 0});
    }
  }
  std::vector<char> free(std::size_t(r.nx) * std::size_t(r.ny), 0);
  r.inside = 0;
  for (int y = 0; y < r.ny; ++y) {
    std::vector<Crossing>& row = rows[std::size_t(y)];
    std::sort(row.begin(), row.end(), [](const Crossing& a, const Crossing& b) { return a.x < b.x; });
    int art = 0, wall = 0;
    std::size_t k = 0;
    for (int x = 0; x < r.nx; ++x) {
      const double cx = r.origin.x + x * r.h;
      for (; k < row.size() && row[k].x < cx; ++k) art += row[k].art, wall += row[k].wall;
      if (wall == 0) continue;
      ++r.inside;
      free[std::size_t(y) * std::size_t(r.nx) + std::size_t(x)] = art == 0;
    }
  }
  return free;
}

// The exact squared Euclidean distance transform along one line (Felzenszwalb and Huttenlocher, the lower
// envelope of parabolas): f[q] becomes the least f[p] + (q − p)². v and z are scratch.
void distance_transform(std::vector<double>& f, std::vector<int>& v, std::vector<double>& z, std::vector<double>& out) {
  const int n = int(f.size());
  v.resize(f.size()), z.resize(f.size() + 1), out.resize(f.size());
  auto meet = [&](int q, int p) { return ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * (q - p)); };
  int k = 0;
  v[0] = 0, z[0] = -infinity, z[1] = infinity;
  for (int q = 1; q < n; ++q) {
    double s = meet(q, v[k]);
    while (s <= z[k]) s = meet(q, v[--k]);
    v[++k] = q, z[k] = s, z[k + 1] = infinity;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    out[q] = double(q - v[k]) * double(q - v[k]) + f[v[k]];
  }
  f.swap(out);
}

FreeSpace free_space(const std::vector<Segment>& segments) {
  Box box;
  for (const Segment& s : segments)
    if (s.owner < 0) box.add(s.a), box.add(s.b);
  FreeSpace r;
  if (box.empty()) return r;
  r.h = std::max({box.width(), box.height(), 1e-9}) / raster_cells;
  r.origin = box.min - Vec2{r.h / 2, r.h / 2};
  r.nx = static_cast<int>(std::ceil(box.width() / r.h)) + 2;
  r.ny = static_cast<int>(std::ceil(box.height() / r.h)) + 2;
  const std::vector<char> free = free_centres(segments, r);
  // Farther than any two pixels apart, yet small enough that adding a squared pixel distance stays exact.
  constexpr double far = 1e12;
  std::vector<double> f(free.size()), line, out, z;
  std::vector<int> v;
  for (std::size_t i = 0; i < free.size(); ++i) f[i] = free[i] ? far : 0.0;
  const std::size_t nx = std::size_t(r.nx), ny = std::size_t(r.ny);
  for (std::size_t y = 0; y < ny; ++y) {
    line.assign(f.begin() + std::ptrdiff_t(y * nx), f.begin() + std::ptrdiff_t((y + 1) * nx));
    distance_transform(line, v, z, out);
    std::copy(line.begin(), line.end(), f.begin() + std::ptrdiff_t(y * nx));
  }
  line.resize(ny);
  for (std::size_t x = 0; x < nx; ++x) {
    for (std::size_t y = 0; y < ny; ++y) line[y] = f[y * nx + x];
    distance_transform(line, v, z, out);
    for (std::size_t y = 0; y < ny; ++y) f[y * nx + x] = line[y];
  }
  r.distance.resize(free.size());
  for (std::size_t i = 0; i < free.size(); ++i)
    r.distance[i] = free[i] ? std::max(0.0, std::sqrt(f[i]) * r.h - r.h / 2) : -1.0;
  return r;
}

// The largest distance of a free centre; −1 when none is free.
double farthest(const FreeSpace& r) {
  return r.distance.empty() ? -1.0 : *std::max_element(r.distance.begin(), r.distance.end());
}

// H(r) on the raster, for ascending radii: the share of the centres inside the container whose distance
// exceeds r. Each free centre is counted once, under the number of radii it exceeds.
std::vector<double> contact_shares(const FreeSpace& r, const std::vector<double>& radii) {
  std::vector<long> exceeding(radii.size() + 1, 0);
  for (double d : r.distance)
    if (d >= 0.0) ++exceeding[std::size_t(std::lower_bound(radii.begin(), radii.end(), d) - radii.begin())];
  std::vector<double> shares(radii.size(), 0.0);
  long farther = 0;  // centres farther than radii[k]
  for (std::size_t k = radii.size(); k-- > 0;) {
    farther += exceeding[k + 1];
    if (r.inside > 0) shares[k] = double(farther) / double(r.inside);
  }
  return shares;
}

// From a free point, a local maximum of the exact distance to the nearest boundary segment (art or wall)
// by pattern search in 8 directions, halving the step when none gains. A step stays under half the
// distance, inside the free disc around the point, so the point never leaves the free space; and the
// distance is 1-Lipschitz, so no point a step away is farther than d + step, which bounds each query.
double climb(SegmentGrid& grid, Vec2 p, double step) {
  static const std::array<Vec2, 8> directions = [] {
    std::array<Vec2, 8> d;
    for (std::size_t k = 0; k < d.size(); ++k)
      d[k] = {std::cos(double(k) * std::numbers::pi / 4), std::sin(double(k) * std::numbers::pi / 4)};
    return d;
  }();
  auto distance = [&](Vec2 q, double cap) { return grid.nearest(q, q, cap, [](int) { return true; }); };
  double d = distance(p, infinity);
  for (step = std::min(step, d / 2); step > climb_tolerance; step = std::min(step, d / 2)) {
    Vec2 best = p;
    double best_distance = d;
    for (Vec2 u : directions) {
      const double du = distance(p + u * step, d + step);
      if (du > best_distance) best = p + u * step, best_distance = du;
    }
    if (best_distance > d)
      p = best, d = best_distance;
    else
      step /= 2;
  }
  return d;
}

// The largest empty disc's radius: the climb from the raster's best local maxima (those within a pixel
// of its largest distance, at most disc_candidates of them), the best result.
double largest_empty_disc(const FreeSpace& r, SegmentGrid& grid) {
  const double best = farthest(r);
  if (best < 0.0) return 0.0;
  const std::size_t nx = std::size_t(r.nx);
  auto peak = [&](std::size_t i) {
    const std::size_t x = i % nx, y = i / nx;
    for (std::size_t yy = y - 1; yy <= y + 1; ++yy)
      for (std::size_t xx = x - 1; xx <= x + 1; ++xx)
        if (r.distance[yy * nx + xx] > r.distance[i]) return false;
    return true;
  };
  std::vector<std::pair<double, std::size_t>> peaks;
  // A free centre is never on the raster's edge, whose centres lie outside the container.
  for (std::size_t i = 0; i < r.distance.size(); ++i)
    if (r.distance[i] >= 0.0 && r.distance[i] >= best - r.h && peak(i)) peaks.push_back({r.distance[i], i});
  std::sort(peaks.begin(), peaks.end(), std::greater<>());
  peaks.resize(std::min(peaks.size(), std::size_t(disc_candidates)));
  double radius = 0.0;
  for (const auto& [d, i] : peaks) radius = std::max(radius, climb(grid, r.centre(i), r.h));
  return radius;
}

// The median art-to-wall gap of the elements within ρ of the wall over the median nearest art-to-art
// gap (docs/quality.md, "Evenness").
std::optional<double> wall_ratio(const std::vector<double>& nearest, const std::vector<Segment>& segments,
                                 const std::vector<std::size_t>& first, double rho, SegmentGrid& grid) {
  std::vector<double> wall, apart;
  for (std::size_t i = 0; i + 1 < first.size(); ++i) {
    if (!std::isfinite(nearest[i])) continue;  // no boundary
    apart.push_back(nearest[i]);
    double d = 2.0 * rho;
    for (std::size_t s = first[i]; s < first[i + 1] && d > 0.0; ++s)
      d = grid.nearest(segments[s].a, segments[s].b, d, [](int owner) { return owner < 0; });
    if (d <= rho) wall.push_back(d);
  }
  if (apart.size() < 2 || wall.empty()) return std::nullopt;
  const double gap = median(apart);
  if (!(gap > 0.0)) return std::nullopt;
  return median(wall) / gap;
}

// Element radius, wall ratio, largest empty disc and contact function (docs/quality.md, "Evenness").
void measure_evenness(FrameMetrics& m, const std::vector<double>& nearest, const std::vector<Segment>& segments,
                      const std::vector<std::size_t>& first, SegmentGrid& grid) {
  std::vector<double> radii;
  for (double a : m.area)
    if (a > 0.0) radii.push_back(std::sqrt(a / std::numbers::pi));
  if (!radii.empty()) m.element_radius = median(radii);
  if (m.element_radius > 0.0) m.wall_ratio = wall_ratio(nearest, segments, first, m.element_radius, grid);
  const FreeSpace space = free_space(segments);
  m.empty_disc_radius = largest_empty_disc(space, grid);
  if (!(m.element_radius > 0.0)) return;
  // Up to the first radius past every free centre's distance, where H is 0.
  const double step = contact_step * m.element_radius;
  const int count = std::min(contact_samples, static_cast<int>(std::floor(std::max(farthest(space), 0.0) / step)) + 2);
  std::vector<double> at(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) at[std::size_t(k)] = k * step;
  m.contact = contact_shares(space, at);
}

}  // namespace

FrameMetrics measure_regions(const std::vector<Region>& elements, const Region& container, Measures what) {
  const std::size_t n = elements.size();
  FrameMetrics m;
  std::vector<cl::Paths> art(n);
  std::vector<IntBox> boxes(n);
  cl::Paths all;
  m.area.resize(n);
  m.outside_share.resize(n);
  const cl::Paths inside_container = clean(container);
  for (std::size_t i = 0; i < n; ++i) {
    art[i] = clean(elements[i]);
    boxes[i] = bounds(art[i]);
    m.area[i] = area(art[i]);
    all.insert(all.end(), art[i].begin(), art[i].end());
    if (m.area[i] > 0.0) m.outside_share[i] = boolean_area(art[i], inside_container, cl::ctDifference) / m.area[i];
  }
  const double container_area = area(inside_container);
  if (container_area > 0.0) m.coverage = boolean_area(all, inside_container, cl::ctIntersection) / container_area;

  // Overlaps, and their art-to-art distance of 0.
  std::vector<double> nearest(n, infinity);
  std::vector<std::vector<int>> overlapping(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (!boxes[i].overlaps(boxes[j])) continue;
      const double shared = boolean_area(art[i], art[j], cl::ctIntersection);
      if (!(shared > 0.0)) continue;
      const double smaller = std::min(m.area[i], m.area[j]);
      m.overlaps.push_back({int(i), int(j), smaller > 0.0 ? shared / smaller : 0.0});
      nearest[i] = nearest[j] = 0.0;
      overlapping[i].push_back(int(j));
      overlapping[j].push_back(int(i));
    }

  std::vector<Segment> segments;
  std::vector<std::size_t> first(n + 1, 0);  // element i's segments are [first[i], first[i + 1])
  for (std::size_t i = 0; i < n; ++i) {
    add_segments(art[i], int(i), segments);
    first[i + 1] = segments.size();
  }
  add_segments(inside_container, -1, segments);
  SegmentGrid grid(segments);

  // Art-to-art distance: the smallest distance between a boundary segment of one and one of the other
  // (holes included, for art lying inside another's hole). Alone, an element has no gap.
  if (n >= 2) {
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t s = first[i]; s < first[i + 1] && nearest[i] > 0.0; ++s)
        nearest[i] = grid.nearest(segments[s].a, segments[s].b, nearest[i],
                                  [i](int owner) { return owner >= 0 && owner != int(i); });
    // Art that collapsed to nothing has no boundary and no distance; it is left out.
    double sum = 0.0, least = infinity;
    int measured = 0;
    for (double d : nearest)
      if (std::isfinite(d)) sum += d, least = std::min(least, d), ++measured;
    if (measured > 0) m.min_gap = least, m.mean_gap = sum / measured;
  }

  // Channel widths: from points along every element's outer rings to the nearest other art or the
  // container's boundary; 0 inside other art.
  double sum = 0.0, sum2 = 0.0;
  long count = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (const cl::Path& ring : art[i]) {
      if (!cl::Orientation(ring)) continue;  // a hole
      for (Vec2 p : samples_along(ring)) {
        double d = infinity;
        for (int j : overlapping[i])
          if (inside(art[j], p)) d = 0.0;
        d = grid.nearest(p, p, d, [i](int owner) { return owner != int(i); });
        if (!std::isfinite(d)) continue;  // nothing else at all
        sum += d, sum2 += d * d, ++count;
      }
    }
  if (count > 0 && sum > 0.0) {
    const double mean = sum / double(count);
    m.channel_cv = std::sqrt(std::max(0.0, sum2 / double(count) - mean * mean)) / mean;
  }
  if (what == Measures::all) measure_evenness(m, nearest, segments, first, grid);
  return m;
}

std::vector<double> contact_function(const std::vector<Region>& elements, const Region& container,
                                     const std::vector<double>& radii) {
  std::vector<Segment> segments;
  for (std::size_t i = 0; i < elements.size(); ++i) add_segments(clean(elements[i]), int(i), segments);
  add_segments(clean(container), -1, segments);
  return contact_shares(free_space(segments), radii);
}

}  // namespace animpak
