// measure_motion (docs/quality.md, "Motion"): the kink of the centroids' motion, whether the slices show,
// and each element's size over its script.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "animpak/render.hpp"
#include "animpak/scene.hpp"
#include "scene/tiny_scenes.hpp"
#include "tiny_world.hpp"

using namespace animpak;

TEST_CASE("measure_motion: even circling has no kink, corners at the slices an infinite one") {
  const World world = tiny_star_world();  // 4 slices at t 0, 1/3, 2/3, 1; loops
  const std::vector<double> times = frame_times(60, true);
  std::vector<std::vector<Vec2>> circling(world.elements.size()), cornering(world.elements.size());
  for (std::size_t e = 0; e < world.elements.size(); ++e)
    for (const double t : times) {
      const double a = 2.0 * std::numbers::pi * t;
      circling[e].push_back({0.5 + 0.2 * std::cos(a), 0.5 + 0.2 * std::sin(a)});
      // Straight from slice to slice through three corners, as the paper's interpolation moves.
      const double u = t * 3.0 - std::floor(t * 3.0);
      const Vec2 corners[] = {{0.2, 0.2}, {0.8, 0.2}, {0.5, 0.8}, {0.2, 0.2}};
      const int k = static_cast<int>(std::floor(t * 3.0));
      cornering[e].push_back(corners[k] + (corners[k + 1] - corners[k]) * u);
    }
  const MotionMetrics smooth = measure_motion(world, world.state, circling, times);
  CHECK(smooth.kink() == Approx(1.0).epsilon(1e-6));
  CHECK(smooth.slice_ratio == Approx(1.0).epsilon(1e-6));
  const MotionMetrics jolting = measure_motion(world, world.state, cornering, times);
  CHECK(jolting.acceleration_median == Approx(0.0).margin(1e-12));
  CHECK(jolting.kink() > 1e6);
  CHECK(jolting.slice_ratio > 1e3);
}

TEST_CASE("measure_motion: across the loop's seam an element continues as the element it loops into") {
  // Two guided stars that swap places and loop into each other: each runs half a circle, together one
  // circle a loop, so at the seam each one's next frame is the other's first.
  const World world =
      make_world(parse_scene(animpak::test::star_scene(0, 5, 3, animpak::test::swapping_pair()), "tiny.json", "/"));
  REQUIRE(world.elements.size() == 2);
  const std::vector<double> times = frame_times(60, true);
  std::vector<std::vector<Vec2>> halves(2);
  for (std::size_t e = 0; e < 2; ++e)
    for (const double t : times) {
      const double a = std::numbers::pi * (t + double(e));
      halves[e].push_back({0.5 + 0.2 * std::cos(a), 0.5 + 0.2 * std::sin(a)});
    }
  // Read element by element, each would jump across the circle at the seam: the four jumps alone would
  // set the 99th percentile of the 120 element-frames.
  const MotionMetrics m = measure_motion(world, world.state, halves, times);
  CHECK(m.kink() == Approx(1.0).epsilon(1e-6));
}

TEST_CASE("measure_motion: an element's size over its script, largest over smallest over its slices") {
  World world = tiny_star_world();
  const std::vector<std::vector<Vec2>> still(world.elements.size(), std::vector<Vec2>(3, Vec2{0.5, 0.5}));
  const std::vector<double> times = frame_times(3, true);
  // As placed, every element is its script: 1.
  for (const double r : measure_motion(world, world.state, still, times).size_over_script) CHECK(r == Approx(1.0));
  // Element 1's second slice grown by 10 % about its first vertex: its area by 21 % against the others.
  const Topology& topo = world.topology;
  const std::int32_t s = topo.element_slice_begin[1] + 1, lo = topo.slice_begin[s];
  for (std::int32_t v = lo; v < topo.slice_begin[s + 1]; ++v) {
    world.state.x[v] = world.state.x[lo] + 1.1f * (world.state.x[v] - world.state.x[lo]);
    world.state.y[v] = world.state.y[lo] + 1.1f * (world.state.y[v] - world.state.y[lo]);
  }
  const MotionMetrics m = measure_motion(world, world.state, still, times);
  CHECK(m.size_over_script[1] == Approx(1.21).epsilon(1e-4));
  CHECK(m.size_over_script[0] == Approx(1.0));
}

