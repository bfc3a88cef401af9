/* Closest point on a spacetime triangle (Ericson, Real-Time Collision Detection §5.1.5), for the
 * exact terms of Eq. 1. The same Voronoi-region tests in the same order as
 * src/solver/reference/closest_point.cpp, every dot product summed x, then y, then t, so the chosen
 * region and the point are bit-identical. */

float ap_dot3(float ax, float ay, float at, float bx, float by, float bt) { return ax * bx + ay * by + at * bt; }

/** Closest point (*qx, *qy) to (px, py) on segment ab in x, y, clamped to the segment; returns the squared
 * distance (reference closest_point_on_segment). */
AP_INLINE float
closest_point_on_segment(float px, float py, float ax, float ay, float bx, float by, float* qx, float* qy) {
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
void closest_point_on_triangle(float px,
                               float py,
                               float pt,
                               float ax,
                               float ay,
                               float at,
                               float bx,
                               float by,
                               float bt,
                               float cx,
                               float cy,
                               float ct,
                               float* qx,
                               float* qy,
                               float* qt) {
  const float abx = bx - ax, aby = by - ay, abt = bt - at;
  const float acx = cx - ax, acy = cy - ay, act = ct - at;

  const float apx = px - ax, apy = py - ay, apt = pt - at;
  const float d1 = ap_dot3(abx, aby, abt, apx, apy, apt);
  const float d2 = ap_dot3(acx, acy, act, apx, apy, apt);
  if (d1 <= 0.0f && d2 <= 0.0f) {
    *qx = ax;
    *qy = ay;
    *qt = at;
    return;
  }

  const float bpx = px - bx, bpy = py - by, bpt = pt - bt;
  const float d3 = ap_dot3(abx, aby, abt, bpx, bpy, bpt);
  const float d4 = ap_dot3(acx, acy, act, bpx, bpy, bpt);
  if (d3 >= 0.0f && d4 <= d3) {
    *qx = bx;
    *qy = by;
    *qt = bt;
    return;
  }

  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) {
    const float s = d1 / (d1 - d3);
    *qx = ax + abx * s;
    *qy = ay + aby * s;
    *qt = at + abt * s;
    return;
  }

  const float cpx = px - cx, cpy = py - cy, cpt = pt - ct;
  const float d5 = ap_dot3(abx, aby, abt, cpx, cpy, cpt);
  const float d6 = ap_dot3(acx, acy, act, cpx, cpy, cpt);
  if (d6 >= 0.0f && d5 <= d6) {
    *qx = cx;
    *qy = cy;
    *qt = ct;
    return;
  }

  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) {
    const float s = d2 / (d2 - d6);
    *qx = ax + acx * s;
    *qy = ay + acy * s;
    *qt = at + act * s;
    return;
  }

  const float va = d3 * d6 - d5 * d4;
  const float e43 = d4 - d3, e56 = d5 - d6;
  if (va <= 0.0f && e43 >= 0.0f && e56 >= 0.0f) {
    const float s = e43 / (e43 + e56);
    *qx = bx + (cx - bx) * s;
    *qy = by + (cy - by) * s;
    *qt = bt + (ct - bt) * s;
    return;
  }

  /* A degenerate triangle reaching the face region answers a, as the reference does. */
  const float sum = va + vb + vc;
  if (!(sum > 0.0f)) {
    *qx = ax;
    *qy = ay;
    *qt = at;
    return;
  }
  const float denom = 1.0f / sum;
  const float v = vb * denom, w = vc * denom;
  *qx = ax + abx * v + acx * w;
  *qy = ay + aby * v + acy * w;
  *qt = at + abt * v + act * w;
}

/* The near block's triangles 16 at a time (repulsion_near_slots) when the host builds for a CPU
 * (-DAP_NEAR_LANES=16, program.cpp): every Voronoi region's answer is computed for all lanes, then the
 * first region that holds, in the order of the scalar function above, is selected per lane. Each lane
 * does the scalar function's float operations on the same operands, so its point is bit-identical; the
 * work is branch-free, so the CPU compiler puts the lanes in SIMD registers (docs/architecture.md, "The
 * near block in lanes"). */
#if defined(AP_NEAR_LANES) && AP_NEAR_LANES == 16
#define AP_LANES 16
typedef float16 ap_floatv;
typedef int16 ap_intv;
#define ap_vloadf(k, p) vload16((k), (p))
#define ap_vloadi(k, p) vload16((k), (p))
typedef uint16 ap_uintv;
/** Each lane's own number, 0 … AP_LANES − 1. */
ap_uintv ap_lane_index(void) { return (ap_uintv)(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15); }
ap_intv ap_lane_index_int(void) { return (ap_intv)(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15); }
#define AP_FOR_LANES(M) M(0) M(1) M(2) M(3) M(4) M(5) M(6) M(7) M(8) M(9) M(a) M(b) M(c) M(d) M(e) M(f)

