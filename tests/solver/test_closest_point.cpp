// Ericson's closest point on a triangle: exact answers in each Voronoi region, then agreement with
// brute-force dense sampling of the triangle on random tilted triangles in (x, y, t).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "animpak/reference.hpp"

using namespace animpak;
using namespace animpak::reference;

namespace {

double dist(Vec3f a, Vec3f b) {
  const double dx = a.x - b.x, dy = a.y - b.y, dt = a.t - b.t;
  return std::sqrt(dx * dx + dy * dy + dt * dt);
}

// Distance from p to a dense barycentric sampling of the triangle (the brute-force truth).
double sampled_distance(Vec3f p, Vec3f a, Vec3f b, Vec3f c, int steps) {
  double best = 1e30;
  for (int i = 0; i <= steps; ++i) {
    for (int j = 0; i + j <= steps; ++j) {
      const double u = double(i) / steps, v = double(j) / steps, w = 1.0 - u - v;
      const Vec3f q{float(w * a.x + u * b.x + v * c.x), float(w * a.y + u * b.y + v * c.y),
                    float(w * a.t + u * b.t + v * c.t)};
      best = std::min(best, dist(p, q));
    }
  }
  return best;
}

void check_equal(Vec3f got, Vec3f want) {
  CHECK(got.x == Approx(want.x).margin(1e-6));
  CHECK(got.y == Approx(want.y).margin(1e-6));
  CHECK(got.t == Approx(want.t).margin(1e-6));
}

}  // namespace

TEST_CASE("closest point: every Voronoi region of a right triangle") {
  const Vec3f a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  SECTION("vertex a") { check_equal(closest_point_on_triangle({-1, -1, 0.5f}, a, b, c), a); }
  SECTION("vertex b") { check_equal(closest_point_on_triangle({2, -0.5f, 0.3f}, a, b, c), b); }
  SECTION("vertex c") { check_equal(closest_point_on_triangle({-0.5f, 2, 1}, a, b, c), c); }
  SECTION("edge ab") { check_equal(closest_point_on_triangle({0.5f, -1, 0.2f}, a, b, c), {0.5f, 0, 0}); }
  SECTION("edge ac") { check_equal(closest_point_on_triangle({-1, 0.5f, 0}, a, b, c), {0, 0.5f, 0}); }
  SECTION("edge bc") { check_equal(closest_point_on_triangle({1, 1, -0.7f}, a, b, c), {0.5f, 0.5f, 0}); }
  SECTION("face") { check_equal(closest_point_on_triangle({0.25f, 0.25f, 3}, a, b, c), {0.25f, 0.25f, 0}); }
  SECTION("on the triangle") { check_equal(closest_point_on_triangle({0.25f, 0.5f, 0}, a, b, c), {0.25f, 0.5f, 0}); }
}

TEST_CASE("closest point: a degenerate triangle gives a finite point") {
  const Vec3f a{0.5f, 0.5f, 0.5f};
  const Vec3f q = closest_point_on_triangle({0.2f, 0.1f, 0.9f}, a, a, a);
  check_equal(q, a);
  const Vec3f r = closest_point_on_triangle({0.2f, 0.1f, 0.9f}, {0, 0, 0}, {1, 1, 1}, {0.5f, 0.5f, 0.5f});
  CHECK((std::isfinite(r.x) && std::isfinite(r.y) && std::isfinite(r.t)));
}

TEST_CASE("closest point: matches dense sampling on random tilted triangles") {
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), wide(-0.5f, 1.5f);
  const int steps = 300;
  for (int trial = 0; trial < 60; ++trial) {
    const Vec3f a{unit(rng), unit(rng), unit(rng)}, b{unit(rng), unit(rng), unit(rng)},
        c{unit(rng), unit(rng), unit(rng)};
    const Vec3f p{wide(rng), wide(rng), wide(rng)};
    const Vec3f q = closest_point_on_triangle(p, a, b, c);
    const double got = dist(p, q), want = sampled_distance(p, a, b, c, steps);
    INFO("trial " << trial);
    // The sampling is a triangle point grid of spacing ≤ √3 / steps; Ericson's point can only be nearer.
    CHECK(got <= want + 1e-5);
    CHECK(got >= want - 2.0 / steps);
    // q lies on the triangle: its distance to the sampled triangle is within the grid spacing.
    CHECK(sampled_distance(q, a, b, c, steps) <= 2.0 / steps);
  }
}
