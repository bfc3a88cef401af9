// A flattened polyline refitted as cubic Bézier segments for the animated formats (fit_beziers):
// the same knots at every key of a path, so that a player's key-to-key interpolation of the vertices and
// control points stays within the tolerance too. docs/animation-formats.md, "Curves".
#include <algorithm>
#include <cmath>

#include "frame_writers.hpp"

namespace animpak::frame_writers {
namespace {

// A turn sharper than this at a point (the angle between the edges before and after it) makes the point a
// knot at every key: a corner of the art stays a corner.
constexpr double corner_cosine = 0.7071;  // 45 degrees
// Least-squares passes that move each point's curve parameter to where the curves come closest to it
// before a segment is given up (Newton steps on the squared distance, summed over the keys).
constexpr int reparameterisations = 3;

double bernstein(int i, double u) {
  const double v = 1 - u;
  switch (i) {
    case 0:
      return v * v * v;
    case 1:
      return 3 * v * v * u;
    case 2:
      return 3 * v * u * u;
    default:
      return u * u * u;
  }
}

Vec2 cubic_at(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3, double u) {
  return bernstein(0, u) * p0 + bernstein(1, u) * p1 + bernstein(2, u) * p2 + bernstein(3, u) * p3;
}

// The distance from p to the segment ab.
double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double length2 = dot(d, d);
  const double s = length2 > 0 ? std::clamp(dot(p - a, d) / length2, 0.0, 1.0) : 0.0;
  return norm(p - (a + d * s));
}

// One polyline at every key, walked from `start` (a knot) and, when closed, back round to it: point j of
// the walk is points[(start + j) mod n].
struct Walk {
  const std::vector<std::vector<Vec2>>& keys;
  std::size_t start, n, length;  // length: n, or n + 1 when closed (the start again at the end)
  Vec2 at(std::size_t key, std::size_t j) const { return keys[key][(start + j) % n]; }
};

// The controls of one segment at every key: c1[k], c2[k] between the walk's points a and b.
struct SegmentFit {
  std::vector<Vec2> c1, c2;
  bool straight = false;
};

// Whether the straight side from a to b (both tangents zero) passes within `tolerance` of every point
// between, at every key.
bool straight_fits(const Walk& walk, std::size_t a, std::size_t b, double tolerance) {
  for (std::size_t k = 0; k < walk.keys.size(); ++k)
    for (std::size_t j = a + 1; j < b; ++j)
      if (distance_to_segment(walk.at(k, j), walk.at(k, a), walk.at(k, b)) > tolerance) return false;
  return true;
}

// The farthest point of the walk between a and b, or the middle of an edge between two of them, from the
// curve at its parameter (u[j − a]; an edge's middle at the middle of its ends' parameters), at key k.
double parametric_error(const Walk& walk, std::size_t k, std::size_t a, std::size_t b, Vec2 c1, Vec2 c2,
                        const std::vector<double>& u) {
  const Vec2 p0 = walk.at(k, a), p3 = walk.at(k, b);
  double worst = 0.0;
  for (std::size_t j = a; j < b; ++j) {
    const double ua = u[j - a], ub = u[j + 1 - a];
    if (j > a) worst = std::max(worst, norm(cubic_at(p0, c1, c2, p3, ua) - walk.at(k, j)));
    const Vec2 middle = 0.5 * (walk.at(k, j) + walk.at(k, j + 1));
    worst = std::max(worst, norm(cubic_at(p0, c1, c2, p3, 0.5 * (ua + ub)) - middle));
  }
  return worst;
}

// The two inner control points of the cubic from the walk's point a to point b at key k that come closest to
// the points between by least squares, each point j at parameter u[j − a]; false when the points do not
// determine them.
bool least_squares_controls(const Walk& walk, std::size_t k, std::size_t a, std::size_t b, const std::vector<double>& u,
                            Vec2& c1, Vec2& c2) {
  const Vec2 p0 = walk.at(k, a), p3 = walk.at(k, b);
  double m11 = 0, m12 = 0, m22 = 0;
  Vec2 r1{0, 0}, r2{0, 0};
  for (std::size_t j = a + 1; j < b; ++j) {
    const double t = u[j - a], b1 = bernstein(1, t), b2 = bernstein(2, t);
    const Vec2 r = walk.at(k, j) - bernstein(0, t) * p0 - bernstein(3, t) * p3;
    m11 += b1 * b1, m12 += b1 * b2, m22 += b2 * b2;
    r1 = r1 + b1 * r, r2 = r2 + b2 * r;
  }
  const double det = m11 * m22 - m12 * m12;
  if (!(std::abs(det) > 1e-12 * std::max(1e-300, m11 * m22))) return false;
  c1 = (m22 * r1 - m12 * r2) * (1.0 / det);
  c2 = (m11 * r2 - m12 * r1) * (1.0 / det);
  return true;
}

// A cubic from the walk's point a to point b at every key within `tolerance` of the points between, their
// parameters the same at every key (so that a player's interpolation between two keys, which moves the
// vertices and control points straight, moves each curve point with its polyline point): chord-length
// parameters averaged over the keys, then moved towards where the keys' curves come closest
// (reparameterisations). False when no such cubic was found; a straight side is tried first.
bool segment_fit(const Walk& walk, std::size_t a, std::size_t b, double tolerance, SegmentFit& fit) {
  const std::size_t keys = walk.keys.size();
  fit.c1.assign(keys, Vec2{}), fit.c2.assign(keys, Vec2{});
  if (straight_fits(walk, a, b, tolerance)) {
    for (std::size_t k = 0; k < keys; ++k) fit.c1[k] = walk.at(k, a), fit.c2[k] = walk.at(k, b);
    fit.straight = true;
    return true;
  }
  fit.straight = false;
  if (b < a + 3) return false;  // one point between: a straight side or a knot
  std::vector<double> u(b - a + 1, 0.0), along(b - a + 1);
  for (std::size_t k = 0; k < keys; ++k) {
    along[0] = 0.0;
    for (std::size_t j = a + 1; j <= b; ++j) along[j - a] = along[j - a - 1] + norm(walk.at(k, j) - walk.at(k, j - 1));
    if (along.back() <= 0.0) return false;
    for (std::size_t j = a; j <= b; ++j) u[j - a] += along[j - a] / along.back() / double(keys);
  }
  u.front() = 0.0, u.back() = 1.0;
  for (int pass = 0;; ++pass) {
    double worst = 0.0;
    for (std::size_t k = 0; k < keys && worst <= tolerance; ++k) {
      if (!least_squares_controls(walk, k, a, b, u, fit.c1[k], fit.c2[k])) return false;
      worst = std::max(worst, parametric_error(walk, k, a, b, fit.c1[k], fit.c2[k], u));
    }
    if (worst <= tolerance) return true;
    if (pass == reparameterisations) return false;
    // One Newton step per point on the sum over the keys of its squared distance from the curve.
    for (std::size_t j = a + 1; j < b; ++j) {
      double slope = 0.0, curvature = 0.0;
      const double t = u[j - a];
      for (std::size_t k = 0; k < keys; ++k) {
        const Vec2 p0 = walk.at(k, a), p1 = fit.c1[k], p2 = fit.c2[k], p3 = walk.at(k, b);
        const Vec2 d = cubic_at(p0, p1, p2, p3, t) - walk.at(k, j);
        const Vec2 d1 = 3 * (1 - t) * (1 - t) * (p1 - p0) + 6 * (1 - t) * t * (p2 - p1) + 3 * t * t * (p3 - p2);
        const Vec2 d2 = 6 * (1 - t) * (p2 - 2 * p1 + p0) + 6 * t * (p3 - 2 * p2 + p1);
        slope += dot(d, d1), curvature += dot(d1, d1) + dot(d, d2);
      }
      if (curvature > 0) u[j - a] = std::clamp(t - slope / curvature, 0.0, 1.0);
    }
    for (std::size_t j = a + 1; j <= b; ++j) u[j - a] = std::max(u[j - a], u[j - a - 1]);
  }
}

// Whether the walk turns by more than 45 degrees at its point j (cyclically when closed), at any key; edges
// of no length are passed over.
bool is_corner(const std::vector<std::vector<Vec2>>& keys, std::size_t j, bool closed) {
  const std::size_t n = keys[0].size();
  for (const auto& points : keys) {
    const auto step = [&](std::size_t i, bool forward) -> std::size_t {
      if (forward) return closed ? (i + 1) % n : i + 1;
      return closed ? (i + n - 1) % n : i - 1;
    };
    Vec2 before{0, 0}, after{0, 0};
    for (std::size_t i = j, walked = 0; walked + 1 < n && (closed || i > 0); ++walked) {
      i = step(i, false);
      before = points[j] - points[i];
      if (norm(before) > 0) break;
    }
    for (std::size_t i = j, walked = 0; walked + 1 < n && (closed || i + 1 < n); ++walked) {
      i = step(i, true);
      after = points[i] - points[j];
      if (norm(after) > 0) break;
    }
    const double lengths = norm(before) * norm(after);
    if (lengths > 0 && dot(before, after) < corner_cosine * lengths) return true;
  }
  return false;
}

}  // namespace

