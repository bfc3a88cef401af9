// The curve between slices (include/animpak/curve.hpp). The spline (the default): through every slice, C2
// at every slice and across the loop seam, natural at open ends, held by the widened slice boxes, the same
// in float as in double, and what the overlap test walks. The monotone cubic (motion_curve 1): C1 at the
// slices where the straight lines turn corners, never outside the two slice values of an interval, flat
// where a coordinate turns. Both periodic across the loop seam and closer to a rotation's circle than the
// chord.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "animpak/curve.hpp"
#include "tiny_worlds.hpp"

using namespace animpak;

namespace {

// A one-coordinate curve through (t_i, x_i) with the library's tangents, evaluated at t.
struct Curve1 {
  std::vector<double> t, x;
  bool cubic = true;

  double tangent(std::size_t i) const {
    const bool p = i > 0, n = i + 1 < t.size();
    const double hp = p ? t[i] - t[i - 1] : 0, hn = n ? t[i + 1] - t[i] : 0;
    return curve_tangent(p ? curve_slope(x[i - 1], x[i], hp) : 0.0, n ? curve_slope(x[i], x[i + 1], hn) : 0.0, hp, hn,
                         p, n);
  }
  double at(double tf) const {
    std::size_t i = 0;
    while (i + 2 < t.size() && t[i + 1] < tf) ++i;
    const double h = t[i + 1] - t[i];
    return curve_value(x[i], x[i + 1], tangent(i), tangent(i + 1), curve_basis((tf - t[i]) / h, h, cubic));
  }
};

}  // namespace

TEST_CASE("monotone curve: passes through every slice and stays within each interval's two values") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> value(-1.0, 1.0), step(0.02, 0.2);
  for (int trial = 0; trial < 200; ++trial) {
    Curve1 c;
    double t = 0;
    for (int i = 0; i < 12; ++i) c.t.push_back(t), c.x.push_back(value(rng)), t += step(rng);
    for (std::size_t i = 0; i < c.t.size(); ++i) CHECK(c.at(c.t[i]) == Approx(c.x[i]).margin(1e-12));
    for (std::size_t i = 0; i + 1 < c.t.size(); ++i)
      for (int j = 1; j < 50; ++j) {
        const double v = c.at(c.t[i] + (c.t[i + 1] - c.t[i]) * j / 50.0);
        INFO("trial " << trial << ", interval " << i << ", " << j << "/50");
        CHECK(v >= std::min(c.x[i], c.x[i + 1]));
        CHECK(v <= std::max(c.x[i], c.x[i + 1]));
      }
  }
}

TEST_CASE(
    "monotone curve: no corner at a slice (C1) where straight lines turn one, and flat where the coordinate turns") {
  const Curve1 cubic{{0.0, 0.3, 0.5, 0.9, 1.0}, {0.0, 0.4, 0.5, 0.2, 0.1}, true};
  Curve1 straight = cubic;
  straight.cubic = false;
  const double d = 1e-6;
  for (const std::size_t i : {std::size_t(1), std::size_t(3)}) {  // monotone through knot 1; knot 3 as well
    const double left = (cubic.at(cubic.t[i]) - cubic.at(cubic.t[i] - d)) / d;
    const double right = (cubic.at(cubic.t[i] + d) - cubic.at(cubic.t[i])) / d;
    CHECK(left == Approx(right).margin(1e-4));
    const double sl = (straight.at(cubic.t[i]) - straight.at(cubic.t[i] - d)) / d;
    const double sr = (straight.at(cubic.t[i] + d) - straight.at(cubic.t[i])) / d;
    CHECK(std::abs(sl - sr) > 0.1);
  }
  // Knot 2 is a maximum: its tangent is zero, so the curve eases in and out of it.
  CHECK(cubic.tangent(2) == 0.0);
  CHECK((cubic.at(0.5 + d) - cubic.at(0.5)) / d == Approx(0.0).margin(1e-4));
}

