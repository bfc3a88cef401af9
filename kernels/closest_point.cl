/* Closest point on a spacetime triangle (Ericson, Real-Time Collision Detection §5.1.5), for the
 * exact terms of Eq. 1. The same Voronoi-region tests in the same order as
 * src/solver/reference/closest_point.cpp, every dot product summed x, then y, then t, so the chosen
 * region and the point are bit-identical. */

float ap_dot3(float ax, float ay, float at, float bx, float by, float bt) { return ax * bx + ay * by + at * bt; }

/** Closest point (*qx, *qy) to (px, py) on segment ab in x, y, clamped to the segment; returns the squared
 * distance (reference closest_point_on_segment). */
float closest_point_on_segment(float px, float py, float ax, float ay, float bx, float by, float* qx, float* qy) {
  const float dx = bx - ax, dy = by - ay;
  const float len2 = dx * dx + dy * dy;
  float s = 0.0f;
  if (len2 > 0.0f) s = ((px - ax) * dx + (py - ay) * dy) / len2;
  if (s < 0.0f) s = 0.0f;
  if (s > 1.0f) s = 1.0f;
  *qx = ax + dx * s;
  *qy = ay + dy * s;
  const float ex = px - *qx, ey = py - *qy;
  return ex * ex + ey * ey;
}

/** Writes the closest point to p on triangle abc into (*qx, *qy, *qt). */
void closest_point_on_triangle(float px, float py, float pt, float ax, float ay, float at, float bx, float by,
                               float bt, float cx, float cy, float ct, float* qx, float* qy, float* qt) {
  const float abx = bx - ax, aby = by - ay, abt = bt - at;
  const float acx = cx - ax, acy = cy - ay, act = ct - at;

  const float apx = px - ax, apy = py - ay, apt = pt - at;
  const float d1 = ap_dot3(abx, aby, abt, apx, apy, apt);
  const float d2 = ap_dot3(acx, acy, act, apx, apy, apt);
  if (d1 <= 0.0f && d2 <= 0.0f) { *qx = ax; *qy = ay; *qt = at; return; }

  const float bpx = px - bx, bpy = py - by, bpt = pt - bt;
  const float d3 = ap_dot3(abx, aby, abt, bpx, bpy, bpt);
  const float d4 = ap_dot3(acx, acy, act, bpx, bpy, bpt);
  if (d3 >= 0.0f && d4 <= d3) { *qx = bx; *qy = by; *qt = bt; return; }

  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) {
    const float s = d1 / (d1 - d3);
    *qx = ax + abx * s; *qy = ay + aby * s; *qt = at + abt * s;
    return;
  }

  const float cpx = px - cx, cpy = py - cy, cpt = pt - ct;
  const float d5 = ap_dot3(abx, aby, abt, cpx, cpy, cpt);
  const float d6 = ap_dot3(acx, acy, act, cpx, cpy, cpt);
  if (d6 >= 0.0f && d5 <= d6) { *qx = cx; *qy = cy; *qt = ct; return; }

  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) {
    const float s = d2 / (d2 - d6);
    *qx = ax + acx * s; *qy = ay + acy * s; *qt = at + act * s;
    return;
  }

  const float va = d3 * d6 - d5 * d4;
  const float e43 = d4 - d3, e56 = d5 - d6;
  if (va <= 0.0f && e43 >= 0.0f && e56 >= 0.0f) {
    const float s = e43 / (e43 + e56);
    *qx = bx + (cx - bx) * s; *qy = by + (cy - by) * s; *qt = bt + (ct - bt) * s;
    return;
  }

  /* A degenerate triangle reaching the face region answers a, as the reference does. */
  const float sum = va + vb + vc;
  if (!(sum > 0.0f)) { *qx = ax; *qy = ay; *qt = at; return; }
  const float denom = 1.0f / sum;
  const float v = vb * denom, w = vc * denom;
  *qx = ax + abx * v + acx * w;
  *qy = ay + aby * v + acy * w;
  *qt = at + abt * v + act * w;
}
