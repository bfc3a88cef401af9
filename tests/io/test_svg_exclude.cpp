// An element's `exclude` (docs/scene-format.md, "Leaving pieces of the art out"): the SVG elements its
// selectors match, with everything inside them, are not imported, as if deleted from the file; a selector
// that matches nothing is an error that says what the file has. Every imported path says which elements
// it is drawn through (ArtPath::lineage), which `animpak check` names pieces by.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>

#include "animpak/error.hpp"
#include "animpak/io.hpp"
#include "svg_helpers.hpp"

using namespace animpak;
using Catch::Matchers::Contains;

namespace {

// A square body in a group, and apart from it a drop-shadow ellipse with an id and a class.
const std::string kBodyAndShadow = svg_test::doc(
    R"(<g id="bee"><rect id="body" class="part" x="0" y="0" width="100" height="100" fill="#fc0"/></g>
       <ellipse id="shadow" class="shade" cx="300" cy="150" rx="60" ry="10" fill="#000" fill-opacity="0.2"/>)",
    R"(viewBox="0 0 400 200")");

ArtShape parse_excluding(const std::string& text, std::vector<std::string> exclude) {
  SvgOptions options;
  options.exclude = std::move(exclude);
  return parse_svg(text, "bee.svg", options);
}

std::vector<std::string> ids_of(const ArtShape& art) {
  std::vector<std::string> ids;
  for (const ArtPath& p : art.paths) ids.push_back(p.id);
  return ids;
}

std::string exclude_error(const std::string& text, std::vector<std::string> exclude) {
  try {
    parse_excluding(text, std::move(exclude));
  } catch (const ExcludeError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("svg exclude: every path knows the elements it is drawn through") {
  const ArtShape art = parse_excluding(kBodyAndShadow, {});
  REQUIRE(ids_of(art) == std::vector<std::string>{"body", "shadow"});
  CHECK(lineage_text(art.paths[0]) == "g#bee > rect#body.part");
  CHECK(lineage_text(art.paths[1]) == "ellipse#shadow.shade");
  REQUIRE(art.paths[1].lineage.size() == 1);
  CHECK(art.paths[1].lineage[0].classes == std::vector<std::string>{"shade"});
  // Drawn through a <use>: the use first, then what it draws.
  const ArtShape used = svg_test::parse(R"(<defs><circle id="dot" r="5"/></defs><use id="u1" href="#dot" x="20"/>)");
  REQUIRE(used.paths.size() == 1);
  CHECK(lineage_text(used.paths[0]) == "use#u1 > circle#dot");
}

TEST_CASE("svg exclude: #id and .class leave the matching element out, and a group with everything in it") {
  CHECK(ids_of(parse_excluding(kBodyAndShadow, {"#shadow"})) == std::vector<std::string>{"body"});
  CHECK(ids_of(parse_excluding(kBodyAndShadow, {".shade"})) == std::vector<std::string>{"body"});
  CHECK(ids_of(parse_excluding(kBodyAndShadow, {" #shadow "})) == std::vector<std::string>{"body"});
  CHECK(ids_of(parse_excluding(kBodyAndShadow, {"#bee"})) == std::vector<std::string>{"shadow"});
  CHECK(ids_of(parse_excluding(kBodyAndShadow, {"g#bee > rect.part"})) == std::vector<std::string>{"shadow"});
  // What is left out draws nowhere: not through a <use> of it, nor of something inside it.
  const std::string used = svg_test::doc(
      R"(<g id="set"><circle id="dot" cx="5" cy="5" r="5"/></g><rect id="box" width="50" height="50"/>
         <use href="#dot" x="100"/><use href="#set" y="100"/>)");
  CHECK(ids_of(parse_excluding(used, {"#dot"})) == std::vector<std::string>{"box"});
  CHECK(ids_of(parse_excluding(used, {"#set"})) == std::vector<std::string>{"box"});
  // A <switch> draws its first child that is left, as if the one left out were deleted.
  const std::string chosen = svg_test::doc(
      R"(<switch><rect id="first" width="10" height="10"/><rect id="second" width="20" height="20"/></switch>)");
  CHECK(ids_of(parse_excluding(chosen, {})) == std::vector<std::string>{"first"});
  CHECK(ids_of(parse_excluding(chosen, {"#first"})) == std::vector<std::string>{"second"});
  // Everything left out: as a file with nothing drawable.
  CHECK_THROWS_WITH(parse_excluding(kBodyAndShadow, {"#bee", ".shade"}), Contains("no drawable geometry"));
}

TEST_CASE("svg exclude: a selector that matches nothing or is no selector is an error saying what there is") {
  const std::string near = exclude_error(kBodyAndShadow, {"#shadow", "#shadw"});
  CHECK_THAT(near, Contains("bee.svg: exclude \"#shadw\": matches no element of the file; did you mean \"#shadow\"?"));
  const std::string far = exclude_error(kBodyAndShadow, {".wing"});
  CHECK_THAT(far, Contains("exclude \".wing\": matches no element of the file"));
  CHECK_THAT(far,
             Contains("the ids of the elements that draw are #bee, #body, #shadow; their classes are .part, .shade"));
  CHECK_THAT(exclude_error(kBodyAndShadow, {"rect[x]"}), Contains("exclude \"rect[x]\": not a selector; give \"#id\""));
  CHECK_THAT(exclude_error(svg_test::doc(R"(<rect width="5" height="5"/>)"), {"#a"}),
             Contains("no element of it that draws has an id or a class"));
  try {
    parse_excluding(kBodyAndShadow, {"#shadow", "#shadw"});
    FAIL("no error");
  } catch (const ExcludeError& e) {
    CHECK(e.index == 1);
    CHECK(e.selector == "#shadw");
  }
}

TEST_CASE("svg exclude: a .path file takes no exclude") {
  const std::filesystem::path file = std::filesystem::path(ANIMPAK_SOURCE_DIR) / "examples/shapes/bird.path";
  CHECK(load_art(file).paths.size() == 2);
  SvgOptions options;
  options.exclude = {"#x"};
  CHECK_THROWS_WITH(load_art(file, options),
                    Contains("bird.path: exclude: a .path file has no ids or classes to select a piece by"));
}
