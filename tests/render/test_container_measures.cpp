// The frame measures of a packing whose container moves (docs/quality.md, "A container that moves"): art
// outside, coverage and the evenness measures are taken against the container where it is at each
// frame's and each point between slices' own time; the size over the script includes the container's
// scale when the elements inherit it. Built in memory from tiny scenes, without simulation steps.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "animpak/render.hpp"
#include "animpak/scene.hpp"
#include "scene/tiny_scenes.hpp"

using namespace animpak;

namespace {

// One library element of `count` stars (each turning once a loop) in the heart, whose container has the
// `animation` object and `inherit_scale`.
World moving_container_world(const std::string& animation, int count, int slices, bool inherit_scale = true) {
  const std::string text = R"({"container": {"art": ")" + test::example_file("shapes/heart-container.path") +
                           R"(", "animation": )" + animation + R"(, "inherit_scale": )" +
                           (inherit_scale ? "true" : "false") + R"(}, "elements": [{"name": "star", "art": ")" +
                           test::example_file("default/star.svg") + R"(", "count": )" + std::to_string(count) +
                           R"(, "animation": {"preset": "rotate", "turns": 1}}], "seed": 3, "slices": )" +
                           std::to_string(slices) + "}";
  return make_world(parse_scene(text, "moving-container.json", "/"));
}

// The same container standing still: how a measure that ignores the motion sees it.
Container container_at_rest(const Container& moving) {
  Container rest = moving;
  rest.motion = ContainerMotion();
  return rest;
}

// Every element's art at tf, as the frames draw it.
std::vector<Region> drawn_regions(const World& w, double tf) {
  std::vector<Region> regions;
  for (const ElementArt& art : frame_art(w, w.state, tf))
    regions.push_back(art_region(w.library[w.elements[regions.size()].library].art.art, art.points, art.stroke_scale));
  return regions;
}

}  // namespace

TEST_CASE(
    "measure_frame: a star carried far by a travelling container is inside it at every frame and between slices") {
  // The heart travels 400 art units (about 0.8 of its width) to the right and back over the loop: the
  // lone star, placed inside it at rest and carried by it at every slice, leaves the heart at rest.
  const World w = moving_container_world(
      R"({"keys": [{"t": 0, "translate": [0, 0]}, {"t": 0.5, "translate": [400, 0]}, {"t": 1, "translate": [0, 0]}]})",
      1, 9);
  REQUIRE(w.container.motion.moves());
  REQUIRE(w.container.motion.at(0.5).ex > 0.5);
  std::vector<double> times = frame_times(24, true);
  const std::vector<double> between = between_slice_times(9);
  times.insert(times.end(), between.begin(), between.end());
  const Container rest = container_at_rest(w.container);
  double far_out = 0.0;  // the largest share outside the heart at rest
  for (const double t : times) {
    const FrameMetrics m = measure_frame(w, w.state, t);
    INFO("t " << t << ": outside " << m.worst_outside().share);
    REQUIRE(m.outside_share.size() == 1);
    CHECK(m.elements_outside().empty());
    CHECK(m.outside_share[0] < 1e-9);
    far_out = std::max(far_out, measure_regions(drawn_regions(w, t), container_region(rest, t)).outside_share[0]);
  }
  // Against the heart at rest the star is wholly outside for much of the loop.
  CHECK(far_out > 0.99);
}

TEST_CASE("measure_frame: coverage and the evenness measures are the beating container's at each time") {
  // A pulse of amplitude 0.3 once a loop: the heart is 1.3 times its rest size at one time and 0.7 at
  // another, and its stars with it.
  const World w = moving_container_world(R"({"preset": "pulse", "amplitude": 0.3, "count": 1})", 3, 9);
  REQUIRE(w.container.motion.moves());
  const double rest_area = w.container.area();
  const Container rest = container_at_rest(w.container);
  double smallest = 10.0, largest = 0.0;
  for (const double t : frame_times(16, true)) {
    const double scale = w.container.motion.at(t).scale();
    smallest = std::min(smallest, scale), largest = std::max(largest, scale);
    const FrameMetrics m = measure_frame(w, w.state, t);
    INFO("t " << t << ", container scale " << scale);
    CHECK(m.elements_outside().empty());
    REQUIRE(m.overlapping().empty());  // the stars' art counts once each in the coverage below
    double art = 0.0;
    for (const double a : m.area) art += a;
    // All the art inside the moved heart: its coverage is the art over the heart's area at t, its rest
    // area times the scale squared.
    CHECK(m.coverage == Approx(art / (rest_area * scale * scale)).epsilon(1e-6));
    // Against the heart at rest the coverage would follow the stars' beat alone.
    const FrameMetrics still = measure_regions(drawn_regions(w, t), container_region(rest, t), Measures::no_evenness);
    if (std::abs(scale - 1.0) > 0.2) CHECK(std::abs(m.coverage - still.coverage) > 0.2 * m.coverage);
  }
  CHECK(smallest == Approx(0.7).margin(0.01));
  CHECK(largest == Approx(1.3).margin(0.01));
  // The largest empty disc over the element radius does not follow the beat: heart and stars scale
  // together. Against the heart at rest it would swing with the heart's area.
  const FrameMetrics low = measure_frame(w, w.state, 0.75), high = measure_frame(w, w.state, 0.25);
  REQUIRE(low.empty_disc());
  REQUIRE(high.empty_disc());
  CHECK(*low.empty_disc() == Approx(*high.empty_disc()).epsilon(0.02));
  const FrameMetrics low_rest = measure_regions(drawn_regions(w, 0.75), container_region(rest, 0.75)),
                     high_rest = measure_regions(drawn_regions(w, 0.25), container_region(rest, 0.25));
  REQUIRE(low_rest.empty_disc());
  REQUIRE(high_rest.empty_disc());
  CHECK(*low_rest.empty_disc() > 1.2 * *high_rest.empty_disc());
}

