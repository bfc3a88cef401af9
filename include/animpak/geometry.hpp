// Small 2D value types shared by every stage. Units: art coordinates in src/io, the normalized
// container (unit square, y pointing down as in the art files and in images) everywhere after.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace animpak {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;
};

inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
inline Vec2 operator*(Vec2 a, double s) { return {s * a.x, s * a.y}; }
inline bool operator==(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline double norm(Vec2 a) { return std::hypot(a.x, a.y); }

/// Axis-aligned box; empty() until a point is added.
struct Box {
  Vec2 min{1e300, 1e300};
  Vec2 max{-1e300, -1e300};
  bool empty() const { return min.x > max.x; }
  void add(Vec2 p) {
    min = {std::fmin(min.x, p.x), std::fmin(min.y, p.y)};
    max = {std::fmax(max.x, p.x), std::fmax(max.y, p.y)};
  }
  double width() const { return max.x - min.x; }
  double height() const { return max.y - min.y; }
};

/// Signed area of a closed polygon (positive when counter-clockwise in a y-up frame).
inline double signed_area(const std::vector<Vec2>& ring) {
  double a = 0.0;
  for (size_t i = 0, n = ring.size(); i < n; ++i) a += cross(ring[i], ring[(i + 1) % n]);
  return 0.5 * a;
}

/// Index of the first of `points` nearest to p (0 for an empty list).
inline int nearest_index(const std::vector<Vec2>& points, Vec2 p) {
  int best = 0;
  for (int i = 1; i < static_cast<int>(points.size()); ++i)
    if (norm(points[i] - p) < norm(points[best] - p)) best = i;
  return best;
}

/// Length of a closed polygon's edges, summed from the first edge to the closing one.
inline double perimeter(const std::vector<Vec2>& ring) {
  double length = 0.0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) length += norm(ring[(i + 1) % n] - ring[i]);
  return length;
}

/// Even–odd (ray crossing) test; a vertex on the ray counts once by the half-open rule.
inline bool ring_contains(const std::vector<Vec2>& ring, Vec2 p) {
  bool inside = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    if ((ring[i].y > p.y) != (ring[j].y > p.y) &&
        p.x < (ring[j].x - ring[i].x) * (p.y - ring[i].y) / (ring[j].y - ring[i].y) + ring[i].x)
      inside = !inside;
  return inside;
}

/// The point of segment ab nearest to p.
inline Vec2 closest_on_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  const double s = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return a + s * ab;
}

inline double segment_distance(Vec2 p, Vec2 a, Vec2 b) { return norm(p - closest_on_segment(p, a, b)); }

/// Distance from p to the closed polygon's edges.
inline double ring_distance(const std::vector<Vec2>& ring, Vec2 p) {
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < ring.size(); ++i)
    d = std::min(d, segment_distance(p, ring[i], ring[(i + 1) % ring.size()]));
  return d;
}

/// Whether segments ab and cd cross at a point interior to both.
inline bool segments_cross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

/// Whether two closed polygons share interior points (one inside the other, or crossing edges).
inline bool rings_overlap(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  if (a.empty() || b.empty()) return false;
  if (ring_contains(b, a[0]) || ring_contains(a, b[0])) return true;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j)
      if (segments_cross(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()])) return true;
  return false;
}

/// Distance between two closed polygons' boundaries; 0 when they overlap.
inline double ring_gap(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  if (rings_overlap(a, b)) return 0.0;
  double d = std::numeric_limits<double>::infinity();
  for (Vec2 p : a) d = std::min(d, ring_distance(b, p));
  for (Vec2 p : b) d = std::min(d, ring_distance(a, p));
  return d;
}

}  // namespace animpak
