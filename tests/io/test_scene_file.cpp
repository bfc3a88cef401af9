#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "animpak/error.hpp"
#include "animpak/param_table.hpp"
#include "animpak/scene_spec.hpp"
#include "temp_dir.hpp"

using namespace animpak;
using Catch::Matchers::Contains;
using Catch::Matchers::EndsWith;
using Catch::Matchers::StartsWith;

namespace {

const std::filesystem::path kShapes = std::filesystem::path(ANIMPAK_SOURCE_DIR) / "examples" / "shapes";

SceneSpec parse_scene_text(const std::string& text) { return parse_scene(text, "scene.json", kShapes); }

/// The InputError message for `text`, or a marker that no error was thrown.
std::string scene_error_of(const std::string& text) {
  try {
    parse_scene_text(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

/// A valid scene around `elements` (a JSON array) and `rest` (more top-level members, each with a
/// leading comma); each malformed case below breaks one thing in it.
std::string scene(const std::string& elements, const std::string& rest = "") {
  return R"({"container": "heart-container.path", "elements": )" + elements + rest + "}";
}
const std::string kBird = R"([{"art": "bird.path"}])";

std::string animated_bird(const std::string& animation) {
  return scene(R"([{"art": "bird.path", "animation": )" + animation + "}]");
}

std::string guided(const std::string& entries, const std::string& loop = "") {
  return scene(R"([{"name": "bird", "art": "bird.path"}])", loop + R"(, "guided": )" + entries);
}

}  // namespace

TEST_CASE("parse_scene: a full scene fills every field") {
  const SceneSpec s = parse_scene_text(R"({
    "container": {"art": "heart-container.path", "outline": 0, "holes": [1, 2]},
    "elements": [
      {"name": "spinner", "art": "bird.path", "count": 3,
       "animation": {"preset": "rotate", "turns": -2, "pivot": [250, 240], "loop": true}},
      {"art": "cat.path", "weight": 2.5,
       "animation": {"keys": [{"t": 0, "translate": [0, 0], "rotate": 0, "scale": 1},
                              {"t": 0.5, "translate": [10, -5], "rotate": 30, "scale": 1.2},
                              {"t": 1, "translate": [0, 0], "rotate": 0, "scale": 1}],
                     "handles": [{"point": [100, 120], "keys": [{"t": 0, "position": [100, 120]},
                                                                {"t": 0.5, "position": [110, 100]}]}]}},
      {"name": "fish", "art": "snake.path", "animation": {"preset": "swim", "amplitude": 0.2, "count": 2, "wavelength": 0.8}}
    ],
    "guided": [
      {"name": "a", "element": "spinner", "targets": [{"x": 250, "y": 100, "t": 0, "angle": 90},
                                                     {"x": 250, "y": 400, "t": 1, "scale": 1.5}], "loop_to": "b"},
      {"name": "b", "element": "cat", "targets": [{"x": 250, "y": 400, "t": 0}, {"x": 250, "y": 100, "t": 1}], "loop_to": "a"}
    ],
    "orientation": {"mode": "field", "field": {"kind": "radial", "center": [250, 300]}},
    "count": 10, "seed": 18446744073709551615, "loop": true, "slices": 50,
    "params": {"k_edge": 4, "max_iterations": 5000}
  })");
  CHECK(s.file == "scene.json");
  CHECK(s.container.art == kShapes / "heart-container.path");
  CHECK(s.container.outline == 0);
  REQUIRE(s.container.holes);
  CHECK(*s.container.holes == std::vector<int>{1, 2});
  REQUIRE(s.elements.size() == 3);
  CHECK(s.elements[0].name == "spinner");
  CHECK(s.elements[0].count == 3);
  CHECK(s.elements[0].animation.preset == AnimationPreset::rotate);
  CHECK(s.elements[0].animation.turns == -2);
  REQUIRE(s.elements[0].animation.pivot);
  CHECK(s.elements[0].animation.pivot->x == 250);
  CHECK(s.elements[1].name == "cat");
  CHECK_FALSE(s.elements[1].count);
  CHECK(s.elements[1].weight == 2.5);
  REQUIRE(s.elements[1].animation.keys.size() == 3);
  CHECK(s.elements[1].animation.keys[1].translate.x == 10);
  CHECK(s.elements[1].animation.keys[1].rotate == 30);
  CHECK(s.elements[1].animation.keys[1].scale == 1.2);
  REQUIRE(s.elements[1].animation.handles.size() == 1);
  CHECK(s.elements[1].animation.handles[0].keys[1].position.y == 100);
  CHECK(s.elements[2].animation.preset == AnimationPreset::swim);
  CHECK(s.elements[2].animation.amplitude == 0.2);
  CHECK(s.elements[2].animation.count == 2);
  CHECK(s.elements[2].animation.wavelength == 0.8);
  REQUIRE(s.guided.size() == 2);
  CHECK(s.guided[0].loop_to == "b");
  CHECK(s.guided[0].targets[0].angle == 90);
  CHECK(s.guided[0].targets[1].scale == 1.5);
  CHECK_FALSE(s.guided[0].targets[0].scale);
  CHECK(s.orientation.mode == OrientationMode::field);
  CHECK(s.orientation.field == FieldKind::radial);
  CHECK(s.orientation.center.y == 300);
  CHECK(s.count == 10);
  CHECK(s.seed == 18446744073709551615ull);
  CHECK(s.loop);
  CHECK(s.params.element.slices == 50);
  CHECK(s.params.forces.k_edge == 4);
  CHECK(s.params.stop.max_iterations == 5000);
  CHECK(s.params.forces.k_shear == Params{}.forces.k_shear);
}

TEST_CASE("parse_scene: an unnamed element is named by its art as the scene writes it, wherever a locator reads it") {
  // A packed folder stores a second art file of the same name as art/2-bird.path; the element stays "bird".
  const animpak::test::TempDir temp("animpak-locator-");
  const ArtLocator renamed = [&](const std::string&, const std::filesystem::path& resolved) {
    const std::filesystem::path copy = temp / "2-bird.path";
    std::filesystem::copy_file(resolved, copy, std::filesystem::copy_options::overwrite_existing);
    return copy;
  };
  const SceneSpec s = parse_scene(scene(kBird), "scene.json", kShapes, renamed);
  REQUIRE(s.elements.size() == 1);
  CHECK(s.elements[0].art.filename() == "2-bird.path");
  CHECK(s.elements[0].name == "bird");
}

TEST_CASE("parse_scene: a minimal scene takes every default") {
  const SceneSpec s = parse_scene_text(scene(kBird));
  REQUIRE(s.elements.size() == 1);
  CHECK(s.elements[0].name == "bird");
  CHECK(s.elements[0].weight == 1.0);
  CHECK(s.elements[0].animation.preset == AnimationPreset::none);
  CHECK(s.elements[0].animation.loop);
  CHECK_FALSE(s.container.outline);
  CHECK_FALSE(s.container.holes);
  CHECK(s.guided.empty());
  CHECK(s.orientation.mode == OrientationMode::random);
  CHECK_FALSE(s.count);
  CHECK(s.seed == 1);
  CHECK(s.loop);
  CHECK(s.params.element.slices == 100);
}

TEST_CASE("parse_scene: fixed and constant-field orientations, count fill") {
  CHECK(parse_scene_text(scene(kBird, R"(, "orientation": {"mode": "fixed", "angle": 45}, "count": "fill")"))
            .orientation.angle == 45);
  const SceneSpec s = parse_scene_text(
      scene(kBird, R"(, "orientation": {"mode": "field", "field": {"kind": "constant", "angle": 30}})"));
  CHECK(s.orientation.field == FieldKind::constant);
  CHECK(s.orientation.angle == 30);
}

TEST_CASE("load_scene: relative art resolves against the scene file's folder") {
  const test::TempDir temp("animpak-scene-");
  const auto& dir = temp.path();
  std::filesystem::create_directories(dir / "art");
  std::filesystem::copy_file(kShapes / "bird.path", dir / "art" / "bird.path",
                             std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir / "scene.json") << R"({"container": "art/bird.path", "elements": [{"art": "art/bird.path"}]})";
  const SceneSpec s = load_scene(dir / "scene.json");
  CHECK(s.elements[0].art == dir / "art" / "bird.path");
  CHECK(s.file == dir / "scene.json");
}

TEST_CASE("load_scene: a missing scene file") {
  CHECK_THROWS_WITH(load_scene("nowhere/scene.json"), StartsWith("nowhere/scene.json: cannot read"));
}

TEST_CASE("parse_scene: malformed JSON gives line and column") {
  CHECK_THAT(scene_error_of("{\n  \"container\": \"heart-container.path\",\n  \"elements\": [}\n"),
             StartsWith("scene.json: malformed JSON at line 3, column 16:"));
}

TEST_CASE("parse_scene: a missing or trailing comma is named with its line") {
  // Between two members on separate lines: the parser stops at the second, the comma belongs after the first.
  CHECK_THAT(
      scene_error_of("{\n  \"container\": \"heart-container.path\"\n  \"elements\": []\n}\n"),
      StartsWith("scene.json: malformed JSON at line 3, column 12:") && EndsWith("(missing comma after line 2?)"));
  // After a number, a closing bracket and a literal, in arrays and objects.
  CHECK_THAT(scene_error_of(scene(R"([{"art": "bird.path", "count": 3)"
                                  "\n"
                                  R"("weight": 1}])")),
             EndsWith("(missing comma after line 1?)"));
  CHECK_THAT(scene_error_of(scene("[{\"art\": \"bird.path\"}\n{\"art\": \"bird.path\"}]")),
             Contains("expected ']'") && EndsWith("(missing comma after line 1?)"));
  CHECK_THAT(scene_error_of(scene(kBird, ", \"loop\": true\n\"seed\": 1")), EndsWith("(missing comma after line 1?)"));
  // On one line, a comma inside a string does not count.
  CHECK_THAT(scene_error_of(R"({"container": "heart, \"container\".path" "elements": []})"),
             EndsWith("(missing comma before column 43 of line 1?)"));
  // A trailing comma before '}' and before ']', named at the comma's line.
  CHECK_THAT(scene_error_of(scene(kBird, ",\n  \"seed\": 1,\n")),
             StartsWith("scene.json: malformed JSON at line 3, column 1:") &&
                 EndsWith("(trailing comma at line 2 before the '}': JSON does not allow it; remove the comma)"));
  CHECK_THAT(scene_error_of(scene("[\n  {\"art\": \"bird.path\"},\n]")),
             EndsWith("(trailing comma at line 2 before the ']': JSON does not allow it; remove the comma)"));
  // Other slips get no hint: a missing colon, a bracket with nothing to close.
  CHECK_THAT(scene_error_of(R"({"container" "heart-container.path"})"), EndsWith("expected ':'"));
  CHECK_THAT(scene_error_of("{\n  \"elements\": [}\n"), !Contains("comma"));
}

TEST_CASE("parse_scene: a key given twice in one object") {
  CHECK_THAT(scene_error_of(scene(kBird, R"(, "seed": 1, "seed": 2)")),
             Contains("scene.json: key `seed` appears twice in one object"));
}

TEST_CASE("parse_scene: unknown top-level field suggests the close one") {
  CHECK(scene_error_of(R"({"container": "heart-container.path", "elemnts": []})") ==
        "scene.json: elemnts: unknown field; did you mean `elements`?");
  CHECK_THAT(scene_error_of(scene(kBird, R"(, "zzz": 1)")),
             StartsWith("scene.json: zzz: unknown field; expected one of `container`"));
}

TEST_CASE("parse_scene: unknown nested field and a prefix suggestion") {
  CHECK(scene_error_of(scene(R"([{"art": "bird.path", "anim": {}}])")) ==
        "scene.json: elements[0].anim: unknown field; did you mean `animation`?");
}

TEST_CASE("parse_scene: missing required fields") {
  CHECK(scene_error_of(R"({"elements": []})") == "scene.json: top level: missing required field `container`");
  CHECK(scene_error_of(R"({"container": "heart-container.path"})") ==
        "scene.json: top level: missing required field `elements`");
  CHECK_THAT(scene_error_of(scene("[]")), StartsWith("scene.json: elements: expected at least one element"));
}

TEST_CASE("parse_scene: type errors name the field and the value") {
  CHECK_THAT(scene_error_of(scene(kBird, R"(, "seed": "abc")")),
             StartsWith("scene.json: seed: expected an integer in [0, "));
  CHECK(scene_error_of(scene(kBird, R"(, "loop": 1)")) == "scene.json: loop: expected true or false, got 1");
  CHECK(scene_error_of(scene(R"({"art": "bird.path"})")) ==
        "scene.json: elements: expected an array, got {\"art\":\"bird.path\"}");
}

TEST_CASE("parse_scene: key time out of range") {
  CHECK(scene_error_of(animated_bird(R"({"keys": [{"t": 1.5}]})")) ==
        "scene.json: elements[0].animation.keys[0].t: expected a number in [0, 1], got 1.5");
}

TEST_CASE("parse_scene: keys out of order or with duplicate t") {
  CHECK_THAT(scene_error_of(animated_bird(R"({"keys": [{"t": 0.5}, {"t": 0.25}]})")),
             StartsWith("scene.json: elements[0].animation.keys[1].t: keys out of order: t 0.25 comes after t 0.5"));
  CHECK_THAT(
      scene_error_of(animated_bird(
          R"({"handles": [{"point": [1, 2], "keys": [{"t": 0.5, "position": [0, 0]}, {"t": 0.5, "position": [1, 1]}]}]})")),
      StartsWith("scene.json: elements[0].animation.handles[0].keys[1].t: duplicate t 0.5"));
}

TEST_CASE("parse_scene: a looping animation whose t = 1 key differs from t = 0") {
  CHECK_THAT(scene_error_of(animated_bird(R"({"keys": [{"t": 0, "rotate": 0}, {"t": 1, "rotate": 90}]})")),
             StartsWith("scene.json: elements[0].animation.keys[1]: the key at t = 1 differs from the key at t = 0 "
                        "(translate [0, 0] vs [0, 0], rotate 90 vs 0, scale 1 vs 1) in a looping animation"));
  CHECK_THAT(
      scene_error_of(animated_bird(
          R"({"handles": [{"point": [1, 2], "keys": [{"t": 0, "position": [1, 2]}, {"t": 1, "position": [3, 2]}]}]})")),
      StartsWith("scene.json: elements[0].animation.handles[0].keys[1]: the key at t = 1 (position [3, 2]) differs"));
  CHECK(scene_error_of(animated_bird(R"({"loop": false, "keys": [{"t": 0, "rotate": 0}, {"t": 1, "rotate": 90}]})")) ==
        "(no error)");
}

TEST_CASE("parse_scene: preset mistakes") {
  CHECK(scene_error_of(animated_bird(R"({"preset": "rotat"})")) ==
        "scene.json: elements[0].animation.preset: expected one of `none`, `rotate`, `pulse`, `swim`, got \"rotat\"; "
        "did you mean `rotate`?");
  CHECK_THAT(scene_error_of(animated_bird(R"({"preset": "pulse", "turns": 2})")),
             StartsWith("scene.json: elements[0].animation.turns: does not apply to preset `pulse`"));
  CHECK_THAT(scene_error_of(animated_bird(R"({"amplitude": 0.1})")),
             StartsWith("scene.json: elements[0].animation.amplitude: needs a `preset`"));
  CHECK_THAT(scene_error_of(animated_bird(R"({"preset": "rotate", "keys": [{"t": 0}]})")),
             StartsWith("scene.json: elements[0].animation.keys: a preset is a complete animation"));
  CHECK(scene_error_of(animated_bird(R"({"preset": "pulse", "amplitude": 0.95})")) ==
        "scene.json: elements[0].animation.amplitude: expected a number in [0, 0.9], got 0.95");
}

TEST_CASE("parse_scene: duplicate element names") {
  CHECK_THAT(scene_error_of(scene(R"([{"name": "x", "art": "bird.path"}, {"name": "x", "art": "cat.path"}])")),
             StartsWith("scene.json: elements[1].name: name `x` is already used by elements[0]"));
  CHECK_THAT(scene_error_of(scene(R"([{"art": "bird.path"}, {"art": "bird.path"}])")),
             StartsWith("scene.json: elements[1]: name `bird` (the art file's stem) is already used by elements[0]"));
}

TEST_CASE("parse_scene: count and weight together") {
  CHECK(scene_error_of(scene(R"([{"art": "bird.path", "count": 2, "weight": 3}])")) ==
        "scene.json: elements[0].weight: give either `count` or `weight`, not both");
}

TEST_CASE("parse_scene: art file missing or not art") {
  const std::string absolute = (kShapes / "x.svg").string();
  CHECK(scene_error_of(scene(R"([{"art": "x.svg"}])")) ==
        "scene.json: elements[0].art: cannot read \"x.svg\" (resolved to " + absolute +
            "); relative paths start at the scene file's folder");
  CHECK_THAT(scene_error_of(R"({"container": "heart.png", "elements": [{"art": "bird.path"}]})"),
             StartsWith("scene.json: container: \"heart.png\" is not an art file; expected a .svg or .path file"));
}

TEST_CASE("parse_scene: container holes listed twice or naming the outline") {
  CHECK(scene_error_of(
            R"({"container": {"art": "heart-container.path", "holes": [1, 1]}, "elements": [{"art": "bird.path"}]})") ==
        "scene.json: container.holes[1]: path 1 is listed twice");
  CHECK(
      scene_error_of(
          R"({"container": {"art": "heart-container.path", "outline": 2, "holes": [2]}, "elements": [{"art": "bird.path"}]})") ==
      "scene.json: container.holes[0]: path 2 is the outline and cannot be a hole");
}

TEST_CASE("parse_scene: guided element naming an unknown library element") {
  CHECK(
      scene_error_of(guided(
          R"([{"name": "g", "element": "brid", "targets": [{"x": 1, "y": 1, "t": 0}, {"x": 1, "y": 1, "t": 1}]}])")) ==
      "scene.json: guided[0].element: no element in `elements` is named `brid`; did you mean `bird`?");
}

TEST_CASE("parse_scene: guided targets must start at t = 0, end at t = 1 and increase") {
  CHECK_THAT(
      scene_error_of(guided(
          R"([{"name": "g", "element": "bird", "targets": [{"x": 1, "y": 1, "t": 0.1}, {"x": 1, "y": 1, "t": 1}]}])")),
      StartsWith("scene.json: guided[0].targets[0].t: the first target must have t = 0, got 0.1"));
  CHECK_THAT(
      scene_error_of(guided(
          R"([{"name": "g", "element": "bird", "targets": [{"x": 1, "y": 1, "t": 0}, {"x": 1, "y": 1, "t": 0.9}]}])")),
      StartsWith("scene.json: guided[0].targets[1].t: the last target must have t = 1, got 0.9"));
  CHECK_THAT(
      scene_error_of(guided(
          R"([{"name": "g", "element": "bird", "targets": [{"x": 1, "y": 1, "t": 0}, {"x": 1, "y": 1, "t": 0.6}, {"x": 1, "y": 1, "t": 0.4}, {"x": 1, "y": 1, "t": 1}]}])")),
      StartsWith("scene.json: guided[0].targets[2].t: targets out of order: t 0.4 comes after t 0.6"));
}

TEST_CASE("parse_scene: loop_to naming an unknown guided element") {
  CHECK(
      scene_error_of(guided(
          R"([{"name": "g", "element": "bird", "loop_to": "h", "targets": [{"x": 1, "y": 1, "t": 0}, {"x": 1, "y": 1, "t": 1}]}])")) ==
      "scene.json: guided[0].loop_to: no guided element is named `h`; did you mean `g`?");
}

TEST_CASE("parse_scene: loops that are not a permutation") {
  const std::string t = R"("targets": [{"x": 1, "y": 1, "t": 0}, {"x": 1, "y": 1, "t": 1}])";
  CHECK_THAT(scene_error_of(guided(R"([{"name": "a", "element": "bird", )" + t +
                                   R"(}, {"name": "b", "element": "bird", "loop_to": "a", )" + t + "}]")),
             StartsWith("scene.json: guided[1].loop_to: `a` is already looped into by guided[0] (`a`, which has no "
                        "`loop_to` and loops into itself)"));
}

TEST_CASE("parse_scene: loop_to without looping") {
  CHECK_THAT(
      scene_error_of(guided(
          R"([{"name": "g", "element": "bird", "loop_to": "g", "targets": [{"x": 1, "y": 1, "t": 0}, {"x": 1, "y": 1, "t": 1}]}])",
          R"(, "loop": false)")),
      StartsWith("scene.json: guided[0].loop_to: needs `loop: true` at the top level"));
}

TEST_CASE("parse_scene: guided paths that do not meet where they loop") {
  CHECK_THAT(
      scene_error_of(guided(
          R"([{"name": "a", "element": "bird", "loop_to": "b", "targets": [{"x": 0, "y": 0, "t": 0}, {"x": 3, "y": 4, "t": 1}]},
                                {"name": "b", "element": "bird", "loop_to": "a", "targets": [{"x": 3, "y": 0, "t": 0}, {"x": 0, "y": 0, "t": 1}]}])")),
      StartsWith("scene.json: guided[0].targets[1]: the last target (3, 4) must meet the first target of `b` "
                 "(guided[1].targets[0]), its `loop_to` at (3, 0) within 1e-06 art units, but is 4 away"));
  CHECK_THAT(
      scene_error_of(guided(
          R"([{"name": "a", "element": "bird", "targets": [{"x": 0, "y": 0, "t": 0}, {"x": 0, "y": 1e-5, "t": 1}]}])")),
      Contains("must meet its own first target (it has no `loop_to`, so it loops into itself)"));
  CHECK(
      scene_error_of(guided(
          R"([{"name": "a", "element": "bird", "targets": [{"x": 0, "y": 0, "t": 0}, {"x": 0, "y": 5e-7, "t": 1}]}])")) ==
      "(no error)");
  CHECK(scene_error_of(guided(
            R"([{"name": "a", "element": "bird", "targets": [{"x": 0, "y": 0, "t": 0}, {"x": 9, "y": 9, "t": 1}]}])",
            R"(, "loop": false)")) == "(no error)");
}

TEST_CASE("scene_warnings: a guided path that ends where it starts in a scene that does not loop") {
  const auto warnings_of = [](const std::string& targets, const std::string& loop) {
    return scene_warnings(
        parse_scene_text(guided(R"([{"name": "dove", "element": "bird", "targets": [)" + targets + "]}]", loop)));
  };
  const std::string round =
      R"({"x": 100, "y": 250, "t": 0}, {"x": 300, "y": 250, "t": 0.5}, {"x": 100, "y": 250, "t": 1})";
  const std::vector<std::string> open = warnings_of(round, R"(, "loop": false)");
  REQUIRE(open.size() == 1);
  CHECK(open[0] ==
        "guided element \"dove\" ends where it starts (x 100, y 250) but the scene does not loop; add \"loop\": true "
        "to the scene to make the animation loop seamlessly");
  // Within the 1e-6 art units a loop allows, as the loop check measures it.
  CHECK(warnings_of(R"({"x": 0, "y": 0, "t": 0}, {"x": 9, "y": 9, "t": 0.5}, {"x": 0, "y": 5e-7, "t": 1})",
                    R"(, "loop": false)")
            .size() == 1);
  CHECK(warnings_of(round, "").empty());  // it loops
  CHECK(warnings_of(R"({"x": 0, "y": 0, "t": 0}, {"x": 9, "y": 9, "t": 0.5}, {"x": 0, "y": 1e-5, "t": 1})",
                    R"(, "loop": false)")
            .empty());
  CHECK(warnings_of(R"({"x": 0, "y": 0, "t": 0}, {"x": 9, "y": 9, "t": 1})", R"(, "loop": false)").empty());
  // Held in place (scaled or turned there): no path to close.
  CHECK(warnings_of(R"({"x": 5, "y": 5, "t": 0}, {"x": 5, "y": 5, "t": 0.5, "scale": 2}, {"x": 5, "y": 5, "t": 1})",
                    R"(, "loop": false)")
            .empty());
}

TEST_CASE("parse_scene: duplicate guided names") {
  const std::string t = R"("targets": [{"x": 1, "y": 1, "t": 0}, {"x": 1, "y": 1, "t": 1}])";
  CHECK_THAT(scene_error_of(guided(R"([{"name": "a", "element": "bird", )" + t +
                                   R"(}, {"name": "a", "element": "bird", )" + t + "}]")),
             StartsWith("scene.json: guided[1].name: name `a` is already used by guided[0]"));
}

TEST_CASE("parse_scene: params overrides are checked by name, type and range") {
  CHECK(scene_error_of(scene(kBird, R"(, "params": {"k_edeg": 1})")) ==
        "scene.json: params.k_edeg: unknown parameter; did you mean `k_edge`?");
  CHECK(scene_error_of(scene(kBird, R"(, "params": {"dt": 0})")) ==
        "scene.json: params.dt: expected a number in [1e-06, 1], got 0");
  CHECK(scene_error_of(scene(kBird, R"(, "params": {"k_edge": -1})")) ==
        "scene.json: params.k_edge: expected a number >= 0, got -1");
  CHECK(scene_error_of(scene(kBird, R"(, "params": {"check_interval": 2.5})")) ==
        "scene.json: params.check_interval: expected an integer in [1, 100000], got 2.5");
}

TEST_CASE("parse_scene: slices out of range or given twice") {
  CHECK(scene_error_of(scene(kBird, R"(, "slices": 1)")) ==
        "scene.json: slices: expected an integer in [2, 1000], got 1");
  CHECK(scene_error_of(scene(kBird, R"(, "slices": 20, "params": {"slices": 30})")) ==
        "scene.json: slices: given twice, here and as params.slices; keep one");
}

TEST_CASE("parse_scene: orientation fields that do not apply to the mode") {
  CHECK_THAT(scene_error_of(scene(kBird, R"(, "orientation": {"angle": 10})")),
             StartsWith("scene.json: orientation.angle: applies only to mode `fixed`"));
  CHECK_THAT(scene_error_of(scene(kBird, R"(, "orientation": {"mode": "field"})")),
             StartsWith("scene.json: orientation: mode `field` needs a `field` object"));
  CHECK_THAT(
      scene_error_of(scene(kBird, R"(, "orientation": {"mode": "field", "field": {"kind": "radial", "angle": 3}})")),
      StartsWith("scene.json: orientation.field.angle: applies only to kind `constant`"));
}

TEST_CASE("parse_scene: total count disagreeing with the element counts") {
  CHECK(scene_error_of(scene(R"([{"art": "bird.path", "count": 4}])", R"(, "count": 6)")) ==
        "scene.json: count: 6 unguided elements, but the elements' `count`s add up to 4 and no element is drawn by "
        "weight; "
        "make them agree or use \"fill\"");
  CHECK(scene_error_of(scene(R"([{"art": "bird.path", "count": 4}, {"art": "cat.path"}])", R"(, "count": 6)")) ==
        "(no error)");
  CHECK(scene_error_of(scene(kBird, R"(, "count": "all")")) ==
        "scene.json: count: expected an integer or \"fill\", got \"all\"");
}

TEST_CASE("parse_scene: the example in docs/scene-format.md is valid") {
  std::ifstream doc(std::string(ANIMPAK_SOURCE_DIR) + "/docs/scene-format.md");
  REQUIRE(doc.good());
  const std::string text((std::istreambuf_iterator<char>(doc)), std::istreambuf_iterator<char>());
  const std::size_t begin = text.find("```json\n");
  REQUIRE(begin != std::string::npos);
  const std::size_t end = text.find("```", begin + 8);
  const SceneSpec s = parse_scene(text.substr(begin + 8, end - begin - 8), "scene-format.md",
                                  std::filesystem::path(ANIMPAK_SOURCE_DIR) / "examples");
  CHECK(s.elements.size() == 4);
  CHECK(s.guided.size() == 2);
  CHECK(s.orientation.field == FieldKind::tangential);
  CHECK(s.params.forces.k_torsion == 0.2);
}

namespace {

/// The JSON pointer of every object in `value`, the value itself first.
void collect_objects(const nlohmann::json& value, const nlohmann::json::json_pointer& at,
                     std::vector<nlohmann::json::json_pointer>& out) {
  if (value.is_object()) out.push_back(at);
  if (value.is_object())
    for (const auto& [key, inner] : value.items()) collect_objects(inner, at / key, out);
  if (value.is_array())
    for (std::size_t i = 0; i < value.size(); ++i) collect_objects(value[i], at / i, out);
}

using Pointer = nlohmann::json::json_pointer;

/// The object schema that `schema` (a property's or an array's items') refers to, or null when it
/// describes no object.
const nlohmann::json* object_schema(const nlohmann::json& root, const nlohmann::json& schema) {
  if (schema.contains("$ref")) return &root.at("$defs").at(schema.at("$ref").get<std::string>().substr(8));
  if (schema.contains("anyOf"))
    for (const nlohmann::json& either : schema.at("anyOf"))
      if (const nlohmann::json* found = object_schema(root, either)) return found;
  return schema.value("type", "") == "object" ? &schema : nullptr;
}

/// Every (object, key) of `value` that its schema `object` lists as required.
void collect_required(const nlohmann::json& root, const nlohmann::json& object, const nlohmann::json& value,
                      const Pointer& at, std::vector<std::pair<Pointer, std::string>>& out) {
  for (const nlohmann::json& key : object.value("required", nlohmann::json::array()))
    out.emplace_back(at, key.get<std::string>());
  for (const auto& [key, inner] : value.items()) {
    const nlohmann::json& property = object.at("properties").at(key);
    if (inner.is_object())
      if (const nlohmann::json* found = object_schema(root, property))
        collect_required(root, *found, inner, at / key, out);
    if (inner.is_array() && property.contains("items"))
      if (const nlohmann::json* found = object_schema(root, property.at("items")))
        for (std::size_t i = 0; i < inner.size(); ++i) collect_required(root, *found, inner[i], at / key / i, out);
  }
}

}  // namespace

TEST_CASE("parse_scene: every key the schema requires, the parser requires") {
  std::ifstream file(std::string(ANIMPAK_SOURCE_DIR) + "/tests/io/every-object.json");
  REQUIRE(file.good());
  const nlohmann::json every = nlohmann::json::parse(file);
  const nlohmann::json schema = nlohmann::json::parse(scene_json_schema());
  std::vector<std::pair<Pointer, std::string>> required;
  collect_required(schema, schema, every, Pointer(), required);
  CHECK(required.size() >= 10);
  for (const auto& [at, key] : required) {
    INFO(at.to_string() << " " << key);
    nlohmann::json missing = every;
    missing[at].erase(key);
    CHECK_THAT(scene_error_of(missing.dump()), Contains("missing required field `" + key + "`"));
  }
}

// tests/docs/validate_scenes.py plants the same keys in the same file and checks that the schema rejects them.
TEST_CASE("parse_scene: an unknown key is an error in every object of the format") {
  std::ifstream file(std::string(ANIMPAK_SOURCE_DIR) + "/tests/io/every-object.json");
  REQUIRE(file.good());
  const nlohmann::json every = nlohmann::json::parse(file);
  CHECK(scene_error_of(every.dump()) == "(no error)");
  std::vector<nlohmann::json::json_pointer> objects;
  collect_objects(every, nlohmann::json::json_pointer(), objects);
  CHECK(objects.size() >= 12);
  for (const nlohmann::json::json_pointer& at : objects) {
    INFO(at.to_string());
    nlohmann::json planted = every;
    planted[at]["unknown_key"] = 1;
    CHECK_THAT(scene_error_of(planted.dump()), Contains("unknown_key: unknown "));
  }
}

TEST_CASE("parse_scene: $schema and the format version") {
  CHECK(scene_error_of(scene(kBird, R"(, "$schema": "../../docs/scene.schema.json", "version": 1)")) == "(no error)");
  CHECK(scene_error_of(scene(kBird, R"(, "$schema": "")")) == "(no error)");
  CHECK(scene_error_of(scene(kBird, R"(, "$schema": 1)")) == "scene.json: $schema: expected a string, got 1");
  CHECK(scene_error_of(scene(kBird, R"(, "version": 0)")) ==
        "scene.json: version: expected an integer in [1, 2147483647], got 0");
  CHECK(scene_error_of(scene(kBird, R"(, "version": 1.5)")) ==
        "scene.json: version: expected an integer in [1, 2147483647], got 1.5");
  // A newer file's new keys are not reported as unknown: the version explains them.
  CHECK(scene_error_of(scene(kBird, R"(, "version": 2, "new_field": true)")) ==
        "scene.json: version: scene format version 2 is newer than this animpak reads (1); upgrade animpak to "
        "read this scene");
  static_assert(kSceneFormatVersion == 1, "a new format version needs the messages above and docs/scene-format.md");
}

TEST_CASE("scene_json_schema: is docs/scene.schema.json, strict where the parser is") {
  const nlohmann::json schema = nlohmann::json::parse(scene_json_schema());
  CHECK(schema["additionalProperties"] == false);
  for (const auto& [name, definition] : schema["$defs"].items()) {
    INFO(name);
    CHECK(definition["additionalProperties"] == false);
  }
  CHECK(schema["$defs"]["params"]["properties"].size() == param_table().size());
  CHECK(schema["$defs"]["params"]["properties"]["slices"] ==
        nlohmann::json::parse(R"j({"description": "n_s: slices along the time axis (§3.1)", "type": "integer",
                                   "minimum": 2, "maximum": 1000, "default": 100})j"));
  CHECK(schema["properties"]["version"]["maximum"] == kSceneFormatVersion);
}

TEST_CASE("parse_scene: mirror takes one line, x or y, and a side that matches it") {
  const SceneSpec none = parse_scene_text(scene(kBird));
  CHECK_FALSE(none.mirror);
  const SceneSpec vertical = parse_scene_text(scene(kBird, R"(, "mirror": {"x": 250.5})"));
  REQUIRE(vertical.mirror);
  CHECK(vertical.mirror->vertical);
  CHECK(vertical.mirror->at == 250.5);
  CHECK(vertical.mirror->keep_low);
  const SceneSpec bottom = parse_scene_text(scene(kBird, R"(, "mirror": {"y": 90, "keep": "bottom"})"));
  REQUIRE(bottom.mirror);
  CHECK_FALSE(bottom.mirror->vertical);
  CHECK(bottom.mirror->at == 90.0);
  CHECK_FALSE(bottom.mirror->keep_low);
  CHECK(parse_scene_text(scene(kBird, R"(, "mirror": {"x": 1, "keep": "right"})")).mirror->keep_low == false);

  CHECK_THAT(scene_error_of(scene(kBird, R"(, "mirror": {"x": 250, "y": 250})")),
             Contains("mirror.y") && Contains("not both"));
  CHECK_THAT(scene_error_of(scene(kBird, R"(, "mirror": {"keep": "left"})")),
             Contains("mirror") && Contains("{\"x\": X} (vertical) or {\"y\": Y} (horizontal)"));
  CHECK_THAT(scene_error_of(scene(kBird, R"(, "mirror": {"x": 250, "keep": "top"})")),
             Contains("mirror.keep") && Contains("\"left\" or \"right\""));
  CHECK_THAT(scene_error_of(scene(kBird, R"(, "mirror": {"y": 250, "keep": "left"})")),
             Contains("mirror.keep") && Contains("\"top\" or \"bottom\""));
  CHECK_THAT(scene_error_of(scene(kBird, R"(, "mirror": {"x": "middle"})")), Contains("mirror.x"));
  CHECK_THAT(scene_error_of(scene(kBird, R"(, "mirror": {"x": 250, "at": 3})")), Contains("mirror") && Contains("at"));
}

TEST_CASE("parse_scene: nesting deeper than 64 levels is refused while parsing, however deep") {
  // 100,000 nested arrays overflowed the stack printing the error's "got …" (a crash, exit 139).
  for (const int depth : {65, 100000}) {
    INFO("depth " << depth);
    const std::string text = R"({"container": {"art": "heart.path"}, "elements": )" + std::string(depth, '[') +
                             std::string(depth, ']') + "}";
    CHECK_THAT(scene_error_of(text), Contains("nested more than 64 levels deep"));
  }
  // 64 levels parse, and the error is about what they hold.
  const std::string text =
      R"({"container": {"art": "heart.path"}, "elements": )" + std::string(63, '[') + std::string(63, ']') + "}";
  CHECK_THAT(scene_error_of(text), !Contains("nested more than"));
}

TEST_CASE("parse_scene: an element's exclude is a list of distinct selectors, and only for SVG art") {
  const std::string star = std::string(ANIMPAK_SOURCE_DIR) + "/examples/default/star.svg";
  const auto with = [&](const std::string& exclude) {
    return scene(R"([{"art": ")" + star + R"(", "exclude": )" + exclude + "}]");
  };
  const SceneSpec s = parse_scene_text(with(R"(["#shadow", ".shade", "g#layer1 > path"])"));
  CHECK(s.elements[0].exclude == std::vector<std::string>{"#shadow", ".shade", "g#layer1 > path"});
  CHECK(parse_scene_text(scene(kBird)).elements[0].exclude.empty());
  CHECK(scene_error_of(with(R"("#shadow")")) == "scene.json: elements[0].exclude: expected an array, got \"#shadow\"");
  CHECK(scene_error_of(with(R"([""])")) == "scene.json: elements[0].exclude[0]: expected a non-empty string, got \"\"");
  CHECK(scene_error_of(with(R"(["#a", "#a"])")) == "scene.json: elements[0].exclude[1]: \"#a\" is listed twice");
  CHECK_THAT(scene_error_of(scene(R"([{"art": "bird.path", "exclude": ["#a"]}])")),
             StartsWith("scene.json: elements[0].exclude: a .path file has no ids or classes to select a piece by"));
}