TEST_CASE("monotone curve: a rotation keeps its radius between slices far better than the chord") {
  // A point on the unit circle turning 15° per slice interval (24 slices a turn), one loop; the slices
  // sit half a step off the coordinates' extremes, the worst case for a clamped coordinate.
  const int n = 24;
  Curve1 x, y;
  for (int i = -1; i <= n + 1; ++i) {
    const double t = double(i) / n, a = 2.0 * M_PI * (t + 0.5 / n);
    x.t.push_back(t), y.t.push_back(t), x.x.push_back(std::cos(a)), y.x.push_back(std::sin(a));
  }
  double chord = 0, curve = 0;
  for (int i = 0; i < n; ++i) {
    const double tm = (i + 0.5) / n;
    const double r = std::hypot(x.at(tm), y.at(tm));
    curve += std::abs(1.0 - r) / n;
    chord += (1.0 - std::cos(M_PI / n)) / n;  // the straight line's midpoint
  }
  INFO("mean radius error: chord " << chord << ", curve " << curve);
  CHECK(curve < chord / 3.0);
}

TEST_CASE("curve_links and curve_tangents (monotone): within an element, across the loop seam, and open ends") {
  using test::TinySlice;
  test::WorldBuilder b;
  // Element 0 loops into itself: a square moving right then back over 5 slices (t 0 .. 1); element 1,
  // open, moves right at constant speed.
  const std::vector<float> xs = {0.3f, 0.4f, 0.5f, 0.4f, 0.3f};
  std::vector<TinySlice> looped, open;
  for (int s = 0; s < 5; ++s) {
    looped.push_back({test::square(xs[s], 0.3f, 0.05f), s / 4.0f});
    open.push_back({test::square(0.2f + 0.1f * s, 0.7f, 0.05f), s / 4.0f});
  }
  b.add_element(looped);
  b.add_element(open);
  for (int k = 0; k < 4; ++k) b.add_loop(4 * 4 + k, k);  // element 0's last slice ≡ its first
  const test::TinyWorld w = b.build();
  const CurveLinks links = curve_links(w.topo);
  CHECK(links.prev == std::vector<std::int32_t>{3, 0, 1, 2, 3, -1, 5, 6, 7, 8});
  CHECK(links.next == std::vector<std::int32_t>{1, 2, 3, 4, 1, 6, 7, 8, 9, -1});
  // The topology holds the same links, filled once where it is built (link_curves); the tangents read them.
  CHECK(w.topo.curve.prev == links.prev);
  CHECK(w.topo.curve.next == links.next);
  CurveTangents m;
  reference::curve_tangents(w.topo, w.state, curve_monotone, m);
  // Element 0: slice 0 and slice 4 are the same point of a periodic motion, with the same tangent; at the
  // turn (slice 2, x at its largest) the tangent is zero; slices 1 and 3 move at Steffen's tangent.
  CHECK(m.x[0] == m.x[16]);
  CHECK(m.x[0] == 0.0f);  // the loop's leftmost point: a turn as well
  CHECK(m.x[8] == 0.0f);
  CHECK(m.x[4] == Approx(0.4f));  // both chords 0.1 per 0.25: slope 0.4
  CHECK(m.x[12] == Approx(-0.4f));
  // Element 1: open ends take their one chord's slope.
  CHECK(m.x[20] == Approx(0.4f));
  CHECK(m.x[36] == Approx(0.4f));
  CHECK(m.y[20] == 0.0f);
}

namespace {

// Whether the overlap test with three points per interval finds an overlap at any of vertices [first, last)
// on curve `mode`, with the slice boxes and broadphase built as a step builds them.
bool overlap_found(const test::TinyWorld& w, int mode, std::int32_t first, std::int32_t last) {
  const CurveTangents m = test::tangents(w, mode);
  SliceBoxes boxes;
  reference::slice_boxes(w.topo, w.state, m, boxes);
  OverlapGrid grid;
  reference::build_overlap_grid(w.topo, boxes, grid);
  bool found = false;
  for (std::int32_t v = first; v < last; ++v)
    found = found || reference::overlap_test(w.topo, w.state, boxes, grid, m, v, 3).overlap;
  return found;
}

}  // namespace

TEST_CASE("overlap test between slices: on the monotone curve it finds an overlap that straight lines do not have") {
  // Element 0 comes up, turns the corner diagonally between slices 1 and 2, and leaves to the right: on the
  // curve it bulges to the upper left of the straight chord between those slices (x lags, y leads, by
  // 0.0375 at the middle). Element 1, a small still square, sits just beyond the chord on that side.
  const std::vector<float> times = {0.0f, 1.0f / 3.0f, 2.0f / 3.0f, 1.0f};
  const float ax[] = {0.3f, 0.3f, 0.6f, 0.9f}, ay[] = {0.1f, 0.4f, 0.7f, 0.7f};
  std::vector<test::TinySlice> mover, still;
  for (int s = 0; s < 4; ++s) {
    mover.push_back({test::square(ax[s], ay[s], 0.05f), times[s]});
    still.push_back({test::square(0.37f, 0.66f, 0.03f), times[s]});
  }
  test::WorldBuilder b;
  b.add_element(mover);
  b.add_element(still);
  const test::TinyWorld w = b.build();
  for (const int mode : {curve_monotone, curve_linear}) {
    INFO("motion_curve " << mode);
    CHECK(overlap_found(w, mode, 16, 32) == (mode == curve_monotone));  // element 1's vertices
  }
}