/** How many lanes of a comparison's result are set (-1). */
int ap_lane_count(ap_intv m) {
  const int16 c = m & 1;
  const int8 c8 = c.lo + c.hi;
  const int4 c4 = c8.lo + c8.hi;
  const int2 c2 = c4.lo + c4.hi;
  return c2.x + c2.y;
}

/** closest_point_on_triangle for AP_LANES triangles at once. */
AP_INLINE void closest_point_on_triangles(float px,
                                          float py,
                                          float pt,
                                          ap_floatv ax,
                                          ap_floatv ay,
                                          ap_floatv at,
                                          ap_floatv bx,
                                          ap_floatv by,
                                          ap_floatv bt,
                                          ap_floatv cx,
                                          ap_floatv cy,
                                          ap_floatv ct,
                                          ap_floatv* qx,
                                          ap_floatv* qy,
                                          ap_floatv* qt) {
  const ap_floatv abx = bx - ax, aby = by - ay, abt = bt - at;
  const ap_floatv acx = cx - ax, acy = cy - ay, act = ct - at;
  const ap_floatv apx = px - ax, apy = py - ay, apt = pt - at;
  const ap_floatv d1 = abx * apx + aby * apy + abt * apt;
  const ap_floatv d2 = acx * apx + acy * apy + act * apt;
  const ap_floatv bpx = px - bx, bpy = py - by, bpt = pt - bt;
  const ap_floatv d3 = abx * bpx + aby * bpy + abt * bpt;
  const ap_floatv d4 = acx * bpx + acy * bpy + act * bpt;
  const ap_floatv vc = d1 * d4 - d3 * d2;
  const ap_floatv cpx = px - cx, cpy = py - cy, cpt = pt - ct;
  const ap_floatv d5 = abx * cpx + aby * cpy + abt * cpt;
  const ap_floatv d6 = acx * cpx + acy * cpy + act * cpt;
  const ap_floatv vb = d5 * d2 - d1 * d6;
  const ap_floatv va = d3 * d6 - d5 * d4;
  const ap_floatv e43 = d4 - d3, e56 = d5 - d6;
  /* From the last region back to the first, each overriding the lanes where it holds. */
  const ap_floatv sum = va + vb + vc;
  const ap_floatv denom = 1.0f / sum;
  const ap_floatv v = vb * denom, w = vc * denom;
  ap_floatv rx = ax + abx * v + acx * w, ry = ay + aby * v + acy * w, rt = at + abt * v + act * w;
  rx = select(rx, ax, !(sum > 0.0f)), ry = select(ry, ay, !(sum > 0.0f)), rt = select(rt, at, !(sum > 0.0f));
  /* The three edge regions share one division: each lane divides the numerator and denominator of the
   * first edge that holds for it (ab, then ac, then bc), from the point of the edge's start along its
   * direction, the scalar function's operands and operations, so its answer is the same bits. */
  const ap_intv m_ab = vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f;
  const ap_intv m_ac = vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f;
  const ap_intv m_bc = va <= 0.0f && e43 >= 0.0f && e56 >= 0.0f;
  ap_floatv num = select(select(e43, d2, m_ac), d1, m_ab);
  ap_floatv den = select(select(e43 + e56, d2 - d6, m_ac), d1 - d3, m_ab);
  const ap_floatv s_edge = num / den;
  const ap_intv from_a = m_ab | m_ac;
  const ap_floatv ox = select(bx, ax, from_a), oy = select(by, ay, from_a), ot = select(bt, at, from_a);
  const ap_floatv ex = select(select(cx - bx, acx, m_ac), abx, m_ab);
  const ap_floatv ey = select(select(cy - by, acy, m_ac), aby, m_ab);
  const ap_floatv et = select(select(ct - bt, act, m_ac), abt, m_ab);
  const ap_floatv edge_x = ox + ex * s_edge, edge_y = oy + ey * s_edge, edge_t = ot + et * s_edge;
  ap_intv m = m_ac | m_bc;
  rx = select(rx, edge_x, m), ry = select(ry, edge_y, m), rt = select(rt, edge_t, m);
  m = d6 >= 0.0f && d5 <= d6;
  rx = select(rx, cx, m), ry = select(ry, cy, m), rt = select(rt, ct, m);
  rx = select(rx, edge_x, m_ab), ry = select(ry, edge_y, m_ab), rt = select(rt, edge_t, m_ab);
  m = d3 >= 0.0f && d4 <= d3;
  rx = select(rx, bx, m), ry = select(ry, by, m), rt = select(rt, bt, m);
  m = d1 <= 0.0f && d2 <= 0.0f;
  *qx = select(rx, ax, m), *qy = select(ry, ay, m), *qt = select(rt, at, m);
}
#endif
