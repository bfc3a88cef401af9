// The reference's segment tests in the plane, shared by the container (Eq. 4 and containment, boundary.hpp)
// and the overlap test (Eq. 3, overlap.hpp): src/solver/reference/closest_point.cpp and segments.cpp;
// kernels/segments.cl and closest_point.cl are their twins. The closest point on a triangle, for Eq. 1, is
// closest_point_on_triangle in include/animpak/closest_point.hpp (inline).
#pragma once

namespace animpak::reference {

/// Closest point (*qx, *qy) to (px, py) on segment ab in x, y: the projection onto the line, clamped to
/// the segment (a for a zero-length one); returns the squared distance. The container's wall and the
/// overlap test's way out both use it. closest_point.cpp.
float closest_point_on_segment(float px, float py, float ax, float ay, float bx, float by, float& qx, float& qy);

/// One step of the even–odd (ray crossing) point-in-polygon test: whether the ray from (px, py)
/// towards +x crosses segment (ax, ay)–(bx, by). Toggle "inside" on every true. segments.cpp.
bool ray_crosses_segment(float px, float py, float ax, float ay, float bx, float by);

/// Whether segments p → n and a → b cross properly: each one's ends strictly on opposite sides of the
/// other's line (touching or collinear does not count). segments.cpp.
bool segments_cross_properly(float px, float py, float nx, float ny, float ax, float ay, float bx, float by);

}  // namespace animpak::reference
