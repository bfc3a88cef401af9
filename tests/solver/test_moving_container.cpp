// A container that moves (docs/scene-format.md, "A container that moves"): the reference's container
// query at a vertex's own t, elements carried by the container's motion at set-up, and a packing that
// keeps a lone element inside the container at every slice and between slices while the container
// travels, turns and scales.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "animpak/container_motion.hpp"
#include "animpak/reference/boundary.hpp"
#include "animpak/scene.hpp"
#include "animpak/simulation.hpp"
#include "scene/tiny_scenes.hpp"
#include "tiny_worlds.hpp"

using namespace animpak;
using animpak::test::WorldBuilder;

namespace {

// A motion that moves by `shift` (unit coordinates) from t = 0 to t = 1, in a straight line.
ContainerMotion sliding(Vec2 shift) {
  AnimationSpec spec;
  spec.loop = false;
  spec.keys = {TransformKey{0.0, {0.0, 0.0}, 0.0, 1.0}, TransformKey{1.0, shift, 0.0, 1.0}};
  return ContainerMotion(spec, {0.5, 0.5}, 1.0, false);
}

void set_motion(ContainerGeometry& box, const ContainerMotion& motion) {
  for (const Similarity& m : motion.table()) {
    box.motion_a.push_back(static_cast<float>(m.a));
    box.motion_b.push_back(static_cast<float>(m.b));
    box.motion_ex.push_back(static_cast<float>(m.ex));
    box.motion_ey.push_back(static_cast<float>(m.ey));
  }
}

// Inside the container as it is at time t: taken back to the container at rest by the motion at t.
bool inside_at(const Container& c, Vec2 p, double t) { return c.contains(c.motion.at(t).inverse(p)); }

std::string moving_star_scene(const std::string& container_animation, const std::string& extra = "") {
  return R"({"container": {"art": ")" + test::example_file("shapes/heart-container.path") + R"(", "animation": )" +
         container_animation + extra + R"(}, "elements": [{"name": "star", "art": ")" +
         test::example_file("default/star.svg") +
         R"(", "count": 1, "animation": {"preset": "rotate", "turns": 1}}], "seed": 2, "slices": 8,
         "params": {"initial_scale": 0.3}})";
}

double slice_rest_area(const World& w, int slice) {
  const Topology& topo = w.topology;
  double area = 0.0;
  const std::int32_t lo = topo.slice_begin[slice], hi = topo.slice_begin[slice + 1];
  for (std::size_t k = 0; k < topo.tri_a.size(); ++k) {
    if (topo.tri_a[k] < lo || topo.tri_a[k] >= hi) continue;
    const auto at = [&](std::int32_t v) { return Vec2{topo.rest_copy_x[v], topo.rest_copy_y[v]}; };
    const Vec2 a = at(topo.tri_a[k]), b = at(topo.tri_b[k]), c = at(topo.tri_c[k]);
    area += 0.5 * std::abs(cross(b - a, c - a));
  }
  return area;
}

}  // namespace

