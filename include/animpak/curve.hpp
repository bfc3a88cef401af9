// The curve every vertex follows between its slices (docs/parameters.md, "Motion between slices"). The
// paper joins slices by straight time edges and renders between them by linear interpolation (§6), so
// a vertex turns a corner at every slice: the speed jumps there, a frame sees it as a jolt. Here, by
// default, every vertex follows a monotone piecewise cubic in t through its positions at the slices
// (Steffen's tangents, "A simple method for monotonic interpolation in one dimension", 1990): C1, so no
// jolt at a slice; periodic across the loop seam; and, per coordinate, never outside the range of its two
// slice values on each interval, so an interpolated polygon still lies in the union of its two slices'
// boxes, the bound the overlap test's box test and broadphase rely on (docs/architecture.md, "The
// overlap test"). `motion_curve` 0 keeps the paper's straight lines.
//
// One function for every consumer of in-between time: the solver's overlap test (the reference here, in
// float; kernels/curve.cl is its twin), and the frames, the animated vector keys and the quality
// measures (src/render, in double). The operations are written out in one order, so the reference and the
// kernel agree bit for bit.
#pragma once

#include <cstdint>
#include <vector>

#include "animpak/state.hpp"

namespace animpak {

/// Where each global slice's vertices continue in time: the slice before and the slice after, vertex k
/// to vertex k, or -1 at an open end. Within an element, its neighbours; across a looping scene's seam
/// (t = 1 ≡ t = 0, §5.2's loop constraint), the last slice's next is the slice after its loop partner's
/// first, and the first slice's previous is the slice before the last of the element that loops into it.
struct CurveLinks {
  std::vector<std::int32_t> prev, next;
};

/// The links of every slice of `topo`, from its element ranges and loop pairs (loop_end, loop_start).
inline CurveLinks curve_links(const Topology& topo) {
  const std::int32_t slices = topo.slice_count();
  CurveLinks links;
  links.prev.assign(slices, -1);
  links.next.assign(slices, -1);
  for (std::int32_t e = 0; e < topo.element_count(); ++e)
    for (std::int32_t s = topo.element_slice_begin[e]; s + 1 < topo.element_slice_begin[e + 1]; ++s) {
      links.next[s] = s + 1;
      links.prev[s + 1] = s;
    }
  // Loop pairs join vertex k of a last slice to vertex k of a first slice (build_world pairs them in
  // order), so any pair names the two slices; the curve continues past the shared slice.
  for (std::size_t i = 0; i < topo.loop_end.size(); ++i) {
    const std::int32_t last = topo.slice[topo.loop_end[i]], first = topo.slice[topo.loop_start[i]];
    if (links.prev[last] < 0 || links.next[first] < 0) continue;  // an element of one slice
    links.next[last] = links.next[first];
    links.prev[first] = links.prev[last];
  }
  return links;
}

/// Slope of a chord over a time step h; a flat or reversed step (slices at one t) gives none.
template <typename T>
T curve_slope(T a, T b, T h) {
  return h > T(0) ? (b - a) / h : T(0);
}

/// Steffen's tangent at a slice from the chords' slopes on either side (sp over the step hp before, sn
/// over hn after): zero where the coordinate turns (the slopes differ in sign or one is zero), otherwise
/// the smaller of twice either slope and their step-weighted mean, with their sign; at an open end, the
/// one chord's slope. So on every interval both tangents lie between 0 and twice its chord's slope, and
/// the cubic is monotone there.
template <typename T>
T curve_tangent(T sp, T sn, T hp, T hn, bool has_prev, bool has_next) {
  if (!has_prev) return has_next ? sn : T(0);
  if (!has_next) return sp;
  if (!(sp * sn > T(0))) return T(0);
  const T mean = (sp * hn + sn * hp) / (hp + hn);
  const T asp = sp < T(0) ? -sp : sp, asn = sn < T(0) ? -sn : sn, amean = mean < T(0) ? -mean : mean;
  T m = asn < asp ? asn : asp;
  const T halved = T(0.5) * amean;
  m = halved < m ? halved : m;
  m = T(2) * m;
  return sp > T(0) ? m : -m;
}

/// The weights of a point at fraction u of an interval of length h: the value is
/// x0 + (x1 − x0)·c01 + m0·c10 + m1·c11 (cubic Hermite); the straight line has c01 = u and no tangents.
template <typename T>
struct CurveBasis {
  T c01, c10, c11;
};

template <typename T>
CurveBasis<T> curve_basis(T u, T h, bool cubic) {
  if (!cubic) return {u, T(0), T(0)};
  const T v = T(1) - u;
  return {u * u * (T(3) - T(2) * u), h * u * v * v, -(h * u * u * v)};
}

/// The curve's value between slice values x0 and x1 with tangents m0 and m1, kept within [x0, x1] (exactly
/// so in floating point; in exact arithmetic Steffen's tangents already keep it there).
template <typename T>
T curve_value(T x0, T x1, T m0, T m1, const CurveBasis<T>& b) {
  T x = x0 + (x1 - x0) * b.c01 + m0 * b.c10 + m1 * b.c11;
  const T lo = x1 < x0 ? x1 : x0, hi = x0 < x1 ? x1 : x0;
  x = x < lo ? lo : x;
  x = hi < x ? hi : x;
  return x;
}

/// The tangent (dx/dt, dy/dt) of vertex k of global slice s of `state`, in T: from the chords to the same
/// vertex of the slices before and after (`links`), the one before the first slice of an element one period
/// earlier and the one after its last one period later (the loop seam). In float these are the reference's
/// operations (curve_tangents; kernels/curve.cl is their twin); the frames take them in double.
template <typename T>
void curve_vertex_tangent(const Topology& topo, const CurveLinks& links, const SimState& state, std::int32_t s,
                          std::int32_t k, T& mx, T& my) {
  const std::int32_t p = links.prev[s], q = links.next[s], e = topo.slice_element[s];
  const T t0 = T(state.t[topo.slice_begin[s]]);
  T hp = T(0), hn = T(0), xp = T(0), yp = T(0), xn = T(0), yn = T(0);
  if (p >= 0) {
    const std::int32_t a = topo.slice_begin[p] + k;
    const T tp =
        s == topo.element_slice_begin[e] ? T(state.t[topo.slice_begin[p]]) - T(1) : T(state.t[topo.slice_begin[p]]);
    hp = t0 - tp, xp = T(state.x[a]), yp = T(state.y[a]);
  }
  if (q >= 0) {
    const std::int32_t b = topo.slice_begin[q] + k;
    const T tn = s + 1 == topo.element_slice_begin[e + 1] ? T(state.t[topo.slice_begin[q]]) + T(1)
                                                          : T(state.t[topo.slice_begin[q]]);
    hn = tn - t0, xn = T(state.x[b]), yn = T(state.y[b]);
  }
  const T x0 = T(state.x[topo.slice_begin[s] + k]), y0 = T(state.y[topo.slice_begin[s] + k]);
  mx = curve_tangent(curve_slope(xp, x0, hp), curve_slope(x0, xn, hn), hp, hn, p >= 0, q >= 0);
  my = curve_tangent(curve_slope(yp, y0, hp), curve_slope(y0, yn, hn), hp, hn, p >= 0, q >= 0);
}

/// The tangent (dx/dt, dy/dt) of every vertex's curve at its slice, from one snapshot of the state.
struct CurveTangents {
  std::vector<float> x, y;
  bool cubic = true;  ///< false: the paper's straight lines (the tangents are computed but weigh nothing)
};

}  // namespace animpak
