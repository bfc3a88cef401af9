// Closest point on a triangle in spacetime (x, y, t), for the exact repulsion terms of Eq. 1 (§5.1
// cites Ericson). Ericson's method (Real-Time Collision Detection §5.1.5): classify p against the
// Voronoi regions of the three vertices, then the three edges, from dot products only, and fall back
// to the face with barycentric coordinates. Every dot product sums x, then y, then t.
//
// Defined here, inline, because the repulsion loop calls it for every near triangle of every boundary
// vertex (docs/architecture.md, "The reference's speed").
#pragma once

#include "animpak/state.hpp"

namespace animpak::reference {

namespace closest_point_detail {

inline float dot3(float ax, float ay, float at, float bx, float by, float bt) { return ax * bx + ay * by + at * bt; }

inline Vec3f along(Vec3f o, float dx, float dy, float dt, float s) {
  return {o.x + dx * s, o.y + dy * s, o.t + dt * s};
}

}  // namespace closest_point_detail

/// Closest point to p on triangle abc in (x, y, t): Ericson, Real-Time Collision Detection §5.1.5.
inline Vec3f closest_point_on_triangle(Vec3f p, Vec3f a, Vec3f b, Vec3f c) {
  const float abx = b.x - a.x, aby = b.y - a.y, abt = b.t - a.t;
  const float acx = c.x - a.x, acy = c.y - a.y, act = c.t - a.t;

  // Vertex region of a.
  const float apx = p.x - a.x, apy = p.y - a.y, apt = p.t - a.t;
  const float d1 = closest_point_detail::dot3(abx, aby, abt, apx, apy, apt);
  const float d2 = closest_point_detail::dot3(acx, acy, act, apx, apy, apt);
  if (d1 <= 0.0f && d2 <= 0.0f) return a;

  // Vertex region of b.
  const float bpx = p.x - b.x, bpy = p.y - b.y, bpt = p.t - b.t;
  const float d3 = closest_point_detail::dot3(abx, aby, abt, bpx, bpy, bpt);
  const float d4 = closest_point_detail::dot3(acx, acy, act, bpx, bpy, bpt);
  if (d3 >= 0.0f && d4 <= d3) return b;

  // Edge region of ab.
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return closest_point_detail::along(a, abx, aby, abt, d1 / (d1 - d3));

  // Vertex region of c.
  const float cpx = p.x - c.x, cpy = p.y - c.y, cpt = p.t - c.t;
  const float d5 = closest_point_detail::dot3(abx, aby, abt, cpx, cpy, cpt);
  const float d6 = closest_point_detail::dot3(acx, acy, act, cpx, cpy, cpt);
  if (d6 >= 0.0f && d5 <= d6) return c;

  // Edge region of ac.
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return closest_point_detail::along(a, acx, acy, act, d2 / (d2 - d6));

  // Edge region of bc.
  const float va = d3 * d6 - d5 * d4;
  const float e43 = d4 - d3, e56 = d5 - d6;
  if (va <= 0.0f && e43 >= 0.0f && e56 >= 0.0f)
    return closest_point_detail::along(b, c.x - b.x, c.y - b.y, c.t - b.t, e43 / (e43 + e56));

  // Face region. A degenerate (zero-area) triangle that reaches here has no face; its vertex a is
  // as good an answer as any and keeps the result finite.
  const float sum = va + vb + vc;
  if (!(sum > 0.0f)) return a;
  const float denom = 1.0f / sum;
  const float v = vb * denom, w = vc * denom;
  return {a.x + abx * v + acx * w, a.y + aby * v + acy * w, a.t + abt * v + act * w};
}

}  // namespace animpak::reference
