/* Boundary force, paper Eq. 4 (src/solver/reference/boundary.cpp): k_bdr (p_b − x) in x, y for a
 * vertex outside the container (even-odd over every ring, so inside a hole is outside). */

/** Eq. 4 on (px, py); zero inside the container or without one. */
void boundary_force(const ForceParams p, int segments, float px, float py, __global const float* ax,
                    __global const float* ay, __global const float* bx, __global const float* by, float* fx,
                    float* fy) {
  bool inside = false;
  for (int i = 0; i < segments; ++i)
    if (ray_crosses_segment(px, py, ax[i], ay[i], bx[i], by[i])) inside = !inside;
  if (inside || segments == 0) return;

  /* Closest point over all segments; the first segment reaching the minimum wins. */
  float best2 = INFINITY;
  float qx = px, qy = py;
  for (int i = 0; i < segments; ++i) {
    const float dx = bx[i] - ax[i], dy = by[i] - ay[i];
    const float len2 = dx * dx + dy * dy;
    float s = 0.0f;
    if (len2 > 0.0f) s = ((px - ax[i]) * dx + (py - ay[i]) * dy) / len2;
    if (s < 0.0f) s = 0.0f;
    if (s > 1.0f) s = 1.0f;
    const float cx = ax[i] + dx * s, cy = ay[i] + dy * s;
    const float ex = px - cx, ey = py - cy;
    const float d2 = ex * ex + ey * ey;
    if (d2 < best2) {
      best2 = d2;
      qx = cx;
      qy = cy;
    }
  }
  const float k = p.k_boundary;
  *fx = k * (qx - px);
  *fy = k * (qy - py);
}