TEST_CASE("measure_motion: with a slice next to every frame the slices' visibility is not a number") {
  const World world = tiny_star_world();                   // 4 slices
  const std::vector<double> times = frame_times(4, true);  // every frame within a frame of a slice time
  std::vector<std::vector<Vec2>> moving(world.elements.size());
  for (auto& c : moving)
    for (const double t : times) c.push_back({0.5 + 0.1 * t * t, 0.5});
  CHECK(std::isnan(measure_motion(world, world.state, moving, times).slice_ratio));
}

TEST_CASE("element_path: the art centroid the frames are measured at, following the slices as they move") {
  World world = tiny_star_world();  // 4 slices at t 0, 1/3, 2/3, 1
  const std::vector<double> times = frame_times(12, true);
  const std::vector<Vec2> before = element_path(world, world.state, 1, times);
  for (std::size_t i = 0; i < times.size(); ++i) {
    const Vec2 framed = art_centroid(frame_art(world, world.state, times[i])[1]);
    CHECK(before[i].x == Approx(framed.x).margin(1e-9));
    CHECK(before[i].y == Approx(framed.y).margin(1e-9));
  }
  // Slice s of element 1 moved s · (6, −4): at the slice times its path moves with it.
  const Topology& topo = world.topology;
  std::vector<double> slice_times;
  for (std::int32_t s = topo.element_slice_begin[1]; s < topo.element_slice_begin[2]; ++s) {
    const int k = s - topo.element_slice_begin[1];
    slice_times.push_back(world.state.t[topo.slice_begin[s]]);
    for (std::int32_t v = topo.slice_begin[s]; v < topo.slice_begin[s + 1]; ++v)
      world.state.x[v] += 6.0f * float(k), world.state.y[v] -= 4.0f * float(k);
  }
  slice_times.pop_back();  // the last slice is t = 1, where a looping path is back at frame 0's slice
  const World base = tiny_star_world();
  const std::vector<Vec2> still = element_path(base, base.state, 1, slice_times),
                          moved = element_path(world, world.state, 1, slice_times);
  for (std::size_t k = 0; k < slice_times.size(); ++k) {
    CHECK(moved[k].x - still[k].x == Approx(6.0 * double(k)).margin(1e-3));
    CHECK(moved[k].y - still[k].y == Approx(-4.0 * double(k)).margin(1e-3));
  }
}

TEST_CASE("loop_neighbours: a swapping pair loops into each other, any other element into itself") {
  const World pair =
      make_world(parse_scene(animpak::test::star_scene(1, 5, 3, animpak::test::swapping_pair()), "tiny.json", "/"));
  REQUIRE(pair.elements.size() == 3);
  int up = -1, down = -1, star = -1;
  for (std::size_t e = 0; e < pair.elements.size(); ++e)
    (pair.elements[e].name == "up" ? up : pair.elements[e].name == "down" ? down : star) = int(e);
  REQUIRE((up >= 0 && down >= 0 && star >= 0));
  const std::vector<LoopNeighbours> loops = loop_neighbours(pair);
  REQUIRE(loops.size() == 3);
  CHECK(loops[up].into == down);
  CHECK(loops[up].from == down);
  CHECK(loops[down].into == up);
  CHECK(loops[star].into == star);
  CHECK(loops[star].from == star);
}

TEST_CASE("measure_motion: how far each element strays from its mean place and its path per loop") {
  const World world = tiny_star_world();  // loops: the path closes from the last frame to the first
  const std::vector<double> times = frame_times(60, true);
  std::vector<std::vector<Vec2>> moves(world.elements.size());
  for (std::size_t e = 0; e < world.elements.size(); ++e)
    for (const double t : times) {
      // Element 0 stands still; the others circle with radius 0.1 e about (0.5, 0.5).
      const double a = 2.0 * std::numbers::pi * t, r = 0.1 * double(e);
      moves[e].push_back({0.5 + r * std::cos(a), 0.5 + r * std::sin(a)});
    }
  const MotionMetrics m = measure_motion(world, world.state, moves, times);
  REQUIRE(m.detour.size() == world.elements.size());
  REQUIRE(m.path_length.size() == world.elements.size());
  CHECK(m.detour[0] == Approx(0.0).margin(1e-12));
  CHECK(m.path_length[0] == Approx(0.0).margin(1e-12));
  for (std::size_t e = 1; e < world.elements.size(); ++e) {
    CHECK(m.detour[e] == Approx(0.1 * double(e)).epsilon(1e-9));
    // 60 chords of a circle, the seam's included: 120 r sin(π/60).
    CHECK(m.path_length[e] == Approx(120.0 * 0.1 * double(e) * std::sin(std::numbers::pi / 60.0)).epsilon(1e-9));
    CHECK_FALSE(m.guided[e]);
  }
}