TEST_CASE("moving container: the reference query takes a point to the container at rest at its own time") {
  WorldBuilder b;
  b.set_container({test::square(0.5f, 0.5f, 0.5f)});  // [0, 1]² at rest
  b.add_element({{{{0.5f, 0.5f}, {0.6f, 0.5f}, {0.5f, 0.6f}}, 0.5f}}, false);
  test::TinyWorld w = b.build();
  set_motion(w.topo.container, sliding({2.0, 0.0}));  // at t = 1 the square is [2, 3] × [0, 1]
  const ContainerGeometry& box = w.topo.container;
  // (2.5, 0.5) is outside at t = 0 and inside at t = 1; at t = 0.5 the square is [1, 2] × [0, 1].
  CHECK_FALSE(reference::container_query(box, 2.5f, 0.5f, 0.0f, false).inside);
  CHECK(reference::container_query(box, 2.5f, 0.5f, 1.0f, false).inside);
  CHECK(reference::container_query(box, 1.5f, 0.5f, 0.5f, false).inside);
  CHECK_FALSE(reference::container_query(box, 0.5f, 0.5f, 0.5f, false).inside);
  // The nearest point is brought back to the point's time, and its distance measured there.
  const reference::ContainerQuery q = reference::container_query(box, 3.25f, 0.5f, 1.0f, true);
  CHECK_FALSE(q.inside);
  CHECK(q.qx == Approx(3.0f).margin(1e-5));
  CHECK(q.qy == Approx(0.5f).margin(1e-5));
  CHECK(q.distance2 == Approx(0.0625f).margin(1e-5));
  // A boundary edge that leaves the moved square crosses it; the same edge at t = 0 lies outside.
  CHECK(reference::edge_crosses_container(box, 2.9f, 0.5f, 3.1f, 0.5f, 1.0f));
  CHECK_FALSE(reference::edge_crosses_container(box, 2.9f, 0.5f, 3.1f, 0.5f, 0.0f));
  // Containment puts a vertex outside the square of its own time back just inside that square.
  w.state.x = {3.2f, 1.5f, 0.5f};
  w.state.y = {0.5f, 0.5f, 0.5f};
  w.state.t = {1.0f, 0.5f, 0.5f};
  reference::apply_containment(w.topo, w.state);
  CHECK(w.state.x[0] < 3.0f);
  CHECK(w.state.x[0] > 2.99f);
  CHECK(w.state.x[1] == 1.5f);                       // inside the square of t = 0.5: untouched
  CHECK(w.state.x[2] == Approx(1.0f).margin(1e-3));  // outside it at t = 0.5: onto its left edge
}

TEST_CASE("moving container: the motion table interpolates linearly, loops exactly and composes preset and keys") {
  AnimationSpec pulse;
  pulse.preset = AnimationPreset::pulse;
  pulse.amplitude = 0.2;
  pulse.count = 2;
  const ContainerMotion beat(pulse, {0.4, 0.6}, 2.0, true);
  REQUIRE(beat.moves());
  REQUIRE(beat.table().size() == static_cast<std::size_t>(kContainerMotionIntervals + 1));
  CHECK(beat.at(0.125).scale() == Approx(1.2).epsilon(1e-9));  // sin(2π · 2 · 1/8) = 1
  CHECK(beat.at(0.375).scale() == Approx(0.8).epsilon(1e-9));
  CHECK(beat.min_scale() == Approx(0.8).epsilon(1e-6));
  CHECK(beat.max_scale() == Approx(1.2).epsilon(1e-6));
  const Vec2 pivot = beat.at(0.3).apply({0.4, 0.6});  // the pivot stays put
  CHECK(pivot.x == Approx(0.4).epsilon(1e-12));
  CHECK(pivot.y == Approx(0.6).epsilon(1e-12));
  const Similarity end = beat.at(1.0), start = beat.at(0.0);
  CHECK((end.a == start.a && end.b == start.b && end.ex == start.ex && end.ey == start.ey));
  // Between entries the table is a straight line in each of a, b, e.
  const double h = 1.0 / kContainerMotionIntervals;
  const Similarity lo = beat.at(10 * h), hi = beat.at(11 * h), mid = beat.at(10.5 * h);
  CHECK(mid.a == Approx(0.5 * (lo.a + hi.a)).epsilon(1e-12));

  AnimationSpec turn;
  turn.preset = AnimationPreset::rotate;
  turn.turns = 1.0;
  const ContainerMotion spin(turn, {0.5, 0.5}, 1.0, true);
  CHECK(spin.at(0.25).angle() == Approx(0.5 * 3.14159265358979).epsilon(1e-9));
  const Vec2 p = spin.at(0.25).apply({1.0, 0.5});  // a quarter turn clockwise on screen (y down)
  CHECK(p.x == Approx(0.5).margin(1e-9));
  CHECK(p.y == Approx(1.0).margin(1e-9));
  const Vec2 back = spin.at(0.25).inverse(p);
  CHECK(back.x == Approx(1.0).margin(1e-12));
  CHECK(back.y == Approx(0.5).margin(1e-12));
  CHECK_FALSE(ContainerMotion{}.moves());
}