TEST_CASE(
    "overlap test between slices: the spline's swing past its slices is tested, where the monotone cubic "
    "and straight lines stay") {
  // Element 0 moves right and back, x 0.2, 0.4, 0.6, 0.6, 0.4 at t 0 .. 1 (open): the natural spline through
  // those swings to x 0.631 in the middle of [0.5, 0.75], the monotone cubic and the straight line stay at
  // 0.6. Element 1, a small still square, sits 0.02 beyond the mover's right edge at 0.6.
  std::vector<test::TinySlice> mover, still;
  const float xs[] = {0.2f, 0.4f, 0.6f, 0.6f, 0.4f};
  for (int s = 0; s < 5; ++s) {
    mover.push_back({test::square(xs[s], 0.5f, 0.05f), s / 4.0f});
    still.push_back({test::square(0.69f, 0.5f, 0.02f), s / 4.0f});
  }
  test::WorldBuilder b;
  b.add_element(mover);
  b.add_element(still);
  const test::TinyWorld w = b.build();
  for (const int mode : {curve_spline, curve_monotone, curve_linear}) {
    INFO("motion_curve " << mode);
    CHECK(overlap_found(w, mode, 0, w.topo.vertex_count()) == (mode == curve_spline));
  }
}

namespace {

// One track of the spline in double: n values at times tau, closed over `period` (> 0) or open.
struct Track {
  std::vector<double> tau, x, mx, my;
  double period = 0.0;

  void solve() {
    const std::int32_t n = static_cast<std::int32_t>(tau.size());
    mx.assign(n, 0.0), my.assign(n, 0.0);
    std::vector<double> cp(n), z(n);
    const auto t = [&](std::int32_t i) { return tau[i]; };
    const auto v = [&](std::int32_t i) { return x[i]; };
    spline_tangents<double>(n, period, t, v, v, mx, my, cp, z);
  }
  // The cubic on interval i (to i + 1, or across the seam from the last back to the first) at fraction u:
  // value, first and second derivative in t.
  void at(std::size_t i, double u, double& value, double& d1, double& d2) const {
    const std::size_t j = i + 1 < tau.size() ? i + 1 : 0;
    const double h = i + 1 < tau.size() ? tau[j] - tau[i] : tau[j] + period - tau[i];
    const double x0 = x[i], x1 = x[j], m0 = mx[i], m1 = mx[j];
    const CurveBasis<double> b = curve_basis(u, h, curve_spline);
    value = x0 + (x1 - x0) * b.c01 + m0 * b.c10 + m1 * b.c11;
    // d/dt of the Hermite basis: (x1 − x0)·6u(1 − u)/h + m0(1 − 4u + 3u²) + m1(3u² − 2u).
    d1 = (x1 - x0) * 6.0 * u * (1.0 - u) / h + m0 * (1.0 - 4.0 * u + 3.0 * u * u) + m1 * (3.0 * u * u - 2.0 * u);
    d2 = ((x1 - x0) * (6.0 - 12.0 * u) / h + m0 * (-4.0 + 6.0 * u) + m1 * (6.0 * u - 2.0)) / h;
  }
};

}  // namespace

