// docs/cli.md, "Limits": make_world estimates the elements and mesh vertices a scene builds and refuses
// it, with the estimate, before the expensive steps (meshing the library, seeding).
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

/// The InputError make_world gives for the scene `text`, or a marker that none was thrown.
std::string size_error_of(const std::string& text) {
  try {
    make_world(parse_scene(text, "size.json", "/"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

/// Stars drawn by weight, filling `container` (the heart unless given) at `seed_spacing`.
std::string filling_stars(double seed_spacing, int slices, const std::string& params = "",
                          const std::string& container = example_file("shapes/heart-container.path")) {
  return R"({"container": {"art": ")" + container + R"("}, "elements": [{"name": "star", "art": ")" +
         example_file("default/star.svg") + R"("}], "slices": )" + std::to_string(slices) +
         R"(, "params": {"seed_spacing": )" + std::to_string(seed_spacing) + params + "}}";
}

}  // namespace

TEST_CASE("make_world: a scene of more than 10000000 mesh vertices is refused with the estimate, before seeding",
          "[limits]") {
  // 3,000 stars at 100 slices: 3,000 × 100 × 55 vertices, meshed once and never placed.
  CHECK_THAT(size_error_of(star_scene(3000, 100, 1)),
             Contains("size.json: the scene would build about 16,505,500 mesh vertices (3,000 elements and 1 "
                      "library element; 100 slices, 55 vertices per slice as meshed), more than the 10,000,000") &&
                 Contains("lower the counts or `slices`"));
}

TEST_CASE("make_world: a library that would mesh more than 10000000 vertices is refused before meshing", "[limits]") {
  // One star at interior_spacing 0.005 and 1,000 slices: about 54,000 vertices per slice.
  const std::string error = size_error_of(star_scene(1, 1000, 1, {"", R"("interior_spacing": 0.005)"}));
  CHECK_THAT(error, Contains("mesh vertices (1 library element, before any copy; 1000 slices, about 53,903 "
                             "vertices per slice, estimated from params.interior_spacing and "
                             "params.boundary_spacing)"));
}

TEST_CASE("make_world: a scene that fills is estimated from the container's area and the seed spacing", "[limits]") {
  // The heart covers 0.514 of the unit square: about 5,938 seeds at spacing 0.01, each a star of 55
  // vertices per slice.
  CHECK_THAT(size_error_of(filling_stars(0.01, 100)),
             Contains("about 32,664,500 mesh vertices (filling the container (0.514 of the unit square) at "
                      "params.seed_spacing 0.01 seeds about 5,938; 5,938 elements and 1 library element"));
  // A square container fills the unit square: about 11,547 seeds at the smallest spacing, more than
  // 10,000 elements, refused before any element is meshed.
  const TempDir dir("animpak-scene-size-");
  std::ofstream(dir / "square.path") << "1\nforeground_color_rgb 0 -1,-1,-1\nbackground_color_rgb 0 0,0,0\n"
                                        "0 1 0 0 0 100 0 100 100 0 100\n";
  const std::string crowded = size_error_of(filling_stars(0.01, 2, "", (dir / "square.path").string()));
  CHECK_THAT(crowded, Contains("the scene would build about 11,547 elements (filling the container (1 of the unit "
                               "square) at params.seed_spacing 0.01 seeds about 11,547; 11,547 unguided, 0 guided), "
                               "more than the 10,000 a scene may build") &&
                          Contains("raise params.seed_spacing"));
}
