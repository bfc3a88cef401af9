// Small 2D value types shared by every stage. Units: art coordinates in src/io, the normalized
// container (unit square, y pointing down as in the art files and in images) everywhere after.
#pragma once

#include <cmath>
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

}  // namespace animpak