TEST_CASE("spline: through every slice, C2 at every slice, periodic across the seam and natural at open ends") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> value(-1.0, 1.0), step(0.02, 0.2);
  for (int trial = 0; trial < 100; ++trial) {
    for (const bool closed : {true, false}) {
      INFO("trial " << trial << (closed ? ", closed" : ", open"));
      Track c;
      double t = 0.0;
      const int n = 2 + trial % 14;
      for (int i = 0; i < n; ++i) c.tau.push_back(t), c.x.push_back(value(rng)), t += step(rng);
      c.period = closed ? t : 0.0;  // the seam's step: the last one drawn
      c.solve();
      const std::size_t intervals = closed ? c.tau.size() : c.tau.size() - 1;
      for (std::size_t i = 0; i < intervals; ++i) {
        double v0, a0, b0, v1, a1, b1;
        c.at(i, 0.0, v0, a0, b0);
        c.at(i, 1.0, v1, a1, b1);
        const std::size_t j = i + 1 < c.tau.size() ? i + 1 : 0;
        CHECK(v0 == Approx(c.x[i]).margin(1e-12));
        CHECK(v1 == Approx(c.x[j]).margin(1e-12));
        if (i + 1 < intervals || closed) {
          // The next interval starts with this one's speed and acceleration.
          double w, a, bb;
          c.at(i + 1 < c.tau.size() ? i + 1 : 0, 0.0, w, a, bb);
          CHECK(a == Approx(a1).margin(1e-9));
          CHECK(bb == Approx(b1).margin(1e-6 * (1.0 + std::abs(b1))));
        }
      }
      if (!closed && n > 2) {
        double v, a, bb;
        c.at(0, 0.0, v, a, bb);
        CHECK(bb == Approx(0.0).margin(1e-6));
        c.at(intervals - 1, 1.0, v, a, bb);
        CHECK(bb == Approx(0.0).margin(1e-6));
      }
    }
  }
}

TEST_CASE("spline: a straight run at constant speed stays straight, a still track stays still") {
  Track c;
  c.tau = {0.0, 0.1, 0.35, 0.5, 0.8};
  for (const double t : c.tau) c.x.push_back(0.2 + 0.5 * t);
  c.solve();
  for (const double m : c.mx) CHECK(m == Approx(0.5).margin(1e-12));
  Track still;
  still.tau = {0.0, 0.25, 0.5, 0.75};
  still.x = {0.3, 0.3, 0.3, 0.3};
  still.period = 1.0;
  still.solve();
  for (const double m : still.mx) CHECK(m == 0.0);
}

