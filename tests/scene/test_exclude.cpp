// An element's `exclude` in a scene (docs/scene-format.md, "Leaving pieces of the art out"): the library
// element pack builds, whose outline the solver packs and whose art the frames draw, has none of what it
// leaves out; a selector that matches nothing names the scene's field, the element and its art.
#include <catch2/catch.hpp>

#include <fstream>
#include <string>

#include "animpak/error.hpp"
#include "animpak/scene.hpp"
#include "temp_dir.hpp"
#include "tiny_scenes.hpp"

using namespace animpak;
using namespace animpak::test;
using Catch::Matchers::Contains;

namespace {

// A square body and, apart from it, a drop-shadow ellipse with an id and a class.
constexpr const char* kBee = R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 300 100">
  <rect id="body" x="0" y="0" width="100" height="100" fill="#fc0"/>
  <ellipse id="shadow" class="shade" cx="250" cy="90" rx="40" ry="10" fill="#000" fill-opacity="0.2"/></svg>)";

std::string bee_scene(const std::filesystem::path& art, const std::string& exclude) {
  return R"({"container": {"art": ")" + example_file("shapes/heart-container.path") +
         R"("}, "elements": [{"name": "bee", "art": ")" + art.string() + R"(", "count": 1)" +
         (exclude.empty() ? "" : R"(, "exclude": )" + exclude) + R"(}], "slices": 3, "seed": 1})";
}

}  // namespace

TEST_CASE("make_world: an element's exclude leaves the piece out of its outline and its drawn art") {
  const TempDir dir("animpak-exclude-");
  const auto art = dir / "bee.svg";
  std::ofstream(art) << kBee;

  const World whole = make_world(parse_scene(bee_scene(art, ""), dir / "scene.json", dir.path()));
  REQUIRE(whole.library.size() == 1);
  CHECK(whole.library[0].art.art.paths.size() == 2);
  CHECK(whole.library[0].outline_pieces.size() == 2);

  for (const std::string exclude : {R"(["#shadow"])", R"([".shade"])"}) {
    INFO(exclude);
    const World world = make_world(parse_scene(bee_scene(art, exclude), dir / "scene.json", dir.path()));
    const SpacetimeElement& bee = world.library[0];
    REQUIRE(bee.art.art.paths.size() == 1);  // what the frames draw
    CHECK(bee.art.art.paths[0].id == "body");
    CHECK(bee.outline_pieces.empty());  // what the solver packs: one piece, no bridge
    CHECK(bee.bridge_radius == 0.0);
    CHECK(bee.notes.empty());
  }
}

TEST_CASE("make_world: an exclude selector that matches nothing names the scene's field, the element and the art") {
  const TempDir dir("animpak-exclude-");
  const auto art = dir / "bee.svg";
  std::ofstream(art) << kBee;
  const std::string scene = (dir / "scene.json").string();
  try {
    make_world(parse_scene(bee_scene(art, R"(["#shadow", "#shadw"])"), scene, dir.path()));
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Contains(scene + ": elements[0].exclude[1]: \"#shadw\" in " + art.string() +
                                  " (element `bee`): matches no element of the file; did you mean \"#shadow\"?"));
  }
}
