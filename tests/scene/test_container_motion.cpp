// The container's `animation` in the scene file (docs/scene-format.md, "A container that moves"): what
// it accepts, what it refuses and why, and the motion make_world gives the container.
#include <catch2/catch.hpp>

#include <string>

#include "animpak/error.hpp"
#include "animpak/scene.hpp"
#include "tiny_scenes.hpp"

using namespace animpak;

namespace {

std::string scene_with(const std::string& container_members, const std::string& top = "") {
  return R"({"container": {"art": ")" + test::example_file("shapes/heart-container.path") + "\"" + container_members +
         R"(}, "elements": [{"name": "star", "art": ")" + test::example_file("default/star.svg") +
         R"(", "count": 2}], "slices": 6)" + top + "}";
}

std::string refusal(const std::string& text) {
  try {
    make_world(parse_scene(text, "scene.json", "."));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("container animation: a preset or keys make the container move, looping with the scene") {
  const SceneSpec plain = parse_scene(scene_with(""), "scene.json", ".");
  CHECK_FALSE(make_world(plain).container.motion.moves());
  CHECK(plain.container.inherit_scale);

  const SceneSpec beat =
      parse_scene(scene_with(R"(, "animation": {"preset": "pulse", "amplitude": 0.1, "count": 2})"), "s.json", ".");
  CHECK(beat.container.animation.loop);
  const World w = make_world(beat);
  REQUIRE(w.container.motion.moves());
  CHECK(w.container.motion.max_scale() == Approx(1.1).epsilon(1e-6));

  // A scene that does not loop gives its container a motion that does not either: keys may end elsewhere.
  const SceneSpec once = parse_scene(
      scene_with(R"(, "animation": {"keys": [{"t": 0}, {"t": 1, "translate": [40, 0]}]}, "inherit_scale": false)",
                 R"(, "loop": false)"),
      "s.json", ".");
  CHECK_FALSE(once.container.animation.loop);
  CHECK_FALSE(once.container.inherit_scale);
  const World moved = make_world(once);
  const Vec2 start = moved.container.motion.at(0.0).apply({0.5, 0.5}),
             end = moved.container.motion.at(1.0).apply({0.5, 0.5});
  CHECK(end.x - start.x == Approx(40.0 * moved.container.frame.scale).epsilon(1e-9));
}

TEST_CASE("container animation: handles, swim, its own loop and a mirror are refused with what to do") {
  const std::string handles =
      refusal(scene_with(R"(, "animation": {"handles": [{"point": [1, 1], "keys": [{"t": 0, "position": [1, 1]}]}]})"));
  CHECK_THAT(handles, Catch::Contains("container.animation.handles") && Catch::Contains("moves as a whole"));
  const std::string swim = refusal(scene_with(R"(, "animation": {"preset": "swim"})"));
  CHECK_THAT(swim, Catch::Contains("container.animation.preset") && Catch::Contains("rotate, pulse or keys"));
  const std::string loop = refusal(scene_with(R"(, "animation": {"preset": "pulse", "loop": false})"));
  CHECK_THAT(loop, Catch::Contains("container.animation.loop") && Catch::Contains("loops when the scene does"));
  const std::string half = refusal(scene_with(R"(, "animation": {"preset": "rotate", "turns": 0.5})"));
  CHECK_THAT(half, Catch::Contains("container.animation.turns") && Catch::Contains("whole number of turns"));
  const std::string seam =
      refusal(scene_with(R"(, "animation": {"keys": [{"t": 0}, {"t": 1, "translate": [40, 0]}]})"));
  CHECK_THAT(seam, Catch::Contains("container.animation.keys[1]") && Catch::Contains("loop"));
  const std::string mirrored =
      refusal(scene_with(R"(, "animation": {"preset": "pulse"})", R"(, "mirror": {"x": 250})"));
  CHECK_THAT(mirrored, Catch::Contains("scene.json") && Catch::Contains("mirror") &&
                           Catch::Contains("remove `mirror` or the container's animation"));
}

TEST_CASE("container animation: the still reference stands the container still at the mean size it is given") {
  const std::string text = scene_with(R"(, "animation": {"pivot": [250, 300], "keys": [
      {"t": 0, "scale": 1}, {"t": 0.5, "scale": 1.3, "rotate": 20, "translate": [30, 0]}, {"t": 1, "scale": 1}]})");
  const SceneSpec scene = parse_scene(text, "scene.json", ".");
  const double mean = ContainerMotion(scene.container.animation, {}, 1.0, scene.loop).mean_scale();
  CHECK(mean > 1.1);
  CHECK(mean < 1.2);
  const SceneSpec still = parse_scene(still_scene_text(text, scene, mean), "still.json", ".");
  const World w = make_world(still);
  REQUIRE(w.container.motion.moves());
  CHECK(w.container.motion.min_scale() == Approx(mean).epsilon(1e-12));
  CHECK(w.container.motion.max_scale() == Approx(mean).epsilon(1e-12));
  // No turn, no move: only the scale about the same pivot.
  const Similarity m = w.container.motion.at(0.4);
  CHECK(m.angle() == 0.0);
  const Vec2 pivot = w.container.frame.to_unit({250, 300});
  const Vec2 kept = m.apply(pivot);
  CHECK(kept.x == Approx(pivot.x).epsilon(1e-12));
  CHECK(kept.y == Approx(pivot.y).epsilon(1e-12));
}