TEST_CASE(
    "curve_chains and the spline's tangents: one closed chain per loop, through loop partners, open chains "
    "elsewhere, and the reference's float solve as the frames' double one") {
  using test::TinySlice;
  test::WorldBuilder b;
  // Element 0 loops into itself over 5 slices; elements 1 and 2 loop into each other (4 slices each, as two
  // penguins swap places: one chain over both, two loops); element 3 is open.
  std::vector<TinySlice> e0, e1, e2, e3;
  for (int s = 0; s < 5; ++s) {
    const float t = s / 4.0f;
    e0.push_back({test::square(0.3f + 0.1f * std::sin(6.2831853f * t), 0.3f, 0.05f), t});
    e3.push_back({test::square(0.2f + 0.1f * s, 0.9f, 0.05f), t});
  }
  for (int s = 0; s < 4; ++s) {
    const float t = s / 3.0f;
    e1.push_back({test::square(0.2f + 0.6f * t, 0.6f + 0.05f * s * (3 - s), 0.05f), t});
    e2.push_back({test::square(0.8f - 0.6f * t, 0.6f - 0.05f * s * (3 - s), 0.05f), t});
  }
  b.add_element(e0);
  b.add_element(e1);
  b.add_element(e2);
  b.add_element(e3);
  for (int k = 0; k < 4; ++k) {
    b.add_loop(4 * 4 + k, k);            // element 0: its last slice is its first
    b.add_loop(20 + 3 * 4 + k, 36 + k);  // element 1's last slice is element 2's first
    b.add_loop(36 + 3 * 4 + k, 20 + k);  // and element 2's last is element 1's first
  }
  const test::TinyWorld w = b.build();
  const CurveLinks links = curve_links(w.topo);
  const CurveChains chains = curve_chains(w.topo, links);
  // Slices: element 0 is 0–4, element 1 5–8, element 2 9–12, element 3 13–17.
  REQUIRE(chains.begin.size() == 4);  // three chains
  const auto chain_of = [&](std::int32_t s) { return chains.chain[s]; };
  CHECK(chains.period[chain_of(13)] == 0.0f);  // element 3: open
  CHECK(chains.begin[chain_of(13) + 1] - chains.begin[chain_of(13)] == 5);
  CHECK(chains.period[chain_of(1)] == 1.0f);  // element 0: 4 entries (its first slice is its last), 1 loop
  CHECK(chains.begin[chain_of(1) + 1] - chains.begin[chain_of(1)] == 4);
  CHECK(chains.entry[0] == chains.entry[4]);
  CHECK(chain_of(5) == chain_of(9));  // elements 1 and 2: one chain of 6 entries over 2 loops
  CHECK(chains.period[chain_of(5)] == 2.0f);
  CHECK(chains.begin[chain_of(5) + 1] - chains.begin[chain_of(5)] == 6);
  CHECK(chains.entry[5] == chains.entry[12]);
  CHECK(chains.entry[9] == chains.entry[8]);
  CHECK(chains.track_vertex.size() == 3 * 4);

  CHECK(w.topo.chains.slice == chains.slice);  // as link_curves filled them
  CHECK(w.topo.chains.entry == chains.entry);

  CurveTangents m;
  reference::curve_tangents(w.topo, w.state, curve_spline, m);
  // A loop's first slice has its last slice's tangent; a still coordinate has none.
  for (int k = 0; k < 4; ++k) {
    CHECK(m.x[k] == m.x[16 + k]);
    CHECK(m.y[k] == m.y[16 + k]);
    CHECK(m.x[20 + k] == m.x[48 + k]);  // element 1's first slice ≡ element 2's last
    CHECK(m.y[k] == 0.0f);
  }
  // Element 1 and 2 together trace one closed curve: at the slice where one hands over to the other the
  // speed carries on (element 1's last slice moves as element 2's first does), here downwards.
  CHECK(m.y[32] == m.y[36]);
  CHECK(m.y[32] < -0.1f);
  // The reference's float solve against the same system in double.
  for (std::int32_t v = 0; v < w.topo.vertex_count(); ++v) {
    const std::int32_t s = w.topo.slice[v], c = chains.chain[s], begin = chains.begin[c];
    const std::int32_t len = chains.begin[c + 1] - begin, k = v - w.topo.slice_begin[s];
    std::vector<double> mx(len), my(len), cp(len), z(len);
    const auto vertex = [&](std::int32_t i) { return w.topo.slice_begin[chains.slice[begin + i]] + k; };
    const auto tau = [&](std::int32_t i) {
      return double(w.state.t[w.topo.slice_begin[chains.slice[begin + i]]]) + double(chains.offset[begin + i]);
    };
    const auto x = [&](std::int32_t i) { return double(w.state.x[vertex(i)]); };
    const auto y = [&](std::int32_t i) { return double(w.state.y[vertex(i)]); };
    spline_tangents<double>(len, double(chains.period[c]), tau, x, y, mx, my, cp, z);
    const std::int32_t i = chains.entry[s] - begin;
    INFO("vertex " << v);
    CHECK(m.x[v] == Approx(mx[i]).margin(1e-4));
    CHECK(m.y[v] == Approx(my[i]).margin(1e-4));
  }
}

TEST_CASE("spline: two slices' widened boxes hold every boundary point of the curve between them") {
  // Elements that wiggle from slice to slice, so the spline swings well past its slice values.
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> jitter(-0.08f, 0.08f);
  test::WorldBuilder b;
  for (int e = 0; e < 4; ++e) {
    std::vector<test::TinySlice> slices;
    for (int s = 0; s < 9; ++s)
      slices.push_back({test::square(0.3f + 0.12f * e + jitter(rng), 0.5f + jitter(rng), 0.04f), s / 8.0f});
    b.add_element(slices);
    if (e % 2 == 0)
      for (int k = 0; k < 4; ++k) b.add_loop(e * 36 + 8 * 4 + k, e * 36 + k);
  }
  const test::TinyWorld w = b.build();
  const CurveTangents m = test::tangents(w, curve_spline);
  SliceBoxes boxes;
  reference::slice_boxes(w.topo, w.state, m, boxes);
  long outside_unwidened = 0;
  for (std::int32_t s = 0; s + 1 < w.topo.slice_count(); ++s) {
    if (w.topo.slice_element[s] != w.topo.slice_element[s + 1]) continue;
    const std::int32_t lo = w.topo.slice_begin[s], hi = w.topo.slice_begin[s + 1];
    const float x0 = std::min(boxes.x0[s], boxes.x0[s + 1]), x1 = std::max(boxes.x1[s], boxes.x1[s + 1]);
    const float y0 = std::min(boxes.y0[s], boxes.y0[s + 1]), y1 = std::max(boxes.y1[s], boxes.y1[s + 1]);
    for (int j = 0; j <= 64; ++j) {
      const CurveBasis<float> basis = curve_basis(j / 64.0f, w.state.t[hi] - w.state.t[lo], curve_spline);
      for (std::int32_t k = 0; k < w.topo.slice_boundary[s]; ++k) {
        const float x = curve_value(w.state.x[lo + k], w.state.x[hi + k], m.x[lo + k], m.x[hi + k], basis);
        const float y = curve_value(w.state.y[lo + k], w.state.y[hi + k], m.y[lo + k], m.y[hi + k], basis);
        INFO("slice " << s << ", vertex " << k << ", " << j << "/64");
        CHECK(x >= x0);
        CHECK(x <= x1);
        CHECK(y >= y0);
        CHECK(y <= y1);
        const float ux0 = std::min(w.state.x[lo + k], w.state.x[hi + k]),
                    ux1 = std::max(w.state.x[lo + k], w.state.x[hi + k]);
        if (x < ux0 - 1e-4f || x > ux1 + 1e-4f) ++outside_unwidened;
      }
    }
  }
  // The boxes matter: the curve does leave its two slice values, often.
  CHECK(outside_unwidened > 100);
}

