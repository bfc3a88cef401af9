// How many slices a scripted motion needs (docs/parameters.md, "How many slices a motion needs"): the
// script sampled densely is the truth; a candidate slice count keeps the script at its slice times, and
// the curve between slices (include/animpak/curve.hpp) must stay within a share of the element's size of
// the script at every dense time.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "animpak/animation.hpp"
#include "animpak/curve.hpp"

namespace animpak {

namespace {

// Dense samples of the script: enough that straight lines between them miss a full turn per loop by a
// thousandth of a percent of the element's size.
constexpr int dense_samples = 481;

// The script's positions at time t, straight between the two dense samples around it (a negligible error
// next to the tolerance at this density).
Vec2 dense_at(const std::vector<std::vector<Vec2>>& dense, int v, double t) {
  const double f = std::clamp(t, 0.0, 1.0) * (dense_samples - 1);
  const int k = std::min(static_cast<int>(f), dense_samples - 2);
  const double w = f - k;
  const Vec2 a = dense[k][v], b = dense[k + 1][v];
  return {a.x + (b.x - a.x) * w, a.y + (b.y - a.y) * w};
}

// The largest distance, over every vertex and dense time, between the script and the curve (`mode`,
// include/animpak/curve.hpp) through n slices at t = s / (n − 1), periodic across t = 1 ≡ 0 when `loop`.
double curve_error(const std::vector<std::vector<Vec2>>& dense, int n, bool loop, int mode) {
  const int vertices = static_cast<int>(dense.front().size());
  std::vector<double> t(n);
  for (int s = 0; s < n; ++s) t[s] = double(s) / (n - 1);
  double worst = 0.0;
  std::vector<Vec2> slice(n), tangent(n);
  // The spline's track: the n slices, or when looping the first n − 1 (the last is the first one loop
  // later) closed over one loop.
  const int entries = loop ? n - 1 : n;
  std::vector<double> mx(entries), my(entries), cp(entries), z(entries);
  for (int v = 0; v < vertices; ++v) {
    for (int s = 0; s < n; ++s) slice[s] = dense_at(dense, v, t[s]);
    if (mode == curve_spline) {
      const auto tau = [&](std::int32_t i) { return t[i]; };
      const auto x = [&](std::int32_t i) { return slice[i].x; };
      const auto y = [&](std::int32_t i) { return slice[i].y; };
      spline_tangents<double>(entries, loop ? 1.0 : 0.0, tau, x, y, mx, my, cp, z);
      for (int s = 0; s < n; ++s) tangent[s] = {mx[s < entries ? s : 0], my[s < entries ? s : 0]};
    } else {
      for (int s = 0; s < n; ++s) {
        // The slices before and after, across the seam one period away when looping.
        const bool has_prev = s > 0 || loop, has_next = s + 1 < n || loop;
        const int p = s > 0 ? s - 1 : n - 2, q = s + 1 < n ? s + 1 : 1;
        const double hp = has_prev ? t[s] - (s > 0 ? t[p] : t[p] - 1.0) : 0.0;
        const double hn = has_next ? (s + 1 < n ? t[q] : t[q] + 1.0) - t[s] : 0.0;
        const double spx = has_prev ? curve_slope(slice[p].x, slice[s].x, hp) : 0.0;
        const double snx = has_next ? curve_slope(slice[s].x, slice[q].x, hn) : 0.0;
        const double spy = has_prev ? curve_slope(slice[p].y, slice[s].y, hp) : 0.0;
        const double sny = has_next ? curve_slope(slice[s].y, slice[q].y, hn) : 0.0;
        tangent[s] = {curve_tangent(spx, snx, hp, hn, has_prev, has_next),
                      curve_tangent(spy, sny, hp, hn, has_prev, has_next)};
      }
    }
    for (int k = 0; k < dense_samples; ++k) {
      const double tk = double(k) / (dense_samples - 1);
      const int s = std::min(static_cast<int>(tk * (n - 1)), n - 2);
      const double h = t[s + 1] - t[s];
      const CurveBasis<double> b = curve_basis((tk - t[s]) / h, h, mode);
      const double x = curve_value(slice[s].x, slice[s + 1].x, tangent[s].x, tangent[s + 1].x, b);
      const double y = curve_value(slice[s].y, slice[s + 1].y, tangent[s].y, tangent[s + 1].y, b);
      worst = std::max(worst, std::hypot(x - dense[k][v].x, y - dense[k][v].y));
    }
  }
  return worst;
}

}  // namespace

SliceAdvice slice_advice(const SliceMesh& mesh, const Outline& outline, const ArtFrame& frame,
                         const AnimationSpec& spec, int slices_now, int mode) {
  SliceAdvice advice;
  const std::vector<std::vector<Vec2>> dense = animate_slices(mesh, outline, frame, spec, dense_samples);
  double still = 0.0;
  for (const std::vector<Vec2>& positions : dense)
    for (std::size_t v = 0; v < positions.size(); ++v)
      still = std::max(still, std::hypot(positions[v].x - dense.front()[v].x, positions[v].y - dense.front()[v].y));
  if (still <= slice_advice_tolerance) return advice;  // the script moves less than the tolerance: any count
  advice.error = slices_now >= 2 ? curve_error(dense, slices_now, spec.loop, mode) : still;
  // Doubling, then bisection: the error falls as slices are added (not strictly, so this finds a count that
  // holds, near the fewest).
  constexpr int most = 1 + (dense_samples - 1) / 2;
  int hi = 3;
  while (hi < most && curve_error(dense, hi, spec.loop, mode) > slice_advice_tolerance) hi = 2 * hi - 1;
  hi = std::min(hi, most);
  int lo = std::max(2, (hi + 1) / 2);
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    if (curve_error(dense, mid, spec.loop, mode) <= slice_advice_tolerance)
      hi = mid;
    else
      lo = mid + 1;
  }
  advice.slices = hi;
  return advice;
}

std::string slice_advice_warning(const SpacetimeElement& element) {
  if (element.slices_needed <= element.slice_count) return {};
  char error[32];
  std::snprintf(error, sizeof error, "%.1f", 100.0 * element.motion_error);
  return "element \"" + element.name + "\": its scripted motion strays up to " + error +
         " % of its size from the curve between " + std::to_string(element.slice_count) + " slices; about " +
         std::to_string(element.slices_needed) + " slices keep it within 1 % (the scene's \"slices\")";
}

}  // namespace animpak
