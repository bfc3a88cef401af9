// Unguided elements make way for guided ones (docs/parameters.md, "Making way"): seeds over the whole
// container, the guided paths included, and starts that step aside while a traveller passes and come
// back after, periodic round the loop; params.make_way 0 keeps the paper's seeds (§4) and straight starts.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "animpak/scene.hpp"
#include "scene/tiny_scenes.hpp"

using namespace animpak;

namespace {

constexpr int kCrossingSlices = 17;

// Twelve still stars in the heart and a guided star that crosses it left to right by t = 0.5 and comes
// back by t = 1, looping into itself.
std::string crossing_scene(const std::string& params, bool loop = true) {
  const std::string targets = loop ? R"([{"x": 110, "y": 230, "t": 0}, {"x": 390, "y": 230, "t": 0.5},
                                         {"x": 110, "y": 230, "t": 1}])"
                                   : R"([{"x": 110, "y": 230, "t": 0}, {"x": 390, "y": 230, "t": 1}])";
  animpak::test::SceneExtras extras{R"(, "guided": [{"name": "traveller", "element": "star", "targets": )" + targets +
                                        "}]" + (loop ? R"(, "loop": true)" : R"(, "loop": false)"),
                                    params};
  return animpak::test::star_scene(12, kCrossingSlices, 5, extras, loop ? R"({"loop": true})" : "{}");
}

World crossing_world(const std::string& text) { return make_world(parse_scene(text, "crossing.json", "/")); }

// Making way as docs/parameters.md ("Making way") suggests turning it on, with `more` params after it.
std::string making_way(const std::string& more = "") {
  return std::string(R"("make_way": 0.2)") + (more.empty() ? "" : ", " + more);
}

// Element e's slice centroids (the mean of its rest copy's slice vertices, as placed).
std::vector<Vec2> centres(const World& w, std::size_t e) {
  std::vector<Vec2> out;
  for (std::int32_t s = w.topology.element_slice_begin[e]; s < w.topology.element_slice_begin[e + 1]; ++s)
    out.push_back({w.topology.slice_rest_copy_cx[s], w.topology.slice_rest_copy_cy[s]});
  return out;
}

// The smallest distance from an unguided element's seed to the traveller's path (its slice centroids,
// joined by straight lines).
double closest_seed_to_path(const World& w) {
  const std::vector<Vec2> path = centres(w, 0);
  double closest = std::numeric_limits<double>::infinity();
  for (std::size_t e = 1; e < w.elements.size(); ++e)
    for (std::size_t s = 0; s + 1 < path.size(); ++s)
      closest = std::min(closest, segment_distance(w.elements[e].position, path[s], path[s + 1]));
  return closest;
}

}  // namespace

TEST_CASE(
    "make_way: seeds land on a guided element's path, which make_way 0 (the default) keeps them off, as the "
    "paper does") {
  const World w = crossing_world(crossing_scene(making_way()));
  REQUIRE(w.elements.size() == 13);
  REQUIRE(w.elements[0].guided);
  const World paper = crossing_world(crossing_scene(""));  // make_way 0, the default
  INFO("closest seed to the path: " << closest_seed_to_path(w) << ", with make_way 0 " << closest_seed_to_path(paper));
  // The seeds are spread over the whole heart, about 0.2 apart: one lies within a fifth of that of the path.
  CHECK(closest_seed_to_path(w) < 0.04);
  CHECK(closest_seed_to_path(paper) > 0.08);
}

TEST_CASE(
    "make_way: an element seeded on the path is out of the traveller's way when it passes, home after, "
    "periodic") {
  const World w = crossing_world(crossing_scene(making_way()));
  const std::vector<Vec2> traveller = centres(w, 0);
  int near_path = 0;
  for (std::size_t e = 1; e < w.elements.size(); ++e) {
    const std::vector<Vec2> c = centres(w, e);
    const Vec2 seed = w.elements[e].position;
    INFO(w.elements[e].name << " seeded at " << seed.x << ", " << seed.y);
    // Periodic: the last slice is the first, bit for bit (it loops into itself).
    CHECK(std::memcmp(&c.front(), &c.back(), sizeof(Vec2)) == 0);
    double nearest_seed = std::numeric_limits<double>::infinity(), nearest = nearest_seed;
    for (int s = 0; s < kCrossingSlices; ++s) {
      nearest_seed = std::min(nearest_seed, norm(seed - traveller[s]));
      nearest = std::min(nearest, norm(c[s] - traveller[s]));
      // Where the traveller is far away, the element is at its seed (a still star's centroid).
      if (norm(seed - traveller[s]) > 0.45) CHECK(norm(c[s] - seed) < 0.01);
    }
    // Out of the traveller's way: never nearer it than two shrunken stars' reach, and an element that a
    // straight start would have left in its way (a straight start keeps its seed) stays well clear of it.
    CHECK(nearest > 0.05);
    if (nearest_seed < 0.05) {
      ++near_path;
      CHECK(nearest > std::max(0.08, 1.8 * nearest_seed));
    }
  }
  CHECK(near_path > 0);
}

