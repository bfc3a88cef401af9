// The curve every vertex follows between its slices (docs/parameters.md, "Motion between slices"). The
// paper joins slices by straight time edges and renders between them by linear interpolation (§6), so
// a vertex turns a corner at every slice: the speed jumps there, a frame sees it as a jolt. Here, by
// default (`motion_curve` 2), every vertex follows the C2 interpolating cubic spline in t through its
// positions at the slices: no jump of speed or of acceleration at a slice, periodic across the loop seam.
// A spline swings past its slice values between them, so an interpolated polygon lies in the union of
// its two slices' boxes only once each box holds its vertices' Bézier handles as well (the control points
// x ± h·m/3 of the intervals on either side); slice_boxes widens them so, and curve_value keeps a point
// within its interval's four control points, so the overlap test's box test and broadphase keep their
// bound (docs/architecture.md, "The overlap test"). `motion_curve` 1 is 0.4.0–0.7.0's monotone cubic
// (Steffen's tangents, "A simple method for monotonic interpolation in one dimension", 1990: C1, within
// each interval's two slice values); 0 keeps the paper's straight lines.
//
// One function for every consumer of in-between time: the solver's overlap test (the reference here, in
// float; kernels/curve.cl is its twin), and the frames, the animated vector keys and the quality
// measures (src/render, in double). The operations are written out in one order, so the reference and the
// kernel agree bit for bit.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "animpak/state.hpp"

