#include <catch2/catch.hpp>

#include <cmath>

#include "animpak/animation.hpp"
#include "animpak/error.hpp"
#include "animpak/io.hpp"
#include "element/fixtures.hpp"

using namespace animpak;

namespace {

std::vector<Vec2> slice_positions(const SpacetimeElement& e, int s) {
  std::vector<Vec2> p;
  for (int v = 0; v < e.vertices_per_slice(); ++v) p.push_back(e.position(s, v));
  return p;
}

}  // namespace

TEST_CASE("build_element: bird.path without animation has consistent counts and replays its art") {
  const ArtShape art = load_path_file(test::shape_path("bird"));
  Params params;
  params.element.slices = 12;
  const SpacetimeElement e = build_element("bird", art, AnimationSpec{}, params, 7);
  CHECK(e.name == "bird");
  REQUIRE(e.slice_count == 12);
  REQUIRE(e.vertices_per_slice() > 10);
  CHECK(e.x.size() == static_cast<std::size_t>(e.vertex_count()));
  CHECK(e.y.size() == e.x.size());
  CHECK(e.t.size() == e.x.size());
  CHECK(e.t[e.id(11, 0)] == 1.0);
  const auto replayed = replay_art(e.binding, e.slice, slice_positions(e, 0));
  double worst = 0.0;
  for (std::size_t p = 0; p < replayed.size(); ++p)
    for (std::size_t q = 0; q < replayed[p].size(); ++q)
      for (std::size_t k = 0; k < replayed[p][q].size(); ++k)
        worst = std::max(worst, norm(replayed[p][q][k] - e.art.art.paths[p].polylines[q].points[k]));
  CHECK(worst < 1e-6);
}

TEST_CASE("build_element: every animal swims and rotates through ARAP without degenerating") {
  Params params;
  params.element.slices = 16;
  for (const std::string& name : test::animal_names()) {
    INFO(name);
    const ArtShape art = load_path_file(test::shape_path(name));
    AnimationSpec spec;
    spec.preset = AnimationPreset::swim;
    spec.amplitude = 0.1;
    const SpacetimeElement e = build_element(name, art, spec, params, 3);
    double worst = 0.0;
    for (int s = 0; s < e.slice_count; ++s) {
      const auto p = slice_positions(e, s);
      for (const Edge& edge : e.slice.edges) {
        const double rest = norm(e.slice.vertices[edge[0]] - e.slice.vertices[edge[1]]);
        worst = std::max(worst, std::fabs(norm(p[edge[0]] - p[edge[1]]) / rest - 1.0));
      }
      for (const Vec2 q : p) CHECK((std::isfinite(q.x) && std::isfinite(q.y)));
    }
    CHECK(worst < 0.5);
    CHECK(slice_positions(e, 0) == slice_positions(e, e.slice_count - 1));
  }
}

TEST_CASE("build_element: animation errors name the element and its art file") {
  const ArtShape art = test::square_art();
  AnimationSpec spec;
  spec.preset = AnimationPreset::rotate;
  spec.turns = 1.5;
  CHECK_THROWS_WITH(build_element("box", art, spec, Params{}, 1), Catch::Contains("element 'box'") &&
                                                                      Catch::Contains("square.svg") &&
                                                                      Catch::Contains("animation.turns"));
}