TEST_CASE("moving container: a beating container scales its elements with it, unless inherit_scale is false") {
  const std::string beat = R"({"preset": "pulse", "amplitude": 0.2, "count": 1})";
  const World inherit = make_world(parse_scene(moving_star_scene(beat), "beat.json", "."));
  const World keep = make_world(parse_scene(moving_star_scene(beat, R"(, "inherit_scale": false)"), "keep.json", "."));
  REQUIRE(inherit.container.motion.moves());
  REQUIRE(inherit.topology.slice_count() == 8);
  const double area0 = slice_rest_area(inherit, 0);
  for (int s = 1; s < 8; ++s) {
    const double t = s / 7.0, k = inherit.container.motion.at(t).scale();
    INFO("slice " << s << ", container scale " << k);
    // The star turns (area kept) and scales with the container: its area by the scale squared.
    CHECK(slice_rest_area(inherit, s) / area0 == Approx(k * k).epsilon(2e-3));
    CHECK(slice_rest_area(keep, s) / slice_rest_area(keep, 0) == Approx(1.0).epsilon(2e-3));
  }
  // Either way each slice sits where the container carries it: its centroid is the motion at its time
  // applied to the same slice's centroid in the container standing still.
  const World still = make_world(parse_scene(moving_star_scene(R"({})"), "still.json", "."));
  REQUIRE_FALSE(still.container.motion.moves());
  for (const World* w : {&inherit, &keep})
    for (int s = 0; s < 8; ++s) {
      const Vec2 expected = w->container.motion.at(s / 7.0).apply(
          {still.topology.slice_rest_copy_cx[s], still.topology.slice_rest_copy_cy[s]});
      CHECK(w->topology.slice_rest_copy_cx[s] == Approx(expected.x).margin(1e-5));
      CHECK(w->topology.slice_rest_copy_cy[s] == Approx(expected.y).margin(1e-5));
    }
}

TEST_CASE(
    "moving container: a lone element packed in a container that travels and turns stays inside at every "
    "slice and between slices") {
  const std::string travel = R"({"keys": [
      {"t": 0, "translate": [0, 0]},
      {"t": 0.5, "translate": [90, -40], "rotate": 60, "scale": 0.9},
      {"t": 1, "translate": [0, 0]}]})";
  World world = make_world(parse_scene(moving_star_scene(travel), "travel.json", "."));
  REQUIRE(world.container.motion.moves());
  auto backend = make_reference_backend(world.topology, world.state, world.params);
  for (int i = 0; i < 400; ++i) backend->step();
  const SimState& state = backend->state();
  REQUIRE(state.growth[0] > 1.0f);  // it grew

  // Not vacuous: the element travels further than its own size, so the container at rest would not hold it.
  const Topology& topo = world.topology;
  const double dx = topo.slice_rest_copy_cx[4] - topo.slice_rest_copy_cx[0];
  CHECK(std::abs(dx) > 0.1);
  int outside_at_rest = 0, outside = 0;
  for (std::int32_t v = 0; v < topo.vertex_count(); ++v) {
    const Vec2 p{state.x[v], state.y[v]};
    outside += inside_at(world.container, p, state.t[v]) ? 0 : 1;
    outside_at_rest += world.container.contains(p) ? 0 : 1;
  }
  CHECK(outside == 0);
  CHECK(outside_at_rest > 0);
  // Between slices, on the curve the frames draw.
  for (int k = 0; k <= 70; ++k) {
    const double tf = k / 70.0;
    for (const Vec2 p : element_at(world, state, 0, tf)) {
      INFO("t = " << tf << " at (" << p.x << ", " << p.y << ")");
      CHECK(inside_at(world.container, p, tf));
    }
  }
}