TEST_CASE("measure_motion: a beating container's elements that inherit its scale follow their script") {
  // The stars as set up, grown evenly by 1.1 at every slice: each beats with the heart, ((1.3 / 0.7))²
  // in area over the loop, and its size over the script is 1 because the script includes the heart's
  // scale at each slice's time (docs/quality.md, "A container that moves").
  const int slices = 9;
  World w = moving_container_world(R"({"preset": "pulse", "amplitude": 0.3, "count": 1})", 2, slices);
  const Topology& topo = w.topology;
  for (std::int32_t s = 0; s < topo.slice_count(); ++s) {
    const std::int32_t begin = topo.slice_begin[s], end = topo.slice_begin[s + 1];
    double cx = 0.0, cy = 0.0;
    for (std::int32_t v = begin; v < end; ++v) cx += w.state.x[v], cy += w.state.y[v];
    cx /= double(end - begin), cy /= double(end - begin);
    for (std::int32_t v = begin; v < end; ++v) {
      w.state.x[v] = static_cast<float>(cx + 1.1 * (w.state.x[v] - cx));
      w.state.y[v] = static_cast<float>(cy + 1.1 * (w.state.y[v] - cy));
    }
  }
  const std::vector<double> times = frame_times(16, true);
  std::vector<std::vector<Vec2>> centroids(w.elements.size());
  for (std::size_t e = 0; e < w.elements.size(); ++e)
    for (const double t : times)
      centroids[e].push_back(art_centroid(element_art(w, int(e), element_at(w, w.state, int(e), t))));
  const MotionMetrics m = measure_motion(w, w.state, centroids, times);
  REQUIRE(m.size_over_script.size() == 2);
  for (const double ratio : m.size_over_script) CHECK(ratio == Approx(1.0).epsilon(1e-4));
  // The stars' drawn size does beat: the slice at the heart's largest over the one at its smallest.
  const double big = element_scale(w, 0, element_at(w, w.state, 0, 0.25)),
               small = element_scale(w, 0, element_at(w, w.state, 0, 0.75));
  CHECK(big / small == Approx(1.3 / 0.7).epsilon(0.02));

  // Without inherit_scale the stars keep their size while the heart beats: their script does not beat
  // either, and the same measure reads 1 on their set-up.
  const World keep = moving_container_world(R"({"preset": "pulse", "amplitude": 0.3, "count": 1})", 2, slices, false);
  const MotionMetrics kept = measure_motion(keep, keep.state, centroids, times);
  for (const double ratio : kept.size_over_script) CHECK(ratio == Approx(1.0).epsilon(1e-4));
  CHECK(element_scale(keep, 0, element_at(keep, keep.state, 0, 0.25)) /
            element_scale(keep, 0, element_at(keep, keep.state, 0, 0.75)) ==
        Approx(1.0).epsilon(1e-3));
  // The beating stars measured against the script that does not beat: their size over it is the beat's.
  SimState beating_on_kept = w.state;
  const MotionMetrics against_kept = measure_motion(keep, beating_on_kept, centroids, times);
  for (const double ratio : against_kept.size_over_script)
    CHECK(ratio == Approx((1.3 / 0.7) * (1.3 / 0.7)).epsilon(0.03));
}

TEST_CASE("container_region: a container that does not move is its rings as they are, at every time") {
  const World w = moving_container_world(R"({"preset": "pulse", "amplitude": 0.3, "count": 1})", 1, 5);
  const Container still = container_at_rest(w.container);
  for (const double t : {0.0, 0.3, 0.5, 1.0}) {
    const Region r = container_region(still, t);
    REQUIRE(r.rings.size() == 1 + still.holes.size());
    CHECK(r.rings[0] == still.outline);  // bit for bit: a static container's measures are unchanged
    CHECK(r.rule == FillRule::evenodd);
  }
  // The moving one at t is its rest outline carried by the motion.
  const Region moved = container_region(w.container, 0.25);
  const Similarity m = w.container.motion.at(0.25);
  REQUIRE(moved.rings[0].size() == w.container.outline.size());
  for (std::size_t i = 0; i < moved.rings[0].size(); ++i) {
    CHECK(moved.rings[0][i].x == m.apply(w.container.outline[i]).x);
    CHECK(moved.rings[0][i].y == m.apply(w.container.outline[i]).y);
  }
}

TEST_CASE("measure_motion: a star a turning container carries neither strays nor travels in it") {
  // The heart turns once a loop about its art's origin, a corner of its box; the lone star rides it. In
  // the picture its centroid circles that corner; in the heart it stays where it was placed.
  const World w = moving_container_world(R"({"preset": "rotate", "turns": 1, "pivot": [0, 0]})", 1, 13);
  const std::vector<double> times = frame_times(48, true);
  std::vector<std::vector<Vec2>> centroids(1);
  for (const double t : times) centroids[0].push_back(art_centroid(element_art(w, 0, element_at(w, w.state, 0, t))));
  double seen = 0.0;  // the largest distance between two of the centroids as the frames show them
  for (const Vec2 a : centroids[0])
    for (const Vec2 b : centroids[0]) seen = std::max(seen, std::hypot(a.x - b.x, a.y - b.y));
  REQUIRE(seen > 0.05);
  const MotionMetrics m = measure_motion(w, w.state, centroids, times);
  REQUIRE(m.detour.size() == 1);
  INFO("detour " << m.detour[0] << ", path " << m.path_length[0] << ", across the picture " << seen);
  CHECK(m.detour[0] < 0.01 * seen);
  CHECK(m.path_length[0] < 0.01 * seen);
}