TEST_CASE("make_way: without a loop the path steps aside as well and need not close") {
  const World w = crossing_world(crossing_scene(making_way(), false));
  const std::vector<Vec2> traveller = centres(w, 0);
  double closest = std::numeric_limits<double>::infinity(), moved = 0.0;
  for (std::size_t e = 1; e < w.elements.size(); ++e) {
    const std::vector<Vec2> c = centres(w, e);
    for (int s = 0; s < kCrossingSlices; ++s) {
      closest = std::min(closest, norm(c[s] - traveller[s]));
      moved = std::max(moved, norm(c[s] - w.elements[e].position));
    }
  }
  CHECK(closest > 0.05);
  CHECK(moved > 0.05);
}

TEST_CASE("make_way: a scene without guided elements is placed exactly as with make_way 0") {
  const std::string plain = animpak::test::star_scene(12, kCrossingSlices, 5);
  const World a = crossing_world(animpak::test::star_scene(12, kCrossingSlices, 5, {"", making_way()}));
  const World b = crossing_world(plain);
  REQUIRE(a.state.x.size() == b.state.x.size());
  CHECK(std::memcmp(a.state.x.data(), b.state.x.data(), a.state.x.size() * sizeof(float)) == 0);
  CHECK(std::memcmp(a.state.y.data(), b.state.y.data(), a.state.y.size() * sizeof(float)) == 0);
  CHECK(std::memcmp(a.topology.rest_copy_x.data(), b.topology.rest_copy_x.data(),
                    a.topology.rest_copy_x.size() * sizeof(float)) == 0);
}

TEST_CASE(
    "make_way_dip: an element's script shrinks while the traveller passes it, by at most the dip, and only "
    "then") {
  const auto area = [](const World& w, std::int32_t s) {
    const std::int32_t first = w.topology.slice_begin[s], count = w.topology.slice_boundary[s];
    std::vector<Vec2> ring;
    for (std::int32_t v = first; v < first + count; ++v)
      ring.push_back({w.topology.rest_copy_x[v], w.topology.rest_copy_y[v]});
    return std::abs(signed_area(ring));
  };
  const World plain = crossing_world(crossing_scene(making_way(R"("make_way_dip": 1)")));
  for (const ElementInstance& e : plain.elements) CHECK(e.dip == 1.0);
  const World w = crossing_world(crossing_scene(making_way(R"("make_way_dip": 1.5)")));
  const std::vector<Vec2> traveller = centres(w, 0);
  int dipped = 0;
  for (std::size_t e = 1; e < w.elements.size(); ++e) {
    INFO(w.elements[e].name);
    CHECK(w.elements[e].dip >= 1.0 / 1.5 - 1e-9);
    const std::vector<Vec2> c = centres(w, e);
    double largest = 0.0, smallest = std::numeric_limits<double>::infinity();
    for (int s = 0; s < kCrossingSlices; ++s) {
      const double a = area(w, w.topology.element_slice_begin[e] + s);
      largest = std::max(largest, a), smallest = std::min(smallest, a);
    }
    // The stars are still: the rest copy's area changes only by the dip, as the square of the scale.
    CHECK(smallest / largest == Approx(w.elements[e].dip * w.elements[e].dip).epsilon(1e-3));
    for (int s = 0; s < kCrossingSlices; ++s) {
      const double a = area(w, w.topology.element_slice_begin[e] + s);
      // Far from the traveller (more than half the heart away), at full size.
      if (norm(c[s] - traveller[s]) > 0.5) CHECK(a == Approx(largest).epsilon(1e-4));
    }
    if (w.elements[e].dip < 0.9) ++dipped;
  }
  CHECK(dipped > 0);
}
