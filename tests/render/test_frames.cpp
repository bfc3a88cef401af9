#include <catch2/catch.hpp>

#include "animpak/curve.hpp"
#include "animpak/render.hpp"
#include "tiny_world.hpp"

using namespace animpak;

TEST_CASE("frame_times: a loop stops one step short of 1, a non-loop ends on 1") {
  CHECK(frame_times(4, true) == std::vector<double>{0.0, 0.25, 0.5, 0.75});
  CHECK(frame_times(5, false) == std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0});
  CHECK(frame_times(1, false) == std::vector<double>{0.0});
  CHECK(frame_times(1, true) == std::vector<double>{0.0});
}

TEST_CASE("element_at: linear between the slices whose t bracket the frame time, clamped outside") {
  World world = tiny_star_world();
  world.params.forces.motion_curve = 0;  // the paper's straight lines (§6)
  SimState& state = world.state;
  const ElementInstance& inst = world.elements[1];
  const int P = world.library[inst.library].vertices_per_slice();
  // Slice s of element 1 sits at x = 0.1 s, y = 0.2 + 0.05 s and at hand-set times (not s / 3).
  const float slice_t[] = {0.0f, 0.3f, 0.6f, 1.0f};
  for (int s = 0; s < 4; ++s)
    for (int v = 0; v < P; ++v) {
      const int id = inst.vertex_begin + s * P + v;
      state.t[id] = slice_t[s];
      state.x[id] = 0.1f * s;
      state.y[id] = 0.2f + 0.05f * s;
    }
  auto check_all = [&](double tf, double x, double y) {
    INFO("tf = " << tf);
    for (const Vec2& p : element_at(world, state, 1, tf)) {
      CHECK(p.x == Approx(x).margin(1e-6));
      CHECK(p.y == Approx(y).margin(1e-6));
    }
  };
  check_all(0.45, 0.15, 0.275);  // midway between slices 1 (t 0.3) and 2 (t 0.6)
  check_all(0.3, 0.1, 0.25);
  check_all(0.8, 0.25, 0.325);
  check_all(-0.5, 0.0, 0.2);
  check_all(1.5, 0.3, 0.35);
  // The other elements keep their own slices.
  CHECK(element_at(world, state, 0, 0.45).size() == world.library[world.elements[0].library].slice.vertices.size());
}

TEST_CASE("element_at: on the spline, through the slices, with no jump of speed or acceleration at them") {
  World world = tiny_star_world();
  REQUIRE(world.params.forces.motion_curve == curve_spline);
  SimState& state = world.state;
  const ElementInstance& inst = world.elements[1];
  const int P = world.library[inst.library].vertices_per_slice();
  // The world loops: the last slice is the first (the loop constraint), x and y go round a triangle.
  const float xs[] = {0.2f, 0.1f, 0.3f, 0.2f}, ys[] = {0.2f, 0.3f, 0.25f, 0.2f};
  for (int s = 0; s < 4; ++s)
    for (int v = 0; v < P; ++v) {
      const int id = inst.vertex_begin + s * P + v;
      state.t[id] = float(s) / 3.0f;
      state.x[id] = xs[s];
      state.y[id] = ys[s];
    }
  for (int s = 0; s < 4; ++s)
    for (const Vec2& p : element_at(world, state, 1, s / 3.0)) {
      CHECK(p.x == Approx(xs[s]).margin(1e-6));
      CHECK(p.y == Approx(ys[s]).margin(1e-6));
    }
  // At the inner slices, the first and second differences just before and just after agree (the
  // straight lines' speed jumps there by 0.3 and 0.9 per unit t).
  const double d = 1e-3;
  const auto x = [&](double t) { return element_at(world, state, 1, t).front().x; };
  for (const double ts : {1.0 / 3.0, 2.0 / 3.0}) {
    INFO("slice at t " << ts);
    const double before = (x(ts) - x(ts - d)) / d, after = (x(ts + d) - x(ts)) / d;
    CHECK(std::abs(after - before) < 0.02);
    const double acc_before = (x(ts) - 2 * x(ts - d) + x(ts - 2 * d)) / (d * d);
    const double acc_after = (x(ts + 2 * d) - 2 * x(ts + d) + x(ts)) / (d * d);
    CHECK(std::abs(acc_after - acc_before) < 0.05 * (1.0 + std::abs(acc_before)));
  }
}

TEST_CASE(
    "element_at: on the monotone curve, through the slices, between their values, a straight track kept "
    "straight") {
  World world = tiny_star_world();
  world.params.forces.motion_curve = curve_monotone;
  SimState& state = world.state;
  const ElementInstance& inst = world.elements[1];
  const int P = world.library[inst.library].vertices_per_slice();
  // Slice s of element 1: x turns back at slice 2 (0, 0.1, 0.3, 0.2), y rises evenly, at evenly spaced times.
  const float xs[] = {0.0f, 0.1f, 0.3f, 0.2f};
  for (int s = 0; s < 4; ++s)
    for (int v = 0; v < P; ++v) {
      const int id = inst.vertex_begin + s * P + v;
      state.t[id] = float(s) / 3.0f;
      state.x[id] = xs[s];
      state.y[id] = 0.2f + 0.05f * float(s);
    }
  for (int s = 0; s < 4; ++s)
    for (const Vec2& p : element_at(world, state, 1, s / 3.0)) {
      CHECK(p.x == Approx(xs[s]).margin(1e-6));
      CHECK(p.y == Approx(0.2 + 0.05 * s).margin(1e-6));
    }
  // Between slices 1 and 2: x moves on towards the turn and never passes 0.3; y stays between its two
  // slice values.
  double last = 0.1;
  for (int j = 1; j < 20; ++j) {
    const Vec2 p = element_at(world, state, 1, (1.0 + j / 20.0) / 3.0).front();
    CHECK(p.x > last);
    CHECK(p.x <= 0.3);
    CHECK(p.y >= 0.25 - 1e-9);
    CHECK(p.y <= 0.3 + 1e-9);
    last = p.x;
  }
  // At the turn (slice 2) x eases in: its speed just before is below the straight line's (0.6 per unit t).
  const double d = 1e-4;
  CHECK((element_at(world, state, 1, 2.0 / 3.0).front().x - element_at(world, state, 1, 2.0 / 3.0 - d).front().x) / d <
        0.1);
}

TEST_CASE("element_scale: 1 at library size, s for a uniformly scaled copy, the initial scale after set-up") {
  const World world = tiny_star_world();
  const SliceMesh& rest = world.library[world.elements[0].library].slice;
  CHECK(element_scale(world, 0, rest.vertices) == Approx(1.0).epsilon(1e-12));
  std::vector<Vec2> scaled = rest.vertices;
  for (Vec2& p : scaled) p = Vec2{0.3, 0.7} + (p - Vec2{0.5, 0.5}) * 0.37;
  CHECK(element_scale(world, 0, scaled) == Approx(0.37).epsilon(1e-9));
  // At t = 0 the placed copy is the rest slice shrunk to params.placement.initial_scale (float positions).
  CHECK(element_scale(world, 0, element_at(world, world.state, 0, 0.0)) == Approx(0.22).epsilon(1e-4));
}
