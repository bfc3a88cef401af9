// Segment tests shared by the container (boundary.cpp) and the overlap test (overlap.cpp); their kernel
// twins are in kernels/segments.cl.
#include "animpak/reference/segments.hpp"

namespace animpak::reference {
namespace {

/// Twice the signed area of triangle a, b, c: positive when c lies left of a → b.
float segment_orient(float ax, float ay, float bx, float by, float cx, float cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

bool opposite_signs(float a, float b) { return (a > 0.0f && b < 0.0f) || (a < 0.0f && b > 0.0f); }

}  // namespace

bool ray_crosses_segment(float px, float py, float ax, float ay, float bx, float by) {
  // Half-open in y (one end above, one not) so a ray through a shared vertex counts once.
  if ((ay > py) == (by > py)) return false;
  const float xi = (bx - ax) * (py - ay) / (by - ay) + ax;
  return px < xi;
}

bool segments_cross_properly(float px, float py, float nx, float ny, float ax, float ay, float bx, float by) {
  return opposite_signs(segment_orient(ax, ay, bx, by, px, py), segment_orient(ax, ay, bx, by, nx, ny)) &&
         opposite_signs(segment_orient(px, py, nx, ny, ax, ay), segment_orient(px, py, nx, ny, bx, by));
}

}  // namespace animpak::reference
