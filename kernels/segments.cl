/* Segment tests shared by the container (boundary.cl) and the overlap test (overlap.cl), twins of
 * src/solver/reference/segments.cpp, and their lanes for the overlap test's walk. */

/** Half-open ray-crossing step of the even-odd test: whether the ray from (px, py) towards +x crosses
 * segment a → b. Half-open in y (one end above, one not), so a ray through a shared vertex counts once. */
AP_INLINE bool ray_crosses_segment(float px, float py, float ax, float ay, float bx, float by) {
  if ((ay > py) == (by > py)) return false;
  const float xi = (bx - ax) * (py - ay) / (by - ay) + ax;
  return px < xi;
}

/** Twice the signed area of triangle a, b, c: positive when c lies left of a → b. */
float segment_orient(float ax, float ay, float bx, float by, float cx, float cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

bool opposite_signs(float a, float b) { return (a > 0.0f && b < 0.0f) || (a < 0.0f && b > 0.0f); }

/** Proper crossing of segments p → n and a → b: each one's ends strictly on opposite sides of the other's
 * line (touching or collinear does not count). */
AP_INLINE bool segments_cross_properly(float px, float py, float nx, float ny, float ax, float ay, float bx, float by) {
  return opposite_signs(segment_orient(ax, ay, bx, by, px, py), segment_orient(ax, ay, bx, by, nx, ny)) &&
         opposite_signs(segment_orient(px, py, nx, ny, ax, ay), segment_orient(px, py, nx, ny, bx, by));
}

#ifdef AP_LANES
/* The same tests on AP_LANES edges at once, for the overlap test's walk on CPU devices (overlap.cl):
 * each lane does the scalar function's float operations. */

/** ray_crosses_segment of (px, py) on each lane's edge a → b. */
AP_INLINE ap_intv ray_crosses_segments(float px, float py, ap_floatv ax, ap_floatv ay, ap_floatv bx, ap_floatv by) {
  return ((ay > py) != (by > py)) && px < (bx - ax) * (py - ay) / (by - ay) + ax;
}

/** The walk's crossing test on each lane's edge a → b: the query edge p → n's box (ex0 … ey1) meets the
 * edge's (ap_max / ap_min as selects) and segments_cross_properly. */
AP_INLINE ap_intv edges_cross_properly(float px,
                                       float py,
                                       float nx,
                                       float ny,
                                       float ex0,
                                       float ex1,
                                       float ey0,
                                       float ey1,
                                       ap_floatv ax,
                                       ap_floatv ay,
                                       ap_floatv bx,
                                       ap_floatv by) {
  const ap_intv box = select(ax, bx, ax < bx) >= ex0 && select(ax, bx, bx < ax) <= ex1 &&
                      select(ay, by, ay < by) >= ey0 && select(ay, by, by < ay) <= ey1;
  const ap_floatv o1 = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
  const ap_floatv o2 = (bx - ax) * (ny - ay) - (by - ay) * (nx - ax);
  const ap_floatv o3 = (nx - px) * (ay - py) - (ny - py) * (ax - px);
  const ap_floatv o4 = (nx - px) * (by - py) - (ny - py) * (bx - px);
  const ap_intv cross =
      ((o1 > 0.0f && o2 < 0.0f) || (o1 < 0.0f && o2 > 0.0f)) && ((o3 > 0.0f && o4 < 0.0f) || (o3 < 0.0f && o4 > 0.0f));
  return box && cross;
}
#endif
