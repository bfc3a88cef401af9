// Coarse to fine (docs/parameters.md, "Coarse to fine"): the coarse level's size, and the fine state made
// from a coarse one: its slices on the coarse curve, its g and velocities between the coarse slices', its
// rest lengths from the fine rest copy, its loop pairs joined, settling from the refinement on.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "animpak/levels.hpp"
#include "scene/tiny_scenes.hpp"

using namespace animpak;

namespace {

// Three stars and two guided ones that loop into each other, 13 slices; with a collision grid of two cells
// a side the coarse level has four slices (t = 0, 1/3, 2/3, 1), those of fine slices 0, 4, 8 and 12.
std::string level_scene(const std::string& params = R"("cell_size": 0.5, "coarse_step": 4)") {
  return test::star_scene(3, 13, 4, test::swapping_pair(params));
}

World level_world(const std::string& text, int slices) {
  SceneSpec scene = parse_scene(text, "levels.json", "/");
  if (slices > 0) scene.params.element.slices = slices;
  return make_world(scene);
}

}  // namespace

TEST_CASE(
    "coarse_slices: about one slice per coarse_step, none below twice the grid's least or that saves too little") {
  Params p;
  CHECK(coarse_slices(p) == 26);  // 100 slices: 99 intervals / 4, rounded up, + 1
  p.element.slices = 74;
  CHECK(coarse_slices(p) == 20);  // twice the 10 slices 0.12 (three cells of 0.04) apart
  p.element.slices = 73;
  CHECK(coarse_slices(p) == 0);  // 19
  p.element.slices = 40;
  CHECK(coarse_slices(p) == 0);
  p.element.slices = 24;
  p.element.coarse_step = 2;
  CHECK(coarse_slices(p) == 0);  // 13: more than half of 24, and fewer than 20
  p.element.slices = 100;
  p.element.coarse_step = 1;
  CHECK(coarse_slices(p) == 0);
  p.element.coarse_step = 3;
  CHECK(coarse_slices(p) == 34);
  p.element.coarse_step = 6;
  CHECK(coarse_slices(p) == 0);  // 18
  p.forces.cell_size = 0.5;
  p.element.slices = 13;
  p.element.coarse_step = 4;
  CHECK(coarse_slices(p) == 4);
}

TEST_CASE(
    "refine_state: new slices on the coarse curve, g and speeds between the coarse slices', settling from there") {
  const std::string text = level_scene();
  const World coarse = level_world(text, coarse_slices(parse_scene(text, "levels.json", "/").params));
  const World fine = level_world(text, 0);
  REQUIRE(coarse.library.front().slice_count == 4);
  REQUIRE(fine.library.front().slice_count == 13);
  REQUIRE(level_mismatch(coarse, fine).empty());
  REQUIRE(fine.elements.size() == 5);

  // A coarse state that moved: every vertex by a periodic swing (so loop partners stay joined), its own g
  // per slice, velocities, and a stop test part way.
  SimState moved = coarse.state;
  for (std::size_t v = 0; v < moved.x.size(); ++v) {
    const double t = moved.t[v];
    moved.x[v] += static_cast<float>(0.02 * std::sin(2 * std::numbers::pi * t));
    moved.y[v] += static_cast<float>(0.01 * std::cos(2 * std::numbers::pi * t));
    moved.vx[v] = static_cast<float>(0.001 * (1 + t)), moved.vy[v] = -0.002f, moved.vt[v] = 0.0005f;
  }
  for (std::size_t s = 0; s < moved.growth.size(); ++s) moved.growth[s] = 2.0f + 0.25f * float(s % 4);
  moved.iteration = 730, moved.settling_since = 700, moved.secondary_since = 0;
  moved.mark_iteration = 720, moved.mark_growth = 2.5, moved.mark_growth_1 = 2.4;

  const SimState refined = refine_state(coarse, moved, fine);
  REQUIRE(refined.x.size() == fine.state.x.size());
  CHECK(refined.iteration == 730);
  // The coarse level's stop is the packing's: the scene's slices settle from the refinement on.
  CHECK(refined.settling_since == 730);
  CHECK(refined.mark_iteration == 720);
  CHECK(refined.mark_growth == 2.5);
  CHECK(refined.mark_growth_1 == 2.4);

  const Topology& ft = fine.topology;
  for (std::size_t e = 0; e < fine.elements.size(); ++e) {
    INFO("element " << fine.elements[e].name);
    const int P = fine.library[fine.elements[e].library].vertices_per_slice();
    const std::vector<Vec2> tangents = element_tangents(coarse, moved, int(e));
    for (int s = 0; s < 13; ++s) {
      INFO("fine slice " << s);
      const std::int32_t fs = fine.elements[e].slice_begin + s;
      const std::vector<Vec2> on_curve = element_at(coarse, moved, int(e), ft.rest_t[ft.slice_begin[fs]], tangents);
      for (int v = 0; v < P; ++v) {
        const std::size_t k = static_cast<std::size_t>(ft.slice_begin[fs] + v);
        CHECK(refined.x[k] == static_cast<float>(on_curve[v].x));
        CHECK(refined.y[k] == static_cast<float>(on_curve[v].y));
        CHECK(refined.t[k] == ft.rest_t[k]);
      }
      // Slices 0, 4, 8 and 12 are the coarse ones: their values exactly; the others a quarter of the way on.
      const std::int32_t c0 = coarse.elements[e].slice_begin + s / 4;
      const float share = float(s % 4) / 4.0f;
      const float g0 = moved.growth[c0], g1 = moved.growth[c0 + (s < 12 ? 1 : 0)];
      CHECK(refined.growth[fs] == Approx(g0 + (g1 - g0) * share).epsilon(1e-6));
      const std::size_t a = static_cast<std::size_t>(coarse.topology.slice_begin[c0]);
      const std::size_t k = static_cast<std::size_t>(ft.slice_begin[fs]);
      if (s % 4 == 0) {
        CHECK(refined.x[k] == moved.x[a]);
        CHECK(refined.vx[k] == moved.vx[a]);
        CHECK(refined.growth[fs] == moved.growth[c0]);
      } else {
        // Not vacuous: an in-between slice is not a copy of either coarse slice.
        CHECK(refined.x[k] != moved.x[a]);
      }
    }
  }
  // The loop constraint's pairs coincide, and every rest length is the fine rest copy's at the new g (§5.3).
  for (std::size_t i = 0; i < ft.loop_end.size(); ++i) {
    CHECK(refined.x[ft.loop_end[i]] == refined.x[ft.loop_start[i]]);
    CHECK(refined.y[ft.loop_end[i]] == refined.y[ft.loop_start[i]]);
  }
  for (std::int32_t v = 0; v < ft.vertex_count(); ++v)
    for (std::int32_t k = ft.spring_begin[v]; k < ft.spring_begin[v + 1]; ++k)
      REQUIRE(refined.spring_rest[k] == rest_copy_length(ft, refined.growth, v, k));
}

TEST_CASE("refine_state: worlds whose elements differ are refused, saying why") {
  const std::string text = level_scene();
  const World coarse = level_world(text, 4);
  const World other = level_world(test::star_scene(4, 13, 4, test::swapping_pair(R"("cell_size": 0.5)")), 0);
  CHECK_THAT(level_mismatch(coarse, other), Catch::Matchers::Contains("places 5 elements, the scene's slices 6"));
  CHECK_THROWS_AS(refine_state(coarse, coarse.state, other), std::invalid_argument);
}