std::vector<BezierLine> fit_beziers(const std::vector<std::vector<Vec2>>& keys, bool closed, double tolerance) {
  std::vector<BezierLine> lines(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k) lines[k] = {keys[k], keys[k], keys[k], closed};
  if (keys.empty() || keys[0].size() < 3 || !(tolerance > 0)) return lines;
  const std::size_t n = keys[0].size();
  std::vector<char> corner(n, 0);
  for (std::size_t j = 0; j < n; ++j) corner[j] = closed || (j > 0 && j + 1 < n) ? is_corner(keys, j, closed) : 1;
  // A closed walk starts at a corner; without one, at point 0 and with a knot half way round, so that no
  // single segment closes on itself.
  std::size_t start = 0;
  if (closed) {
    while (start < n && !corner[start]) ++start;
    if (start == n) start = 0, corner[0] = corner[n / 2] = 1;
  }
  const Walk walk{keys, start, n, closed ? n + 1 : n};
  const auto knot = [&](std::size_t j) { return j == 0 || j + 1 == walk.length || corner[(start + j) % n]; };
  // From each knot, the farthest point that one segment reaches within the tolerance, never past the next
  // corner: found by doubling the reach (from 3 points on: a curved segment needs two points between its
  // ends), then halving the gap between the last that fits and the first that does not.
  std::vector<std::size_t> knots{0};
  std::vector<SegmentFit> segments;
  for (std::size_t a = 0; a + 1 < walk.length;) {
    std::size_t end = a + 1;
    while (end + 1 < walk.length && !knot(end)) ++end;
    std::size_t good = a + 1, bad = end + 1;
    SegmentFit good_fit, fit;
    segment_fit(walk, a, a + 1, tolerance, good_fit);
    for (std::size_t reach = 3; good < end; reach *= 2) {
      const std::size_t b = std::min(a + reach, end);
      if (!segment_fit(walk, a, b, tolerance, fit)) {
        bad = b;
        break;
      }
      good = b, good_fit = fit;
    }
    while (bad <= end && bad - good > 1) {
      const std::size_t mid = good + (bad - good) / 2;
      if (segment_fit(walk, a, mid, tolerance, fit))
        good = mid, good_fit = fit;
      else
        bad = mid;
    }
    knots.push_back(good), segments.push_back(good_fit);
    a = good;
  }
  const std::size_t vertices = closed ? knots.size() - 1 : knots.size();
  for (std::size_t k = 0; k < keys.size(); ++k) {
    BezierLine& line = lines[k];
    line.points.resize(vertices);
    for (std::size_t v = 0; v < vertices; ++v) line.points[v] = walk.at(k, knots[v]);
    line.before = line.after = line.points;
    for (std::size_t s = 0; s < segments.size(); ++s) {
      line.after[s] = segments[s].c1[k];
      line.before[(s + 1) % vertices] = segments[s].c2[k];
    }
  }
  return lines;
}

}  // namespace animpak::frame_writers
