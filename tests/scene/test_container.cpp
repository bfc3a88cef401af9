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

TEST_CASE("mirror_container: the kept side with the line as its wall, the whole as it and its image, and its errors") {
  const Container whole = make_container(frame_with_hole(), {});
  // The 200 × 100 frame's hole spans x 60–100: a line at x = 80 cuts it, so the kept side has a notch
  // instead of a hole, and its image on the right has one too.
  const Container left = mirror_container(whole, {true, 80.0, true}, "scene.json");
  REQUIRE(left.mirror);
  CHECK(left.mirror->vertical);
  CHECK(left.mirror->at == Approx(whole.frame.to_unit({80, 0}).x));
  CHECK(left.holes.empty());
  const double unit = whole.frame.scale * whole.frame.scale;  // art units² → unit²
  CHECK(left.area() == Approx((80.0 * 100 - 20 * 40) * unit));
  const Box kept = left.bounds();
  CHECK(kept.max.x == Approx(left.mirror->at).margin(1e-8));
  // The shown container: the kept side and its image, 160 wide with the hole's two halves as one hole.
  CHECK(left.shown_holes().size() == 1);
  CHECK(std::abs(signed_area(left.shown_outline())) == Approx(160.0 * 100 * unit));
  CHECK(left.shown_bounds().width() == Approx(160 * whole.frame.scale));
  // Every vertex of the kept side reflects onto the shown outline's side of the line.
  for (Vec2 p : left.outline) CHECK(left.mirror->reflect(p).x >= left.mirror->at - 1e-8);

  // The other side, and a horizontal line.
  const Container right = mirror_container(whole, {true, 150.0, false}, "scene.json");
  CHECK(right.area() == Approx(50.0 * 100 * unit));
  CHECK(right.bounds().min.x == Approx(right.mirror->at).margin(1e-8));
  const Container top = mirror_container(whole, {false, 50.0, true}, "scene.json");
  CHECK_FALSE(top.mirror->vertical);
  CHECK(top.area() == Approx((200.0 * 50 - 40 * 20) * unit));
  CHECK(std::abs(signed_area(top.shown_outline())) == Approx(200.0 * 100 * unit));

  // A line outside the container, and a cut that leaves two pieces.
  CHECK_THROWS_WITH(mirror_container(whole, {true, 250.0, true}, "scene.json"),
                    Catch::Contains("scene.json: mirror: the line x = 250 misses the container") &&
                        Catch::Contains("spans x 0 to 200"));
  ArtShape u;
  u.source = "u.path";
  u.paths.push_back(ring_path(0, {{0, 0}, {100, 0}, {100, 100}, {70, 100}, {70, 20}, {30, 20}, {30, 100}, {0, 100}}));
  CHECK_THROWS_WITH(mirror_container(make_container(u, {}), {false, 60.0, false}, "u.json"),
                    Catch::Contains("2 separate pieces") && Catch::Contains("move the mirror line"));
}
