/* The curve every vertex follows between its slices, twin of include/animpak/curve.hpp and
 * src/solver/reference/curve.cpp (docs/parameters.md, "Motion between slices"): the C2 spline through the
 * slices, kept within each interval's four Bézier control points; the monotone cubic with Steffen's
 * tangents, kept within its two slice values per coordinate; or the paper's straight line. Every
 * operation in the reference's order. */

/** Slope of a chord over a time step h; none over a flat or reversed step (reference curve_slope). */
float curve_slope(float a, float b, float h) { return h > 0.0f ? (b - a) / h : 0.0f; }

/** Steffen's tangent from the slopes on either side (reference curve_tangent). */
float curve_tangent(float sp, float sn, float hp, float hn, bool has_prev, bool has_next) {
  if (!has_prev) return has_next ? sn : 0.0f;
  if (!has_next) return sp;
  if (!(sp * sn > 0.0f)) return 0.0f;
  const float mean = (sp * hn + sn * hp) / (hp + hn);
  const float asp = sp < 0.0f ? -sp : sp, asn = sn < 0.0f ? -sn : sn, amean = mean < 0.0f ? -mean : mean;
  float m = asn < asp ? asn : asp;
  const float halved = 0.5f * amean;
  m = halved < m ? halved : m;
  m = 2.0f * m;
  return sp > 0.0f ? m : -m;
}

/** The weights of the point at fraction u of an interval of length h (reference curve_basis):
 * x0 + (x1 - x0) c01 + m0 c10 + m1 c11, with h and whether the value may swing to the Bézier handles. */
typedef struct {
  float c01, c10, c11, h;
  bool spline;
} CurveBasis;

CurveBasis curve_basis(float u, float h, int mode) {
  CurveBasis b;
  b.h = h;
  b.spline = false;
  if (mode == AP_CURVE_LINEAR) {
    b.c01 = u, b.c10 = 0.0f, b.c11 = 0.0f;
    return b;
  }
  const float v = 1.0f - u;
  b.c01 = u * u * (3.0f - 2.0f * u);
  b.c10 = h * u * v * v;
  b.c11 = -(h * u * u * v);
  b.spline = mode == AP_CURVE_SPLINE;
  return b;
}

/** The Bézier handle of slice value x with tangent m over a step h (reference curve_handle). */
float curve_handle(float x, float m, float h) { return x + (h * m) / 3.0f; }

/** The curve's value between slice values x0 and x1: within [x0, x1], or on the spline within the
 * interval's four control points (reference curve_value), with those control points' handles given:
 * p = curve_handle(x0, m0, b.h), q = curve_handle(x1, m1, -b.h) (read only on the spline; slice_boxes
 * keeps them, overlap.cl). */
AP_INLINE float curve_value_handles(float x0, float x1, float m0, float m1, const CurveBasis b, float p, float q) {
  float x = x0 + (x1 - x0) * b.c01 + m0 * b.c10 + m1 * b.c11;
  float lo = x1 < x0 ? x1 : x0, hi = x0 < x1 ? x1 : x0;
  if (b.spline) {
    lo = p < lo ? p : lo;
    lo = q < lo ? q : lo;
    hi = hi < p ? p : hi;
    hi = hi < q ? q : hi;
  }
  x = x < lo ? lo : x;
  x = hi < x ? hi : x;
  return x;
}

#ifdef AP_LANES
/** curve_value_handles on AP_LANES lanes: the same operations on each lane, the clamp as selects; the handles
 * read from hp and hq (kept by slice_boxes, overlap.cl). */
