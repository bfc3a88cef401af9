#include <catch2/catch.hpp>

#include "animpak/error.hpp"
#include "animpak/scene.hpp"

using namespace animpak;

namespace {

ArtPath ring_path(int index, std::vector<Vec2> points, int type = 0) {
  ArtPath p;
  p.id = "path" + std::to_string(index);
  p.source_index = index;
  p.path_type = type;
  p.polylines.push_back({std::move(points), true});
  return p;
}

// A 200 × 100 frame (art units) with a 40 × 40 hole in its left half.
ArtShape frame_with_hole() {
  ArtShape art;
  art.source = "frame.path";
  art.paths.push_back(ring_path(1, {{60, 30}, {100, 30}, {100, 70}, {60, 70}}, 7));
  art.paths.push_back(ring_path(0, {{0, 0}, {200, 0}, {200, 100}, {0, 100}}));
  return art;
}

}  // namespace

TEST_CASE("make_container: normalizes the longer side to 1, centred, and finds type-7 holes") {
  const Container c = make_container(frame_with_hole(), {});
  REQUIRE(c.holes.size() == 1);
  CHECK(c.outline_path == 0);  // by source index: the frame is drawn after its hole
  CHECK(c.hole_paths == std::vector<int>{1});
  const Box box = c.bounds();
  CHECK(box.width() == Approx(1.0));
  CHECK(box.height() == Approx(0.5));
  CHECK(box.min.y == Approx(0.25));
  CHECK(c.area() == Approx(0.5 - 0.2 * 0.2));
  CHECK(c.contains({0.1, 0.5}));
  CHECK_FALSE(c.contains({0.4, 0.5}));  // inside the hole
  CHECK_FALSE(c.contains({0.5, 0.1}));  // above the frame
  CHECK(c.distance_to_boundary({0.4, 0.5}) == Approx(0.1));
  CHECK(c.frame.to_unit({200, 100}).x == Approx(1.0));
}

TEST_CASE("make_container: explicit outline and holes by source index, and their errors") {
  ContainerSpec spec;
  spec.outline = 0;
  spec.holes = std::vector<int>{};
  CHECK(make_container(frame_with_hole(), spec).holes.empty());
  CHECK(make_container(frame_with_hole(), spec).outline_path == 0);
  spec.outline = 5;
  CHECK_THROWS_WITH(make_container(frame_with_hole(), spec),
                    Catch::Contains("frame.path: path 5") && Catch::Contains("container.outline"));
  spec.outline = 1;
  spec.holes = std::vector<int>{0};
  CHECK_THROWS_WITH(make_container(frame_with_hole(), spec), Catch::Contains("not inside the container outline"));

  ArtShape flat;
  flat.source = "flat.svg";
  flat.paths.push_back(ring_path(0, {{0, 0}, {1, 1}, {2, 2}}));
  CHECK_THROWS_WITH(make_container(flat, {}), Catch::Contains("flat.svg"));
}

TEST_CASE("poisson_disk: samples are inside, apart, off the boundary, cover the room, and repeat per seed") {
  const Container c = make_container(frame_with_hole(), {});
  const double r = 0.08, margin = 0.03;
  Rng rng(42);
  const std::vector<Vec2> points = poisson_disk(c, r, margin, rng);
  REQUIRE(points.size() > 20);
  for (std::size_t i = 0; i < points.size(); ++i) {
    INFO(i);
    CHECK(c.contains(points[i]));
    CHECK(c.distance_to_boundary(points[i]) >= margin);
    for (std::size_t j = 0; j < i; ++j) CHECK(norm(points[i] - points[j]) >= r);
  }
  // Coverage: every admissible place is within 2r of a sample (Bridson leaves no larger gap).
  for (double y = 0.0; y <= 1.0; y += 0.01)
    for (double x = 0.0; x <= 1.0; x += 0.01) {
      const Vec2 p{x, y};
      if (!c.contains(p) || c.distance_to_boundary(p) < margin) continue;
      double nearest = 1e9;
      for (Vec2 s : points) nearest = std::min(nearest, norm(s - p));
      INFO(x << ", " << y);
      CHECK(nearest < 2 * r);
    }
  Rng again(42);
  CHECK(poisson_disk(c, r, margin, again) == points);
  Rng other(43);
  CHECK(poisson_disk(c, r, margin, other) != points);
}

TEST_CASE("Rng: same seed, same numbers, uniform stays in range, below has no bias at the edges") {
  Rng a(7), b(7);
  for (int i = 0; i < 100; ++i) CHECK(a.next() == b.next());
  Rng c(9);
  int low = 0, high = 0;
  for (int i = 0; i < 20000; ++i) {
    const double u = c.uniform();
    REQUIRE(u >= 0.0);
    REQUIRE(u < 1.0);
    const auto k = c.below(3);
    REQUIRE(k < 3);
    low += k == 0;
    high += k == 2;
  }
  CHECK(std::abs(low - high) < 600);
}
