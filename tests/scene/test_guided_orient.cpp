// Guided elements that face along their paths (docs/scene-format.md, "Facing along the path") and closed
// paths that stay smooth through their start when the scene does not loop.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>

#include "animpak/error.hpp"
#include "animpak/scene.hpp"
#include "scene/tiny_scenes.hpp"

using namespace animpak;
using animpak::test::SceneExtras;
using animpak::test::star_scene;
using Catch::Matchers::Contains;

namespace {

World oriented_world(const std::string& text) { return make_world(parse_scene(text, "tiny.json", "/")); }

std::string orient_error(const std::string& text) {
  try {
    oriented_world(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// An oval round the heart's middle, anticlockwise on screen (y down): left, top, right, bottom, left.
std::string oval_targets(const std::string& middle_target_extra = "") {
  return R"([{"x": 190, "y": 260, "t": 0}, {"x": 250, "y": 220, "t": 0.25},
             {"x": 310, "y": 260, "t": 0.5)" +
         middle_target_extra + R"(}, {"x": 250, "y": 300, "t": 0.75}, {"x": 190, "y": 260, "t": 1}])";
}

std::string oval_scene(const std::string& guided_extra, const std::string& middle_target_extra = "",
                       const std::string& top = "", int slices = 41) {
  const SceneExtras extras{R"(, "guided": [{"name": "dove", "element": "star", "targets": )" +
                               oval_targets(middle_target_extra) + guided_extra + "}]" + top,
                           ""};
  return star_scene(0, slices, 3, extras, R"({"preset": "none"})");
}

double wrapped_degrees(double radians) {
  double d = std::remainder(radians, 2.0 * std::numbers::pi) * 180.0 / std::numbers::pi;
  return d <= -180.0 ? d + 360.0 : d;
}

// The guided element's anchor per slice, and its slice's rotation against the art as drawn (radians), read
// back from the built world: the angle of the vector from the anchor to another vertex against the same
// vector of the element's rest slice.
struct Track {
  std::vector<Vec2> anchor;
  std::vector<double> angle;
};
Track track_of(const World& w) {
  const Topology& topo = w.topology;
  const ElementInstance& dove = w.elements[0];
  const SpacetimeElement& e = w.library[dove.library];
  std::int32_t anchor = -1;
  for (std::int32_t v = topo.slice_begin[dove.slice_begin]; v < topo.slice_begin[dove.slice_begin + 1]; ++v)
    if (topo.flags[v] & vertex_anchor) anchor = v - dove.vertex_begin;
  REQUIRE(anchor >= 0);
  const int other = anchor == 0 ? 1 : 0;
  Track track;
  for (int s = 0; s < e.slice_count; ++s) {
    const auto at = [&](int v) {
      const std::int32_t id = dove.vertex_begin + e.id(s, v);
      return Vec2{w.state.x[id], w.state.y[id]};
    };
    const Vec2 now = at(other) - at(anchor), rest = e.position(s, other) - e.position(s, anchor);
    track.anchor.push_back(at(anchor));
    track.angle.push_back(std::atan2(rest.x * now.y - rest.y * now.x, rest.x * now.x + rest.y * now.y));
  }
  return track;
}

}  // namespace

TEST_CASE("guided orient path: the element faces along its path at every slice, turned by its facing") {
  for (const double facing : {0.0, 180.0, 90.0}) {
    INFO("facing " << facing);
    const std::string extra =
        R"(, "orient": "path")" + (facing != 0.0 ? R"(, "facing": )" + std::to_string(facing) : std::string());
    const Track track = track_of(oriented_world(oval_scene(extra)));
    const int n = static_cast<int>(track.anchor.size());
    for (int s = 1; s + 1 < n; ++s) {
      INFO("slice " << s);
      const Vec2 d = track.anchor[s + 1] - track.anchor[s - 1];
      const double travel = std::atan2(d.y, d.x);
      CHECK(std::abs(wrapped_degrees(track.angle[s] - (travel - facing * std::numbers::pi / 180.0))) < 6.0);
    }
  }
  // Without orient, the element keeps the targets' angle (none given: as drawn) however the path turns.
  const Track still = track_of(oriented_world(oval_scene("")));
  for (const double a : still.angle) CHECK(std::abs(wrapped_degrees(a)) < 1e-3);
}

TEST_CASE("guided orient path: a target's angle still wins at its slice, and every target slice holds its angle") {
  const World w = oriented_world(oval_scene(R"(, "orient": "path")", R"(, "angle": 30)"));
  const Track track = track_of(w);
  // t 0.5 is slice 20 of 41: at the rightmost point the path runs straight down (90°), the target says 30°.
  CHECK(std::abs(wrapped_degrees(track.angle[20] - 30.0 * std::numbers::pi / 180.0)) < 1e-3);
  // The difference fades by the targets on either side: at t 0.25 (top, running right) and t 0.75
  // (bottom, running left) the element faces along the path again, as at t 0 (leftmost, running up).
  CHECK(std::abs(wrapped_degrees(track.angle[10])) < 1.0);
  CHECK(std::abs(wrapped_degrees(track.angle[30] - std::numbers::pi)) < 1.0);
  CHECK(std::abs(wrapped_degrees(track.angle[0] + std::numbers::pi / 2)) < 1.0);
  // Half way from the top to the target (t 0.375), half the difference: 30° short of the path's direction.
  const Vec2 d = track.anchor[16] - track.anchor[14];
  CHECK(std::abs(wrapped_degrees(track.angle[15] - std::atan2(d.y, d.x)) + 30.0) < 6.0);
  // The five target slices hold their angles (the torsional force, Eq. 5), every vertex of them.
  const Topology& topo = w.topology;
  int holding = 0;
  for (std::int32_t v = 0; v < topo.vertex_count(); ++v) holding += (topo.flags[v] & vertex_hold_angle) != 0;
  CHECK(holding == 5 * (topo.slice_begin[1] - topo.slice_begin[0]));
}

TEST_CASE("guided orient: facing without orient path, or an unknown orient, is refused naming the field") {
  CHECK_THAT(orient_error(oval_scene(R"(, "facing": 180)")),
             Contains("guided[0].facing") && Contains("\"orient\": \"path\""));
  CHECK_THAT(orient_error(oval_scene(R"(, "orient": "forward")")), Contains("guided[0].orient") && Contains("path"));
}

TEST_CASE("guided path: an oval in a scene that does not loop turns no corner where it starts and ends") {
  // The turn from the last slice step into the first, as if the path ran on: an open path leaves the
  // start along the chord to the next target and arrives along the chord from the one before (62° apart
  // on this oval); a closed one runs through it.
  // Measured against the largest turn between two steps anywhere else on the path (a cubic through four
  // targets bends most at them, 29° a step on this oval of 41 slices).
  const Track track = track_of(oriented_world(oval_scene("", "", R"(, "loop": false)", 41)));
  const int n = static_cast<int>(track.anchor.size());
  const auto turn = [](Vec2 into, Vec2 out) {
    return std::abs(wrapped_degrees(std::atan2(out.y, out.x) - std::atan2(into.y, into.x)));
  };
  double elsewhere = 0.0;
  for (int s = 1; s + 1 < n; ++s)
    elsewhere = std::max(elsewhere, turn(track.anchor[s] - track.anchor[s - 1], track.anchor[s + 1] - track.anchor[s]));
  const double at_start = turn(track.anchor[n - 1] - track.anchor[n - 2], track.anchor[1] - track.anchor[0]);
  INFO("turn where it starts " << at_start << "°, elsewhere at most " << elsewhere << "°");
  CHECK(elsewhere < 35.0);
  CHECK(at_start <= 1.2 * elsewhere);
}
