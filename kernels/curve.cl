/* The curve every vertex follows between its slices, twin of include/animpak/curve.hpp and
 * src/solver/reference/curve.cpp (docs/parameters.md, "Motion between slices"): a monotone cubic
 * through the slices with Steffen's tangents, kept within its two slice values per coordinate, or the
 * paper's straight line. Every operation in the reference's order. */

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
 * x0 + (x1 - x0) c01 + m0 c10 + m1 c11. */
typedef struct {
  float c01, c10, c11;
} CurveBasis;

CurveBasis curve_basis(float u, float h, bool cubic) {
  CurveBasis b;
  if (!cubic) {
    b.c01 = u, b.c10 = 0.0f, b.c11 = 0.0f;
    return b;
  }
  const float v = 1.0f - u;
  b.c01 = u * u * (3.0f - 2.0f * u);
  b.c10 = h * u * v * v;
  b.c11 = -(h * u * u * v);
  return b;
}

/** The curve's value between slice values x0 and x1, within [x0, x1] (reference curve_value). */
float curve_value(float x0, float x1, float m0, float m1, const CurveBasis b) {
  float x = x0 + (x1 - x0) * b.c01 + m0 * b.c10 + m1 * b.c11;
  const float lo = x1 < x0 ? x1 : x0, hi = x0 < x1 ? x1 : x0;
  x = x < lo ? lo : x;
  x = hi < x ? hi : x;
  return x;
}

/** Every vertex's tangent at its slice from one snapshot, one work-item per vertex (reference
 * curve_tangents). The slice before the first of an element, across the loop seam, lies one period
 * earlier; the slice after the last, one period later. */
__kernel void curve_tangents(const WorldInfo world,
                             __global const int* slice,               /* input: per vertex */
                             __global const int* slice_begin,         /* input: slices + 1 */
                             __global const int* slice_element,       /* input: per slice */
                             __global const int* element_slice_begin, /* input: elements + 1 */
                             __global const int* curve_prev,          /* input: per slice, -1 at an open end */
                             __global const int* curve_next,          /* input: per slice, -1 at an open end */
                             __global const float* x,
                             __global const float* y,
                             __global const float* t,     /* input: positions */
                             __global float* tangent_x,   /* output: per vertex */
                             __global float* tangent_y) { /* output: per vertex */
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
