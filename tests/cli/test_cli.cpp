#include <catch2/catch.hpp>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <regex>

#include "animpak/param_table.hpp"
#include "animpak/version.hpp"
#include "run_animpak.hpp"
#include "temp_dir.hpp"

using Catch::Matchers::Contains;

TEST_CASE("animpak: --help for the program and every command exits 0 and describes it") {
  for (const std::string args : {"--help", "inspect --help", "devices --help"}) {
    INFO(args);
    const CommandResult r = run_animpak(args);
    CHECK(r.code == 0);
    CHECK(r.out.find("Usage") != std::string::npos);
  }
  CHECK(run_animpak("--help").out.find("inspect") != std::string::npos);
  CHECK(run_animpak("--version").out.find("animpak " + std::string(animpak::animpak_version) + " (") !=
        std::string::npos);
}

// That docs/ holds exactly this output is the `docs:` tests' job (tests/docs/generated_docs.py).
TEST_CASE("animpak: --help shows every option's default, in the shared commands and the frontend's alike") {
  const std::string render = run_animpak("render --help").out;
  CHECK(render.find("--frames INT:INT in [1 - 100000]=100") != std::string::npos);
  CHECK(render.find("--background TEXT=white") != std::string::npos);
  const std::string pack = run_animpak("pack --help").out;
  CHECK(pack.find("--grid-sort TEXT:{auto,host,device}=auto") != std::string::npos);
  const std::string bench = run_animpak("bench --help").out;
  CHECK(bench.find("--steps INT:INT in [1 - 100000]=") != std::string::npos);
}

TEST_CASE("animpak params and schema: the constants and the scene format, from the code's tables") {
  const CommandResult text = run_animpak("params");
  REQUIRE(text.code == 0);
  CHECK(text.out.rfind("name ", 0) == 0);
  CHECK(std::count(text.out.begin(), text.out.end(), '\n') == static_cast<long>(animpak::param_table().size()) + 1);
  CHECK_THAT(text.out, Contains("\nslices ") && Contains(" 100 ") && Contains("[2, 1000]"));

  const CommandResult markdown = run_animpak("params --markdown");
  REQUIRE(markdown.code == 0);
  CHECK(markdown.out.rfind("| name | default | range | paper | meaning |\n|---|", 0) == 0);
  CHECK_THAT(markdown.out, Contains("| `k_repulsion` | 8e-8 | ≥ 0 | k_rpl = 10 (Eq. 1) |"));

  const CommandResult schema = run_animpak("schema");
  REQUIRE(schema.code == 0);
  const nlohmann::json parsed = nlohmann::json::parse(schema.out);
  CHECK(parsed["$schema"] == "https://json-schema.org/draft/2020-12/schema");
  CHECK(parsed["required"] == nlohmann::json::array({"container", "elements"}));
}

TEST_CASE("animpak --version names the commit of the source tree it was built from, read at build time") {
  const std::string version = run_animpak("--version").out;
  std::smatch m;
  REQUIRE(std::regex_search(
      version, m, std::regex(R"(animpak [0-9]+\.[0-9]+\.[0-9]+ \(commit ([0-9a-f]{7,}|unknown)(-dirty)?\))")));
  // The tree's commit now, without the dirty mark: a test file edited since the build may add one. A
  // commit read when the build folder was configured, many commits ago, fails here.
  const CommandResult git = run_command("git -C '" ANIMPAK_SOURCE_DIR "' rev-parse --short=7 HEAD");
  if (git.code != 0) {
    CHECK(m[1] == "unknown");
    return;
  }
  const std::string head = git.out.substr(0, git.out.find_first_of(" \n"));
  CHECK(m[1] == head);
}

TEST_CASE("animpak: usage errors exit 1 with one line saying what is wrong") {
  CHECK(run_animpak("").code == 1);
  CHECK(run_animpak("frobnicate").code == 1);
  const CommandResult r = run_animpak("inspect --no-such-flag x.svg");
  CHECK(r.code == 1);
  CHECK(r.err.find("--no-such-flag") != std::string::npos);
  CHECK(run_animpak("inspect " + shapes_dir() + "/bird.path --slices 1").code == 1);
}

