// Small real scenes for the scene, solver, render and CLI tests: the example heart container and star
// (or shape) art, few elements and few slices, so that building and packing them takes seconds even
// under the sanitizers. Art paths are absolute, so the text works from any folder.
#pragma once

#include <cstdint>
#include <string>

namespace animpak::test {

inline std::string example_file(const std::string& relative) {
  return std::string(ANIMPAK_SOURCE_DIR) + "/examples/" + relative;
}

/// Members of a scene's top level after "elements" (each with a leading comma) and its params object.
struct SceneExtras {
  std::string top;     ///< e.g. R"(, "guided": [...])"
  std::string params;  ///< members of "params", without braces, e.g. R"("initial_scale": 0.1)"
};

inline constexpr const char* rotating = R"({"preset": "rotate", "turns": 1})";

/// `count` stars in the heart (count 0: none unguided, e.g. for guided-only scenes), each with the
/// `animation` object, by default one turn per loop.
inline std::string star_scene(int count, int slices, std::uint64_t seed, const SceneExtras& extras = {},
                              const std::string& animation = rotating) {
  return R"({"container": {"art": ")" + example_file("shapes/heart-container.path") +
         R"("}, "elements": [{"name": "star", "art": ")" + example_file("default/star.svg") + R"(", "count": )" +
         std::to_string(count) + R"(, "animation": )" + animation + "}]" + extras.top + R"(, "seed": )" +
         std::to_string(seed) + R"(, "slices": )" + std::to_string(slices) + R"(, "params": {)" + extras.params + "}}";
}

/// Two guided stars swapping places on separate arcs (so they never meet) and looping into each other;
/// "up" turns by 90° on the way.
inline SceneExtras swapping_pair(const std::string& params = "") {
  return {R"(, "guided": [
    {"name": "up", "element": "star", "loop_to": "down",
     "targets": [{"x": 220, "y": 250, "t": 0}, {"x": 250, "y": 200, "t": 0.5, "angle": 90}, {"x": 280, "y": 250, "t": 1}]},
    {"name": "down", "element": "star", "loop_to": "up",
     "targets": [{"x": 280, "y": 250, "t": 0}, {"x": 250, "y": 320, "t": 0.5}, {"x": 220, "y": 250, "t": 1}]}])",
          params};
}

}  // namespace animpak::test
