// The curve between slices (include/animpak/curve.hpp): through every slice, C1 at the slices where the
// straight lines turn corners, never outside the two slice values of an interval (the overlap test's box
// bound), flat where a coordinate turns, periodic across the loop seam, and closer to a rotation's circle
// than the chord.
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

TEST_CASE("curve: passes through every slice and stays within each interval's two values") {
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

TEST_CASE("curve: no corner at a slice (C1) where straight lines turn one, and flat where the coordinate turns") {
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

TEST_CASE("curve: a rotation keeps its radius between slices far better than the chord") {
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

TEST_CASE("curve_links and curve_tangents: within an element, across the loop seam, and open ends") {
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
  CurveTangents m;
  reference::curve_tangents(w.topo, links, w.state, true, m);
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

TEST_CASE("overlap test between slices: on the curve it finds an overlap that straight lines do not have") {
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
  reference::SliceBoxes boxes;
  reference::slice_boxes(w.topo, w.state, boxes);
  reference::OverlapGrid grid;
  reference::build_overlap_grid(w.topo, boxes, grid);
  for (const bool cubic : {true, false}) {
    INFO((cubic ? "curve" : "straight lines"));
    const CurveTangents m = test::tangents(w, cubic);
    bool found = false;
    for (std::int32_t v = 16; v < 32; ++v)  // element 1's vertices
      found = found || reference::overlap_test(w.topo, w.state, boxes, grid, m, v, 3).overlap;
    CHECK(found == cubic);
  }
}

TEST_CASE("curve: a shape turning one turn over 24 slices keeps its area within 0.5 % between slices") {
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
  const auto worst_area_change = [&](bool cubic) {
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
  CHECK(worst_area_change(true) < 0.005);
  CHECK(worst_area_change(false) > 0.015);  // the chord: cos 7.5° in radius, squared
}
