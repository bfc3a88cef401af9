// docs/cli.md, "Limits": what a scene asks for is bounded while it is read, before any art is opened.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "animpak/error.hpp"
#include "animpak/scene_spec.hpp"

using namespace animpak;
using Catch::Matchers::Contains;

namespace {

const std::filesystem::path kLimitShapes = std::filesystem::path(ANIMPAK_SOURCE_DIR) / "examples" / "shapes";

/// The InputError message for the scene `text`, or a marker that no error was thrown.
std::string limit_error_of(const std::string& text) {
  try {
    parse_scene(text, "scene.json", kLimitShapes);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

/// A scene of the heart and `elements` (a JSON array), with `rest` (top-level members, each with a
/// leading comma).
std::string limit_scene(const std::string& elements, const std::string& rest = "") {
  return R"({"container": "heart-container.path", "elements": )" + elements + rest + "}";
}

/// `n` entries of bird.path, named e0, e1, …, each with `count`.
std::string bird_entries(int n, int count) {
  std::string text = "[";
  for (int i = 0; i < n; ++i)
    text += std::string(i ? ", " : "") + R"({"name": "e)" + std::to_string(i) + R"(", "art": "bird.path", "count": )" +
            std::to_string(count) + "}";
  return text + "]";
}

}  // namespace

TEST_CASE("parse_scene: count 100000 is refused with the number of elements it would build", "[limits]") {
  // In the count field's range, [0, 100000], but past the 10,000 elements a scene may build: this ran
  // for hours seeding before it was refused.
  const std::string error =
      limit_error_of(limit_scene(R"([{"art": "bird.path", "count": 100000}])", R"(, "count": 100000)"));
  CHECK_THAT(error, Contains("scene.json: count: the scene would build 100000 elements (100000 unguided, 0 guided)") &&
                        Contains("more than the 10000 a scene may build") && Contains("lower `count`"));
  // Drawn by weight to the same count.
  CHECK_THAT(limit_error_of(limit_scene(R"([{"art": "bird.path"}])", R"(, "count": 100000)")),
             Contains("count: the scene would build 100000 elements"));
  // 10,000 is the limit itself.
  CHECK(limit_error_of(limit_scene(R"([{"art": "bird.path"}])", R"(, "count": 10000)")) == "(no error)");
}

TEST_CASE("parse_scene: element counts that add up past 10000 elements are refused", "[limits]") {
  const std::string two = R"([{"name": "a", "art": "bird.path", "count": 6000},
                              {"name": "b", "art": "cat.path", "count": 5000}])";
  CHECK_THAT(
      limit_error_of(limit_scene(two)),
      Contains("scene.json: elements: the elements' counts would build 11000 elements (11000 unguided, 0 guided)"));
  // Guided elements count too: 10,000 unguided and one guided.
  const std::string guided = R"(, "guided": [{"name": "g", "element": "a",
      "targets": [{"x": 250, "y": 200, "t": 0}, {"x": 250, "y": 200, "t": 1}]}])";
  CHECK_THAT(limit_error_of(limit_scene(R"([{"name": "a", "art": "bird.path", "count": 10000}])", guided)),
             Contains("10001 elements (10000 unguided, 1 guided)"));
}

TEST_CASE("parse_scene: more than 1000 element entries are refused before any is read", "[limits]") {
  // 100,000 entries with count 0 built 100,000 library elements, past 5.3 GB.
  CHECK_THAT(limit_error_of(limit_scene(bird_entries(100000, 0))),
             Contains("scene.json: elements: 100000 entries, more than the 1000 a scene may list") &&
                 Contains("one entry with a `count`"));
  CHECK_THAT(limit_error_of(limit_scene(bird_entries(1001, 0))), Contains("elements: 1001 entries"));
  CHECK(limit_error_of(limit_scene(bird_entries(1000, 0))) == "(no error)");
}

TEST_CASE("parse_scene: more than 10000 guided elements are refused before any is read", "[limits]") {
  std::string guided = R"(, "guided": [)";
  for (int i = 0; i <= 10000; ++i) guided += i ? ", {}" : "{}";
  CHECK_THAT(limit_error_of(limit_scene(R"([{"art": "bird.path"}])", guided + "]")),
             Contains("scene.json: guided: 10001 guided elements, more than the 10000 elements a scene may build"));
}