TEST_CASE(
    "curve: a shape turning one turn over 24 slices keeps its area within 0.1 % between slices on the spline, 0.5 % on "
    "the monotone cubic") {
  // A regular pentagon of radius 0.3 turning once over a looping element of 24 slices (15° a slice
  // interval); its area at eight points of every interval against its area at the slices.
  constexpr int n = 24, corners = 5;
  std::vector<test::TinySlice> slices;
  for (int s = 0; s < n; ++s) {
    const float t = float(s) / (n - 1);
    test::Ring ring;
    for (int k = 0; k < corners; ++k) {
      const double a = 2.0 * M_PI * (double(t) + double(k) / corners);
      ring.push_back({float(0.5 + 0.3 * std::cos(a)), float(0.5 + 0.3 * std::sin(a))});
    }
    slices.push_back({ring, t});
  }
  test::WorldBuilder b;
  b.add_element(slices);
  for (int k = 0; k < corners; ++k) b.add_loop((n - 1) * corners + k, k);
  const test::TinyWorld w = b.build();
  const auto worst_area_change = [&](int cubic) {
    const CurveTangents m = test::tangents(w, cubic);
    const auto area_at = [&](int s, float u) {
      const std::int32_t lo = s * corners, hi = lo + corners;
      const CurveBasis<float> basis = curve_basis(u, w.state.t[hi] - w.state.t[lo], cubic);
      double x[corners], y[corners], a = 0.0;
      for (int k = 0; k < corners; ++k) {
        x[k] = curve_value(w.state.x[lo + k], w.state.x[hi + k], m.x[lo + k], m.x[hi + k], basis);
        y[k] = curve_value(w.state.y[lo + k], w.state.y[hi + k], m.y[lo + k], m.y[hi + k], basis);
      }
      for (int k = 0; k < corners; ++k) a += x[k] * y[(k + 1) % corners] - x[(k + 1) % corners] * y[k];
      return std::abs(0.5 * a);
    };
    const double at_slice = area_at(0, 0.0f);
    double worst = 0.0;
    for (int s = 0; s + 1 < n; ++s)
      for (int j = 1; j <= 8; ++j) worst = std::max(worst, std::abs(area_at(s, j / 9.0f) / at_slice - 1.0));
    return worst;
  };
  CHECK(worst_area_change(curve_spline) < 0.001);
  CHECK(worst_area_change(curve_monotone) < 0.005);
  CHECK(worst_area_change(curve_linear) > 0.015);  // the chord: cos 7.5° in radius, squared
}

TEST_CASE("curve_tangents refuses a topology whose curve links were never filled, naming link_curves") {
  test::WorldBuilder b;
  b.add_element(test::square_tube(0.5f, 0.5f, 0.05f, {0.0f, 0.5f, 1.0f}));
  test::TinyWorld w = b.build();
  w.topo.curve = {};  // a topology put together without link_curves
  w.topo.chains = {};
  CurveTangents m;
  CHECK_THROWS_WITH(reference::curve_tangents(w.topo, w.state, curve_spline, m), Catch::Contains("link_curves"));
  link_curves(w.topo);
  CHECK_NOTHROW(reference::curve_tangents(w.topo, w.state, curve_spline, m));
}
