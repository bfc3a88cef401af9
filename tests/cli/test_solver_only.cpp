// animpak-solve, the command a GPU machine with nothing but an OpenCL driver runs: it offers only the
// solver commands, its pack writes state.bin and stats.json without frames, and the full animpak renders
// that folder afterwards as if it had packed it itself.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <fstream>

#include "animpak/version.hpp"
#include "run_animpak.hpp"
#include "scene/tiny_scenes.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;

TEST_CASE("animpak-solve --help: lists the solver commands and none that draw") {
  const CommandResult help = run_animpak_solve("--help");
  REQUIRE(help.code == 0);
  for (const char* command : {"pack", "devices", "validate", "bench", "params", "schema"}) {
    INFO(command);
    CHECK(help.out.find("\n  " + std::string(command) + " ") != std::string::npos);
  }
  // The footer names them as missing; no line may offer them as a command.
  CHECK(help.out.find("\n  inspect ") == std::string::npos);
  CHECK(help.out.find("\n  render ") == std::string::npos);
  // The same commit as animpak's, from the same build.
  const std::string version = run_animpak("--version").out;
  REQUIRE(version.rfind("animpak " + std::string(animpak::animpak_version) + " (commit ", 0) == 0);
  CHECK(run_animpak_solve("--version").out == "animpak-solve" + version.substr(std::string("animpak").size()));
}

TEST_CASE("animpak-solve: inspect, render and bench --plot are usage errors that say why") {
  CHECK(run_animpak_solve("inspect scene.json").code == 1);
  CHECK(run_animpak_solve("render somewhere").code == 1);
  const CommandResult plot = run_animpak_solve("bench --plot p.png --sizes 100");
  CHECK(plot.code == 1);
  CHECK_THAT(plot.err, Contains("rendering library"));
}

TEST_CASE("animpak-solve pack, then animpak render: state and statistics here, frames there") {
  const animpak::test::TempDir scratch("animpak-solve-");
  const fs::path& dir = scratch.path();
  std::ofstream(dir / "scene.json") << animpak::test::star_scene(3, 5, 2);
  const std::string out = (dir / "out").string();

  const CommandResult packed = run_animpak_solve("pack " + (dir / "scene.json").string() + " --out " + out +
                                                 " --max-iterations 20 --device reference");
  INFO(packed.err);
  REQUIRE(packed.code == 0);
  CHECK(fs::exists(dir / "out" / "state.bin"));
  REQUIRE(fs::exists(dir / "out" / "stats.json"));
  CHECK_FALSE(fs::exists(dir / "out" / "frames"));
  CHECK_THAT(packed.err, Contains("animpak render " + out));
  const nlohmann::json stats = nlohmann::json::parse(read_text(dir / "out" / "stats.json"));
  CHECK(stats["iterations"].get<std::uint64_t>() <= 20);
  CHECK(stats["frames"].empty());

  // A command line written for `animpak pack --no-render` runs unchanged.
  CHECK(run_animpak_solve("pack --resume " + out + " --max-iterations 25 --no-render --device reference").code == 0);

  const CommandResult rendered = run_animpak("render " + out + " --frames 2 --format png --size 32");
  INFO(rendered.err);
  REQUIRE(rendered.code == 0);
  CHECK(fs::exists(dir / "out" / "frames" / "frame_0000.png"));
  CHECK(fs::exists(dir / "out" / "frames" / "frame_0001.png"));
  CHECK_FALSE(fs::exists(dir / "out" / "frames" / "frame_0002.png"));
}
