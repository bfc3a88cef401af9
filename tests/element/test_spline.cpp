#include <catch2/catch.hpp>

#include <cmath>

#include "animpak/animation.hpp"
#include "animpak/error.hpp"

using namespace animpak;

TEST_CASE("Spline: passes through every key exactly, looping or not") {
  const std::vector<double> t{0.0, 0.2, 0.45, 0.8};
  const std::vector<double> v{1.0, -3.0, 2.5, 7.0};
  for (bool loop : {false, true}) {
    const Spline s(t, v, loop);
    for (std::size_t i = 0; i < t.size(); ++i) CHECK(std::fabs(s(t[i]) - v[i]) <= 1e-12);
  }
}

TEST_CASE("Spline: a looping spline closes with matching value and slope across t = 1 == 0") {
  const Spline s({0.1, 0.3, 0.6, 0.9}, {0.0, 2.0, -1.0, 4.0}, true);
  const double h = 1e-6;
  CHECK(std::fabs(s(1.0) - s(0.0)) <= 1e-12);
  CHECK(std::fabs(s(1.0 - h) - s(h)) <= 1e-4);  // continuous: both sides meet
  const double left = (s(1.0) - s(1.0 - h)) / h, right = (s(h) - s(0.0)) / h;
  CHECK(left == Approx(right).epsilon(1e-4));
  // Not trivially flat: the slope there is not zero, so the check above means something.
  CHECK(std::fabs(right) > 1.0);
}

TEST_CASE("Spline: a key at t = 1 must repeat the t = 0 key when looping, and may stand in for it") {
  const Spline closed({0.0, 0.5, 1.0}, {2.0, 5.0, 2.0}, true);
  CHECK(closed(1.0) == 2.0);
  CHECK(closed(0.5) == 5.0);
  const Spline only_end({0.5, 1.0}, {5.0, 2.0}, true);
  CHECK(only_end(0.0) == 2.0);
  CHECK(only_end(1.0) == 2.0);
  CHECK_THROWS_AS(Spline({0.0, 0.5, 1.0}, {2.0, 5.0, 3.0}, true), InputError);
  CHECK_NOTHROW(Spline({0.0, 0.5, 1.0}, {2.0, 5.0, 3.0}, false));
}

TEST_CASE("Spline: one key is a constant, two keys do not overshoot") {
  for (bool loop : {false, true}) {
    const Spline one({0.3}, {4.0}, loop);
    for (double t : {0.0, 0.3, 0.77, 1.0}) CHECK(one(t) == 4.0);
  }
  const Spline two({0.2, 0.7}, {0.0, 10.0}, false);
  for (int i = 0; i <= 100; ++i) {
    const double y = two(i / 100.0);
    CHECK(y >= 0.0);
    CHECK(y <= 10.0);
  }
  CHECK(two(0.0) == 0.0);  // clamped to the end keys outside them
  CHECK(two(1.0) == 10.0);
  const Spline two_loop({0.2, 0.7}, {0.0, 10.0}, true);
  for (int i = 0; i <= 100; ++i) {
    const double y = two_loop(i / 100.0);
    CHECK(y >= -10.0);  // a periodic cubic swings past its keys a little, but stays bounded
    CHECK(y <= 20.0);
  }
}

TEST_CASE("Spline: rotation angles interpolate as numbers, so several turns survive") {
  const Spline s({0.0, 0.5, 1.0}, {0.0, 360.0, 720.0}, false);
  CHECK(s(0.25) > 100.0);
  CHECK(s(1.0) == 720.0);
}

TEST_CASE("Spline: bad keys are InputError naming the key") {
  try {
    Spline({0.0, 0.5, 0.5}, {1.0, 2.0, 3.0}, false);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("[2]") != std::string::npos);
  }
  CHECK_THROWS_AS(Spline({}, {}, false), InputError);
  CHECK_THROWS_AS(Spline({0.0, 1.5}, {1.0, 2.0}, false), InputError);
  CHECK_THROWS_AS(Spline({0.0}, {1.0, 2.0}, false), InputError);
}
