// Guided elements in motion (paper §4): the anchor is sprung to the artist's target points only, so
// the slices between two targets leave a straight path that crosses a hole, while the targets' slices
// stay near their targets and turn back to a target's angle.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "animpak/scene.hpp"
#include "animpak/simulation.hpp"
#include "scene/tiny_scenes.hpp"

using namespace animpak;

namespace {

// One guided star in the annulus example's ring (outline r 240, hole r 95 about (250, 250), art
// units), 9 slices: targets at t 0, 0.5 and 1 on slices 0, 4 and 8. The stretch from target 0 to
// target 1 runs along y = 200, 50 from the ring's centre, so slice 2 starts inside the hole.
World ring_world(const std::string& params) {
  const std::string text =
      R"({"container": {"art": ")" + animpak::test::example_file("annulus/ring.svg") +
      R"(", "outline": 0, "holes": [1]}, "elements": [{"name": "star", "art": ")" +
      animpak::test::example_file("default/star.svg") +
      R"(", "count": 0, "animation": {"preset": "rotate", "turns": 0}}], "guided": [{"name": "crosser", "element": "star",
      "targets": [{"x": 420, "y": 200, "t": 0}, {"x": 80, "y": 200, "t": 0.5, "angle": 90}, {"x": 80, "y": 300, "t": 1}]}],
      "loop": false, "seed": 1, "slices": 9, "params": {)" +
      params + "}}";
  return make_world(parse_scene(text, "ring.json", "/"));
}

// Mean signed angle (degrees) from each vertex's rest direction to its direction about the slice's
// current centroid.
double slice_turn(const Topology& topo, const SimState& s, std::int32_t slice) {
  const std::int32_t b = topo.slice_begin[slice], e = topo.slice_begin[slice + 1];
  double cx = 0.0, cy = 0.0, sum = 0.0;
  for (std::int32_t v = b; v < e; ++v) cx += s.x[v], cy += s.y[v];
  cx /= e - b, cy /= e - b;
  for (std::int32_t v = b; v < e; ++v) {
    const double ux = s.x[v] - cx, uy = s.y[v] - cy, rx = topo.rest_dir_x[v], ry = topo.rest_dir_y[v];
    sum += std::atan2(rx * uy - ry * ux, rx * ux + ry * uy);
  }
  return sum / (e - b) * 180.0 / 3.14159265358979323846;
}

// Turns slice `slice` of the state by `degrees` about its centroid.
void turn_slice(const Topology& topo, SimState& s, std::int32_t slice, double degrees) {
  const std::int32_t b = topo.slice_begin[slice], e = topo.slice_begin[slice + 1];
  double cx = 0.0, cy = 0.0;
  for (std::int32_t v = b; v < e; ++v) cx += s.x[v], cy += s.y[v];
  cx /= e - b, cy /= e - b;
  const double a = degrees * 3.14159265358979323846 / 180.0;
  for (std::int32_t v = b; v < e; ++v) {
    const double ux = s.x[v] - cx, uy = s.y[v] - cy;
    s.x[v] = static_cast<float>(cx + std::cos(a) * ux - std::sin(a) * uy);
    s.y[v] = static_cast<float>(cy + std::sin(a) * ux + std::cos(a) * uy);
  }
}

}  // namespace

TEST_CASE("guided: the slices between targets leave the hole, the targets' slices stay within 0.02 of them") {
  const World w = ring_world("");
  const Topology& topo = w.topology;
  REQUIRE(topo.target_x.size() == 3);
  std::int32_t anchor = -1;  // the anchor's index within a slice
  for (std::int32_t v = topo.slice_begin[0]; v < topo.slice_begin[1]; ++v)
    if (topo.flags[v] & vertex_anchor) anchor = v;
  REQUIRE(anchor >= 0);
  const std::int32_t middle = topo.slice_begin[2] + anchor;
  REQUIRE_FALSE(w.container.contains({w.state.x[middle], w.state.y[middle]}));

  auto backend = make_reference_backend(topo, w.state, w.params);
  for (int i = 0; i < 4000; ++i) backend->step();
  const SimState s = backend->state();
  for (std::int32_t v = 0; v < topo.vertex_count(); ++v) {
    if (topo.target[v] < 0) continue;
    INFO("slice " << topo.slice[v]);
    CHECK(std::hypot(s.x[v] - topo.target_x[topo.target[v]], s.y[v] - topo.target_y[topo.target[v]]) < 0.02);
  }
  // Off the straight line y = 200 (0.396 in the unit container) and out of the hole.
  CHECK(w.state.y[middle] - s.y[middle] > 0.1);
  CHECK(w.container.contains({s.x[middle], s.y[middle]}));
}

TEST_CASE("guided: a target's slice turned 20 degrees off the target's angle turns back, faster than with k_tor") {
  for (const bool hold : {true, false}) {
    INFO((hold ? "k_target_angle default" : "k_target_angle = k_torsion"));
    // On the straight path between targets (guide_curve 0), as this comparison was calibrated: on the
    // smooth path the neighbouring slices start turned along the curve and help the plain k_tor back too.
    const World w = ring_world(hold ? R"("guide_curve": 0)" : R"("k_target_angle": 2e-4, "guide_curve": 0)");
    const std::int32_t keyed = 4;  // target 1, angle 90
    REQUIRE((w.topology.flags[w.topology.slice_begin[keyed]] & vertex_hold_angle));
    SimState start = w.state;
    turn_slice(w.topology, start, keyed, 20.0);
    CHECK(slice_turn(w.topology, start, keyed) == Approx(20.0).margin(0.01));
    auto backend = make_reference_backend(w.topology, start, w.params);
    // The turn is limited by the velocity cap, so the plain k_tor also turns it back, only slower: the
    // bounds sit between what the two stiffnesses leave after 400 steps.
    for (int i = 0; i < 400; ++i) backend->step();
    const double left = std::abs(slice_turn(w.topology, backend->state(), keyed));
    if (hold)
      CHECK(left < 1.0);
    else
      CHECK(left > 2.0);
  }
}
