// docs/cli.md, "Limits": art and scenes that would run for hours or fill the memory exit 2 at once, with
// the error every command gives for bad input.
#include <catch2/catch.hpp>

#include <cstdint>
#include <fstream>
#include <string>

#include "run_animpak.hpp"
#include "temp_dir.hpp"

namespace {

/// A .path file of one filled path through `n` random points of a 500-unit square, from a fixed LCG:
/// about n² / 8.5 crossings.
std::filesystem::path random_path_file(const animpak::test::TempDir& dir, int n) {
  std::uint64_t state = 7;
  std::string points;
  for (int i = 0; i < 2 * n; ++i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    points += " " + std::to_string(static_cast<double>(state >> 11) * 0x1.0p-53 * 500.0);
  }
  const auto file = dir / ("random" + std::to_string(n) + ".path");
  std::ofstream(file) << "1\nforeground_color_rgb 0 -1,-1,-1\nbackground_color_rgb 0 120,120,120\n0 1 0" << points
                      << "\n";
  return file;
}

}  // namespace

TEST_CASE("animpak check: art whose path crosses itself 470000 times exits 2 naming the path", "[limits]") {
  const animpak::test::TempDir dir("animpak-limits-");
  const CommandResult r = run_animpak("check " + random_path_file(dir, 2000).string());
  CHECK(r.code == 2);
  CHECK(r.err.find("animpak: error: " + (dir / "random2000.path").string() +
                   ": its paths cross themselves more than 100000 times (most: path 0 ('path0'), 2000 points") !=
        std::string::npos);
  CHECK(r.err.find("simplify the path in your editor") != std::string::npos);
}

TEST_CASE("animpak pack and check: a scene of count 100000 exits 2 with the elements it would build", "[limits]") {
  const animpak::test::TempDir dir("animpak-limits-");
  const auto scene = dir / "scene.json";
  std::ofstream(scene) << R"({"container": ")" << shapes_dir() << R"(/heart-container.path", "elements": [{"art": ")"
                       << shapes_dir() << R"(/bird.path"}], "count": 100000})";
  for (const std::string& command : {std::string("check "), "pack --out " + (dir / "out").string() + " "}) {
    INFO(command);
    const CommandResult r = run_animpak(command + scene.string());
    CHECK(r.code == 2);
    CHECK(r.err.find("count: the scene would build 100000 elements (100000 unguided, 0 guided), more than the 10000") !=
          std::string::npos);
  }
  CHECK_FALSE(std::filesystem::exists(dir / "out" / "state.bin"));
}