TEST_CASE("animpak: --fps must be a finite number and --seed a whole number that fits 64 bits") {
  // NaN passed the range check and wrote "fr":nan into animation.json; -1, 2^64 and 1e23 became
  // 18446744073709551615 without a word. Refused before anything is read.
  for (const char* fps : {"nan", "inf", "1e999"}) {
    const CommandResult r = run_animpak(std::string("render nowhere --format lottie --fps ") + fps);
    INFO(fps << ": " << r.err);
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Contains("--fps: ") && Contains("expected a finite number, got "));
  }
  for (const char* seed : {"-1", "18446744073709551616", "1e23", "3.5", "+4"}) {
    const CommandResult r = run_animpak(std::string("pack scene.json --out nowhere --seed=") + seed);
    INFO(seed << ": " << r.err);
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Contains("--seed: expected a whole number from 0 to 18446744073709551615, got "));
  }
}

TEST_CASE("animpak inspect: a missing or unsupported file exits 2 and names it") {
  const CommandResult missing = run_animpak("inspect /nonexistent/bird.svg");
  CHECK(missing.code == 2);
  CHECK(missing.err.rfind("animpak: error: ", 0) == 0);
  CHECK(missing.err.find("/nonexistent/bird.svg") != std::string::npos);
  const CommandResult unsupported = run_animpak("inspect " + std::string(ANIMPAK_SOURCE_DIR) + "/CMakeLists.txt");
  CHECK(unsupported.code == 2);
  CHECK(unsupported.err.find("CMakeLists.txt") != std::string::npos);
}

TEST_CASE("animpak inspect --json: counts follow the extrusion formulas") {
  const int slices = 7;
  const CommandResult r =
      run_animpak("inspect " + shapes_dir() + "/bird.path --json --slices " + std::to_string(slices));
  REQUIRE(r.code == 0);
  const nlohmann::json report = nlohmann::json::parse(r.out);
  REQUIRE(report["elements"].size() == 1);
  const auto& e = report["elements"][0];
  CHECK(e["name"] == "bird");
  const int per_slice = e["vertices_per_slice"];
  CHECK(e["vertices"] == slices * per_slice);
  const int time = e["springs"]["time"];
  const int envelope = e["envelope_triangles"];
  // 3 time edges and 2 envelope triangles per boundary edge and slice gap (paper §3.1)
  CHECK(time % (3 * (slices - 1)) == 0);
  CHECK(envelope * 3 == time * 2);
  CHECK(e["springs"]["edge"].get<int>() % slices == 0);
  CHECK(e["springs"]["shear"].get<int>() % slices == 0);
  CHECK(e["springs"]["negative_space"].get<int>() % slices == 0);
}

TEST_CASE("animpak inspect --out: writes the slice, art and strip pictures of every element") {
  const animpak::test::TempDir scratch("animpak-inspect-");
  const auto dir = scratch / "out";
  const CommandResult r =
      run_animpak("inspect " + shapes_dir() + "/snake.path --slices 4 --size 64 --out " + dir.string());
  REQUIRE(r.code == 0);
  for (const char* suffix : {"-slice.png", "-art.png", "-strip.png"}) {
    INFO(suffix);
    CHECK(std::filesystem::file_size(dir / (std::string("snake") + suffix)) > 100);
  }
}

TEST_CASE("animpak inspect: the default example scene builds every library element") {
  const CommandResult r =
      run_animpak("inspect " + std::string(ANIMPAK_SOURCE_DIR) + "/examples/default/scene.json --json --slices 4");
  REQUIRE(r.code == 0);
  const nlohmann::json report = nlohmann::json::parse(r.out);
  REQUIRE(report["elements"].size() >= 1);
  for (const auto& e : report["elements"]) CHECK(e["vertices"].get<int>() > 0);
}

TEST_CASE("animpak devices: lists each device with its build result and the default choice") {
  const CommandResult r = run_animpak("devices");
  CHECK(r.code == 0);
  CHECK(r.out.find("Default for pack: ") != std::string::npos);
  // Every device line is followed by whether the kernels build on it.
  std::size_t devices = 0, builds = 0;
  for (std::size_t at = 0; (at = r.out.find("  Device: ", at)) != std::string::npos; ++at) ++devices;
  for (std::size_t at = 0; (at = r.out.find("    kernels: ", at)) != std::string::npos; ++at) ++builds;
  CHECK(devices == builds);
}

TEST_CASE("animpak pack --device: a name no device has is a usage error naming it") {
  const auto scene = std::string(ANIMPAK_SOURCE_DIR) + "/examples/default/scene.json";
  const animpak::test::TempDir scratch("animpak-cli-device-");
  const CommandResult r =
      run_animpak("pack " + scene + " --out " + (scratch / "out").string() + " --device no-such-device --no-render");
  CHECK(r.code == 1);
  CHECK(r.err.find("no-such-device") != std::string::npos);
}