AP_INLINE ap_floatv curve_value_lanes(const ap_floatv x0,
                                      const ap_floatv x1,
                                      const ap_floatv m0,
                                      const ap_floatv m1,
                                      const CurveBasis b,
                                      __global const float* hp,
                                      __global const float* hq) {
  ap_floatv v = x0 + (x1 - x0) * b.c01 + m0 * b.c10 + m1 * b.c11;
  ap_floatv lo = select(x0, x1, x1 < x0), hi = select(x0, x1, x0 < x1);
  if (b.spline) {
    const ap_floatv p = ap_vloadf(0, hp), q = ap_vloadf(0, hq);
    lo = select(lo, p, p < lo);
    lo = select(lo, q, q < lo);
    hi = select(hi, p, hi < p);
    hi = select(hi, q, hi < q);
  }
  v = select(v, lo, v < lo);
  v = select(v, hi, hi < v);
  return v;
}
#endif

/** Every vertex's tangent at its slice from one snapshot, one work-item per vertex (reference
 * curve_tangents). The slice before the first of an element, across the loop seam, lies one period
 * earlier; the slice after the last, one period later. */
__kernel void curve_tangents(const WorldInfo world,
                             __global const int* vertex_topology, /* input: slice per vertex */
                             __global const int* slice_topology,  /* input: slice_begin, slice_element, ... */
                             __global const int* curve_prev,      /* input: per slice, -1 at an open end */
                             __global const int* curve_next,      /* input: per slice, -1 at an open end */
                             __global const float* positions,     /* input: x, y, t per vertex */
                             __global float* curve_planes) {      /* output: tangent_x, tangent_y per vertex */
  __global const int* slice = vertex_topology + AP_TOPO_SLICE * world.vertex_stride;
  __global const int* slice_begin = slice_topology + AP_SLICES_BEGIN * world.slice_stride;
  __global const int* slice_element = slice_topology + AP_SLICES_ELEMENT * world.slice_stride;
  __global const int* element_slice_begin = slice_topology + AP_SLICES_ELEMENT_BEGIN * world.slice_stride;
  __global const float* x = positions + AP_X * world.vertex_stride;
  __global const float* y = positions + AP_Y * world.vertex_stride;
  __global const float* t = positions + AP_T * world.vertex_stride;
  __global float* tangent_x = curve_planes + AP_CURVE_TANGENT_X * world.vertex_stride;
  __global float* tangent_y = curve_planes + AP_CURVE_TANGENT_Y * world.vertex_stride;
  const int v = get_global_id(0);
  if (v >= world.vertices) return;
  const int s = slice[v], k = v - slice_begin[s];
  const int p = curve_prev[s], q = curve_next[s];
  const int e = slice_element[s];
  const float t0 = t[slice_begin[s]];
  float hp = 0.0f, hn = 0.0f, xp = 0.0f, yp = 0.0f, xn = 0.0f, yn = 0.0f;
  if (p >= 0) {
    const int a = slice_begin[p] + k;
    const float tp = s == element_slice_begin[e] ? t[slice_begin[p]] - 1.0f : t[slice_begin[p]];
    hp = t0 - tp, xp = x[a], yp = y[a];
  }
  if (q >= 0) {
    const int b = slice_begin[q] + k;
    const float tn = s + 1 == element_slice_begin[e + 1] ? t[slice_begin[q]] + 1.0f : t[slice_begin[q]];
    hn = tn - t0, xn = x[b], yn = y[b];
  }
  const float x0 = x[v], y0 = y[v];
  tangent_x[v] = curve_tangent(curve_slope(xp, x0, hp), curve_slope(x0, xn, hn), hp, hn, p >= 0, q >= 0);
  tangent_y[v] = curve_tangent(curve_slope(yp, y0, hp), curve_slope(y0, yn, hn), hp, hn, p >= 0, q >= 0);
}

/** Entry i's time on its chain: its slice's t plus the loops the chain has crossed (reference
 * spline_tangents' tau). */
float spline_tau(__global const int* slice_begin,
                 __global const int* chain_slice,
                 __global const float* chain_offset,
                 __global const float* t,
                 int b,
                 int i) {
  return t[slice_begin[chain_slice[b + i]]] + chain_offset[b + i];
}