namespace animpak {

/// The curve between slices, `motion_curve`: the paper's straight lines, the monotone cubic (0.4.0 to
/// 0.7.0) or the C2 spline (the default).
enum CurveMode : int { curve_linear = 0, curve_monotone = 1, curve_spline = 2 };

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
/// `h` and `spline` say how far the value may swing: within the interval's two values, or (the spline)
/// within its four Bézier control points x0, x0 + h·m0/3, x1 − h·m1/3, x1.
template <typename T>
struct CurveBasis {
  T c01, c10, c11, h;
  bool spline;
};

template <typename T>
CurveBasis<T> curve_basis(T u, T h, int mode) {
  if (mode == curve_linear) return {u, T(0), T(0), h, false};
  const T v = T(1) - u;
  return {u * u * (T(3) - T(2) * u), h * u * v * v, -(h * u * u * v), h, mode == curve_spline};
}

/// The Bézier handle of a slice value x with tangent m over a step h (+h: the interval after the slice,
/// −h: the one before), as curve_value and slice_boxes both compute it.
template <typename T>
T curve_handle(T x, T m, T h) {
  return x + (h * m) / T(3);
}

/// The curve's value between slice values x0 and x1 with tangents m0 and m1, kept within [x0, x1] for the
/// monotone cubic (exactly so in floating point; in exact arithmetic Steffen's tangents already keep it
/// there) and within the four control points for the spline (the cubic's convex hull, which the widened
/// slice boxes hold).
template <typename T>
T curve_value(T x0, T x1, T m0, T m1, const CurveBasis<T>& b) {
  T x = x0 + (x1 - x0) * b.c01 + m0 * b.c10 + m1 * b.c11;
  T lo = x1 < x0 ? x1 : x0, hi = x0 < x1 ? x1 : x0;
  if (b.spline) {
    const T p = curve_handle(x0, m0, b.h), q = curve_handle(x1, m1, -b.h);
    lo = p < lo ? p : lo;
    lo = q < lo ? q : lo;
    hi = hi < p ? p : hi;
    hi = hi < q ? q : hi;
  }
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
  int mode = curve_spline;  ///< CurveMode; curve_linear: the tangents are computed but weigh nothing
};

/// The chains of `topo` from its links (curve_links).
inline CurveChains curve_chains(const Topology& topo, const CurveLinks& links) {
  const std::int32_t slices = topo.slice_count();
  CurveChains c;
  c.begin.push_back(0);
  c.entry.assign(slices, -1);
  c.chain.assign(slices, -1);
  std::vector<char> incoming(static_cast<std::size_t>(slices), 0);
  for (std::int32_t s = 0; s < slices; ++s)
    if (links.next[s] >= 0) incoming[links.next[s]] = 1;
  const auto last_of_element = [&](std::int32_t s) {
    return s + 1 == topo.element_slice_begin[topo.slice_element[s] + 1];
  };
  // Walks `next` from `start` until an open end or back at `start`; returns the chain's period.
  const auto walk = [&](std::int32_t start) {
    const std::int32_t id = static_cast<std::int32_t>(c.begin.size()) - 1;
    float loops = 0.0f;
    std::int32_t s = start;
    while (true) {
      c.entry[s] = static_cast<std::int32_t>(c.slice.size());
      c.chain[s] = id;
      c.slice.push_back(s);
      c.offset.push_back(loops);
      c.alias.push_back(-1);
      const std::int32_t q = links.next[s];
      if (q < 0) break;
      if (last_of_element(s)) loops += 1.0f;
      if (q == start) break;
      s = q;
    }
    c.begin.push_back(static_cast<std::int32_t>(c.slice.size()));
    c.period.push_back(links.next[s] == start ? loops : 0.0f);
  };
  // Open chains start where nothing comes before; closed ones at their lowest slice that something
  // leads to (a looping element's first slice is nobody's next: its loop partner's last stands for it).
  for (std::int32_t s = 0; s < slices; ++s)
    if (links.prev[s] < 0 && c.entry[s] < 0) walk(s);
  for (std::int32_t s = 0; s < slices; ++s)
    if (c.entry[s] < 0 && incoming[s]) walk(s);
  // The first slices left over are their loop partners' last ones (the loop pairs, as curve_links reads
  // them) and take their tangents; anything else left (none, by the walks above) is a chain of its own.
  for (std::size_t i = 0; i < topo.loop_end.size(); ++i) {
    const std::int32_t last = topo.slice[topo.loop_end[i]], first = topo.slice[topo.loop_start[i]];
    if (c.entry[first] >= 0 || c.entry[last] < 0) continue;
    c.entry[first] = c.entry[last];
    c.chain[first] = c.chain[last];
    c.alias[c.entry[last]] = first;
  }
  for (std::int32_t s = 0; s < slices; ++s)
    if (c.entry[s] < 0) walk(s);
  for (std::size_t k = 0; k + 1 < c.begin.size(); ++k) {
    const std::int32_t first = c.slice[c.begin[k]];
    for (std::int32_t v = topo.slice_begin[first]; v < topo.slice_begin[first + 1]; ++v) {
      c.track_vertex.push_back(v);
      c.track_chain.push_back(static_cast<std::int32_t>(k));
    }
  }
  return c;
}

/// Fills topo.curve and topo.chains (state.hpp) from its element ranges and loop pairs. Wherever a topology
/// is built (build_world; the tests' WorldBuilder), once its slices and loop pairs are set: every consumer
/// reads them from there instead of computing them again.
inline void link_curves(Topology& topo) {
  topo.curve = curve_links(topo);
  topo.chains = curve_chains(topo, topo.curve);
}

/// Throws std::invalid_argument unless topo.curve and topo.chains cover every slice of `topo`, naming
/// `user`: a topology put together without link_curves has none.
inline void require_curve_links(const Topology& topo, const char* user) {
  const std::size_t slices = static_cast<std::size_t>(topo.slice_count());
  if (topo.curve.prev.size() != slices || topo.curve.next.size() != slices || topo.chains.chain.size() != slices ||
      topo.chains.entry.size() != slices)
    throw std::invalid_argument(std::string(user) +
                                ": the topology's curve links do not cover its slices; call link_curves(topology) "
                                "(include/animpak/curve.hpp) once its slices and loop pairs are set");
}

/// Row i of the spline's system on a track of n entries at times tau (open or closed over `period`):
/// a·m[i−1] + b·m[i] + c·m[i+1] = d (x and y), the C2 condition at an inner knot, the natural end (no
/// acceleration) at an open end, and m = 0 where the steps are flat (slices at one t).
template <typename T>
struct SplineRow {
  T a, b, c, dx, dy;
};

template <typename T, typename Tau, typename X, typename Y>
SplineRow<T> spline_row(std::int32_t i, std::int32_t n, T period, const Tau& tau, const X& x, const Y& y) {
  const bool closed = period > T(0);
  const bool has_prev = i > 0 || closed, has_next = i + 1 < n || closed;
  const std::int32_t ip = i > 0 ? i - 1 : n - 1, in = i + 1 < n ? i + 1 : 0;
  const T hp = !has_prev ? T(0) : (i > 0 ? tau(i) - tau(ip) : tau(i) + period - tau(ip));
  const T hn = !has_next ? T(0) : (i + 1 < n ? tau(in) - tau(i) : tau(in) + period - tau(i));
  const T spx = has_prev ? curve_slope(x(ip), x(i), hp) : T(0), snx = has_next ? curve_slope(x(i), x(in), hn) : T(0);
  const T spy = has_prev ? curve_slope(y(ip), y(i), hp) : T(0), sny = has_next ? curve_slope(y(i), y(in), hn) : T(0);
  SplineRow<T> r{T(0), T(1), T(0), T(0), T(0)};
  if (has_prev && has_next) {
    r = {hn, T(2) * (hp + hn), hp, T(3) * (hn * spx + hp * snx), T(3) * (hn * spy + hp * sny)};
  } else if (has_next) {
    r = {T(0), T(2), T(1), T(3) * snx, T(3) * sny};
  } else if (has_prev) {
    r = {T(1), T(2), T(0), T(3) * spx, T(3) * spy};
  }
  if (!(r.b > T(0))) r = {T(0), T(1), T(0), T(0), T(0)};
  return r;
}

/// The tangents mx, my at the n entries of one track: the C2 cubic spline through (tau(i), x(i), y(i)),
/// open (natural ends) or closed over `period` (periodic). A tridiagonal solve, Thomas' algorithm, and
/// for a closed track the Sherman–Morrison correction for its two corners; cp and z are scratch. Every
/// operation in one order: kernels/curve.cl's curve_spline_tangents is its twin in float, the frames
/// take it in double.
template <typename T, typename Tau, typename X, typename Y, typename Out>
void spline_tangents(std::int32_t n, T period, const Tau& tau, const X& x, const Y& y, Out& mx, Out& my, Out& cp,
                     Out& z) {
  if (n < 2) {
    for (std::int32_t i = 0; i < n; ++i) mx[i] = T(0), my[i] = T(0);
    return;
  }
  const bool closed = period > T(0);
  T gamma = T(0), alpha = T(0), beta = T(0);
  if (closed) {
    const SplineRow<T> first = spline_row<T>(0, n, period, tau, x, y),
                       last = spline_row<T>(n - 1, n, period, tau, x, y);
    gamma = -first.b, beta = first.a, alpha = last.c;
  }
  // Forward sweep: mx, my hold the eliminated right-hand sides, z the correction's.
  for (std::int32_t i = 0; i < n; ++i) {
    SplineRow<T> r = spline_row<T>(i, n, period, tau, x, y);
    T u = T(0);
    if (closed) {
      if (i == 0) r.b = r.b - gamma, r.a = T(0), u = gamma;
      if (i == n - 1) r.b = r.b - alpha * beta / gamma, r.c = T(0), u = alpha;
    }
    if (i == 0) {
      cp[i] = r.c / r.b;
      mx[i] = r.dx / r.b, my[i] = r.dy / r.b, z[i] = u / r.b;
    } else {
      const T den = r.b - r.a * cp[i - 1];
      cp[i] = r.c / den;
      mx[i] = (r.dx - r.a * mx[i - 1]) / den, my[i] = (r.dy - r.a * my[i - 1]) / den;
      z[i] = (u - r.a * z[i - 1]) / den;
    }
  }
  for (std::int32_t i = n - 2; i >= 0; --i) {
    mx[i] = mx[i] - cp[i] * mx[i + 1], my[i] = my[i] - cp[i] * my[i + 1];
    z[i] = z[i] - cp[i] * z[i + 1];
  }
  if (!closed) return;
  const T den = T(1) + z[0] + beta * z[n - 1] / gamma;
  const T fx = (mx[0] + beta * mx[n - 1] / gamma) / den, fy = (my[0] + beta * my[n - 1] / gamma) / den;
  for (std::int32_t i = 0; i < n; ++i) mx[i] = mx[i] - fx * z[i], my[i] = my[i] - fy * z[i];
}

}  // namespace animpak
