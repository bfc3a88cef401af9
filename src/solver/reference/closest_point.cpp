// Closest point on a segment in the plane, for the container's wall and the overlap test's way out.
// (The closest point on a triangle, for Eq. 1, is inline in animpak/closest_point.hpp.)
#include "animpak/reference/segments.hpp"

namespace animpak::reference {

float closest_point_on_segment(float px, float py, float ax, float ay, float bx, float by, float& qx, float& qy) {
  const float dx = bx - ax, dy = by - ay;
  const float len2 = dx * dx + dy * dy;
  float s = 0.0f;
  if (len2 > 0.0f) s = ((px - ax) * dx + (py - ay) * dy) / len2;
  if (s < 0.0f) s = 0.0f;
  if (s > 1.0f) s = 1.0f;
  qx = ax + dx * s;
  qy = ay + dy * s;
  const float ex = px - qx, ey = py - qy;
  return ex * ex + ey * ey;
}

}  // namespace animpak::reference