/** Row i of a track's system (reference spline_row): a m[i-1] + rb m[i] + c m[i+1] = (dx, dy). */
void spline_row(int i,
                int n,
                float period,
                int b,
                int k,
                __global const int* slice_begin,
                __global const int* chain_slice,
                __global const float* chain_offset,
                __global const float* x,
                __global const float* y,
                __global const float* t,
                float* ra,
                float* rb,
                float* rc,
                float* rdx,
                float* rdy) {
  const bool closed = period > 0.0f;
  const bool has_prev = i > 0 || closed, has_next = i + 1 < n || closed;
  const int ip = i > 0 ? i - 1 : n - 1, in = i + 1 < n ? i + 1 : 0;
  const float ti = spline_tau(slice_begin, chain_slice, chain_offset, t, b, i);
  const float tp = spline_tau(slice_begin, chain_slice, chain_offset, t, b, ip);
  const float tn = spline_tau(slice_begin, chain_slice, chain_offset, t, b, in);
  const float hp = !has_prev ? 0.0f : (i > 0 ? ti - tp : ti + period - tp);
  const float hn = !has_next ? 0.0f : (i + 1 < n ? tn - ti : tn + period - ti);
  const int vi = slice_begin[chain_slice[b + i]] + k, vp = slice_begin[chain_slice[b + ip]] + k,
            vn = slice_begin[chain_slice[b + in]] + k;
  const float spx = has_prev ? curve_slope(x[vp], x[vi], hp) : 0.0f;
  const float snx = has_next ? curve_slope(x[vi], x[vn], hn) : 0.0f;
  const float spy = has_prev ? curve_slope(y[vp], y[vi], hp) : 0.0f;
  const float sny = has_next ? curve_slope(y[vi], y[vn], hn) : 0.0f;
  float a = 0.0f, bb = 1.0f, c = 0.0f, dx = 0.0f, dy = 0.0f;
  if (has_prev && has_next) {
    a = hn, bb = 2.0f * (hp + hn), c = hp, dx = 3.0f * (hn * spx + hp * snx), dy = 3.0f * (hn * spy + hp * sny);
  } else if (has_next) {
    a = 0.0f, bb = 2.0f, c = 1.0f, dx = 3.0f * snx, dy = 3.0f * sny;
  } else if (has_prev) {
    a = 1.0f, bb = 2.0f, c = 0.0f, dx = 3.0f * spx, dy = 3.0f * spy;
  }
  if (!(bb > 0.0f)) a = 0.0f, bb = 1.0f, c = 0.0f, dx = 0.0f, dy = 0.0f;
  *ra = a, *rb = bb, *rc = c, *rdx = dx, *rdy = dy;
}

/** The C2 spline's tangents, one work-item per track (vertex k of every slice on one chain; reference
 * curve_tangents with spline_tangents): Thomas' algorithm, and on a closed chain the Sherman–Morrison
 * correction for its corners. The eliminated right-hand sides live in the tangents themselves, the sweep's
 * ratios in cp and the correction's column in z (per vertex). A chain's entry with an alias (a looping
 * element's first slice) hands its tangents on. */
__kernel void curve_spline_tangents(const WorldInfo world,
                                    const int tracks,
                                    __global const int* track_vertex,   /* input: per track */
                                    __global const int* track_chain,    /* input: per track */
                                    __global const int* chain_begin,    /* input: chains + 1 */
                                    __global const int* chain_slice,    /* input: per entry */
                                    __global const float* chain_offset, /* input: per entry */
                                    __global const int* chain_alias,    /* input: per entry, -1 for none */
                                    __global const float* chain_period, /* input: per chain */
                                    __global const int* slice_topology, /* input: slice_begin */
                                    __global const float* positions,    /* input: x, y, t per vertex */
                                    __global float* cp,
                                    __global float* z,              /* scratch: per vertex */
                                    __global float* curve_planes) { /* output: tangent_x, tangent_y */
  __global const int* slice_begin = slice_topology + AP_SLICES_BEGIN * world.slice_stride;
  __global const float* x = positions + AP_X * world.vertex_stride;
  __global const float* y = positions + AP_Y * world.vertex_stride;
  __global const float* t = positions + AP_T * world.vertex_stride;
  __global float* tangent_x = curve_planes + AP_CURVE_TANGENT_X * world.vertex_stride;
  __global float* tangent_y = curve_planes + AP_CURVE_TANGENT_Y * world.vertex_stride;
  const int track = get_global_id(0);
  if (track >= tracks) return;
  const int c = track_chain[track], b = chain_begin[c], n = chain_begin[c + 1] - b;
  const int k = track_vertex[track] - slice_begin[chain_slice[b]];
  const float period = chain_period[c];
  if (n < 2) {
    for (int i = 0; i < n; ++i) {
      const int v = slice_begin[chain_slice[b + i]] + k;
      tangent_x[v] = 0.0f, tangent_y[v] = 0.0f;
      if (chain_alias[b + i] >= 0) {
        const int a = slice_begin[chain_alias[b + i]] + k;
        tangent_x[a] = 0.0f, tangent_y[a] = 0.0f;
      }
    }
    return;
  }
  const bool closed = period > 0.0f;
  float gamma = 0.0f, alpha = 0.0f, beta = 0.0f;
  float ra, rb, rc, rdx, rdy;
  if (closed) {
    spline_row(0, n, period, b, k, slice_begin, chain_slice, chain_offset, x, y, t, &ra, &rb, &rc, &rdx, &rdy);
    gamma = -rb, beta = ra;
    spline_row(n - 1, n, period, b, k, slice_begin, chain_slice, chain_offset, x, y, t, &ra, &rb, &rc, &rdx, &rdy);
    alpha = rc;
  }
  int prev = -1;
  for (int i = 0; i < n; ++i) {
    const int v = slice_begin[chain_slice[b + i]] + k;
    spline_row(i, n, period, b, k, slice_begin, chain_slice, chain_offset, x, y, t, &ra, &rb, &rc, &rdx, &rdy);
    float u = 0.0f;
    if (closed) {
      if (i == 0) rb = rb - gamma, ra = 0.0f, u = gamma;
      if (i == n - 1) rb = rb - alpha * beta / gamma, rc = 0.0f, u = alpha;
    }
    if (i == 0) {
      cp[v] = rc / rb;
      tangent_x[v] = rdx / rb, tangent_y[v] = rdy / rb, z[v] = u / rb;
    } else {
      const float den = rb - ra * cp[prev];
      cp[v] = rc / den;
      tangent_x[v] = (rdx - ra * tangent_x[prev]) / den, tangent_y[v] = (rdy - ra * tangent_y[prev]) / den;
      z[v] = (u - ra * z[prev]) / den;
    }
    prev = v;
  }
  for (int i = n - 2; i >= 0; --i) {
    const int v = slice_begin[chain_slice[b + i]] + k, w = slice_begin[chain_slice[b + i + 1]] + k;
    tangent_x[v] = tangent_x[v] - cp[v] * tangent_x[w], tangent_y[v] = tangent_y[v] - cp[v] * tangent_y[w];
    z[v] = z[v] - cp[v] * z[w];
  }
  if (closed) {
    const int v0 = slice_begin[chain_slice[b]] + k, vl = slice_begin[chain_slice[b + n - 1]] + k;
    const float den = 1.0f + z[v0] + beta * z[vl] / gamma;
    const float fx = (tangent_x[v0] + beta * tangent_x[vl] / gamma) / den;
    const float fy = (tangent_y[v0] + beta * tangent_y[vl] / gamma) / den;
    for (int i = 0; i < n; ++i) {
      const int v = slice_begin[chain_slice[b + i]] + k;
      tangent_x[v] = tangent_x[v] - fx * z[v], tangent_y[v] = tangent_y[v] - fy * z[v];
    }
  }
  for (int i = 0; i < n; ++i)
    if (chain_alias[b + i] >= 0) {
      const int v = slice_begin[chain_slice[b + i]] + k, a = slice_begin[chain_alias[b + i]] + k;
      tangent_x[a] = tangent_x[v], tangent_y[a] = tangent_y[v];
    }
}
