#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

#include "animpak/bench.hpp"
#include "run_animpak.hpp"
#include "scene/tiny_scenes.hpp"
#include "skip.hpp"
#include "temp_dir.hpp"

namespace {

std::string examples() { return std::string(ANIMPAK_SOURCE_DIR) + "/examples"; }

}  // namespace

// Only the shape of the results is checked: wall times differ from machine to machine.
TEST_CASE("animpak bench: JSON rows for every world, with phases, a fit and a written plot") {
  const animpak::test::TempDir scratch("animpak-bench-");
  const auto json_file = scratch / "bench.json", plot = scratch / "bench.png";
  const CommandResult r = run_animpak("bench --sizes 2000,4000 --steps 2 --warmup 1 --examples " + examples() +
                                      " --json " + json_file.string() + " --plot " + plot.string());
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("ms per 1k vertices") != std::string::npos);

  const nlohmann::json j = nlohmann::json::parse(read_text(json_file));
  const auto& results = j.at("results");
  REQUIRE(results.size() == 5);  // two synthetic sizes and the three example scenes
  std::vector<std::string> scenes;
  for (const auto& row : results) {
    scenes.push_back(row.at("scene").get<std::string>());
    CHECK(row.at("device") == "reference");
    CHECK(row.at("vertices").get<int>() > 0);
    CHECK(row.at("ms_per_iter").get<double>() > 0.0);
    CHECK(row.at("reference_ms_per_iter") == row.at("ms_per_iter"));
    CHECK(row.at("speedup").get<double>() == 1.0);
    for (const char* phase : {"grid", "forces", "integrate", "constraints", "loop", "growth", "statistics"})
      CHECK(row.at("phases").at(phase).get<double>() >= 0.0);
  }
  // The constant-density series is the default.
  CHECK(scenes == std::vector<std::string>{"constant-2000", "constant-4000", "default", "aquarium", "annulus"});
  CHECK(results[0].at("series") == "constant");
  CHECK(results[2].at("series") == "example");
  // Synthetic worlds land near their target size (whole elements of one size).
  CHECK(std::abs(results[0].at("vertices").get<int>() - 2000) < 700);
  CHECK(std::abs(results[1].at("vertices").get<int>() - 4000) < 700);
  for (const auto& row : results)
    CHECK(row.at("visits_per_vertex").get<double>() ==
          Approx(row.at("neighbour_visits").get<double>() / row.at("vertices").get<double>()));
  REQUIRE(j.at("fits").size() == 1);
  CHECK(j.at("fits")[0].at("series") == "constant");
  CHECK(j.at("fits")[0].at("points") == 2);
  CHECK(j.at("fits")[0].at("cost_ratio_largest_to_smallest").get<double>() > 0.0);

  REQUIRE(std::filesystem::exists(plot));
  CHECK(std::filesystem::file_size(plot) > 1000);
}

TEST_CASE("animpak bench: an unknown device is a usage error, a missing examples folder is bad input") {
  CHECK(run_animpak("bench --device no-such-device --sizes 2000").code == 1);
  const CommandResult missing = run_animpak("bench --sizes 2000 --steps 1 --examples /nonexistent");
  CHECK(missing.code == 2);
  CHECK(missing.err.find("/nonexistent") != std::string::npos);
}

TEST_CASE("animpak bench --grid-sort both: each OpenCL device timed with each sort, rows say which") {
  if (run_animpak("devices").out.find("Device:") == std::string::npos)
    return animpak::test::skip("no OpenCL device (Debian package pocl-opencl-icd): bench --grid-sort both not tested");
  const animpak::test::TempDir scratch("animpak-bench-");
  const auto json_file = scratch / "bench-sorts.json";
  const CommandResult r = run_animpak(
      "bench --device pocl --grid-sort both --sizes 2000 --steps 2 --warmup 1 "
      "--no-example-scenes --examples " +
      examples() + " --json " + json_file.string());
  INFO(r.err);
  if (r.code == 1 && r.err.find("pocl") != std::string::npos)
    return animpak::test::skip("no PoCL device (Debian package pocl-opencl-icd): bench --grid-sort both not tested");
  REQUIRE(r.code == 0);
  const nlohmann::json j = nlohmann::json::parse(read_text(json_file));
  std::vector<std::string> rows;
  for (const auto& row : j.at("results"))
    rows.push_back(row.at("device").get<std::string>() + "/" +
                   (row.at("grid_sort").is_null() ? std::string("-") : row.at("grid_sort").get<std::string>()));
  CHECK(rows == std::vector<std::string>{"reference/-", "pocl:host/host", "pocl:device/device"});
  for (const auto& row : j.at("results")) CHECK(row.at("ms_per_iter").get<double>() > 0.0);

  CHECK(run_animpak("bench --grid-sort sideways --sizes 2000").code == 1);
  CHECK(run_animpak("pack --grid-sort sideways " + examples() + "/default/scene.json --out " +
                    (scratch / "never").string())
            .code == 1);
}

TEST_CASE("animpak bench --series both: constant and dense worlds, a fit for each, visits per vertex printed") {
  const animpak::test::TempDir scratch("animpak-bench-");
  const auto json_file = scratch / "bench-series.json";
  const CommandResult r = run_animpak(
      "bench --series both --sizes 2000,8000 --steps 1 --warmup 0 --no-example-scenes "
      "--examples " +
      examples() + " --json " + json_file.string());
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Matchers::Contains("reference, constant series: "));
  CHECK_THAT(r.out, Catch::Matchers::Contains("reference, dense series: "));
  CHECK_THAT(r.out, Catch::Matchers::Contains("visits per vertex"));
  const nlohmann::json j = nlohmann::json::parse(read_text(json_file));
  std::vector<std::string> scenes;
  for (const auto& row : j.at("results")) scenes.push_back(row.at("scene").get<std::string>());
  CHECK(scenes == std::vector<std::string>{"constant-2000", "constant-8000", "dense-2000", "dense-8000"});
  REQUIRE(j.at("fits").size() == 2);
  CHECK(j.at("fits")[0].at("series") == "constant");
  CHECK(j.at("fits")[1].at("series") == "dense");
  for (const auto& fit : j.at("fits")) {
    CHECK(fit.at("device") == "reference");
    CHECK(fit.at("visits_per_vertex_min").get<double>() <= fit.at("visits_per_vertex_max").get<double>());
  }
  CHECK(run_animpak("bench --series sparse --sizes 2000").code == 1);
}

TEST_CASE("animpak bench --scene: times the given scene by its path, alone or beside a series") {
  const std::string scene = examples() + "/aquarium/scene.json";
  const animpak::test::TempDir scratch("animpak-bench-");
  const auto json_file = scratch / "bench-scene.json";
  CommandResult r = run_animpak("bench --scene " + scene + " --steps 1 --warmup 0 --examples " + examples() +
                                " --json " + json_file.string());
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Matchers::Contains(scene));
  nlohmann::json j = nlohmann::json::parse(read_text(json_file));
  // Instead of the synthetic worlds and the example scenes: one row.
  REQUIRE(j.at("results").size() == 1);
  CHECK(j.at("results")[0].at("scene") == scene);
  CHECK(j.at("results")[0].at("series") == "scene");
  CHECK(j.at("results")[0].at("vertices").get<int>() > 0);

  r = run_animpak("bench --scene " + scene + " --series dense --sizes 2000 --steps 1 --warmup 0 --examples " +
                  examples() + " --json " + json_file.string());
  REQUIRE(r.code == 0);
  j = nlohmann::json::parse(read_text(json_file));
  std::vector<std::string> scenes;
  for (const auto& row : j.at("results")) scenes.push_back(row.at("scene").get<std::string>());
  CHECK(scenes == std::vector<std::string>{scene, "dense-2000"});
}

TEST_CASE("animpak bench --state: times steps from a packed state, a folder or its state.bin") {
  const animpak::test::TempDir scratch("animpak-bench-");
  const std::string scene = (scratch / "scene.json").string(), packed = (scratch / "packed").string();
  std::ofstream(scene) << animpak::test::star_scene(3, 5, 2);
  REQUIRE(run_animpak("pack " + scene + " --out " + packed + " --max-iterations 30 --no-render").code == 0);
  const auto json_file = scratch / "bench-state.json";
  CommandResult r = run_animpak("bench --state " + packed + " --state " + packed +
                                "/state.bin --steps 1 --warmup 0 "
                                "--examples " +
                                examples() + " --json " + json_file.string());
  INFO(r.err);
  REQUIRE(r.code == 0);
  nlohmann::json j = nlohmann::json::parse(read_text(json_file));
  // The two states and nothing else.
  REQUIRE(j.at("results").size() == 2);
  CHECK(j.at("results")[0].at("scene") == packed);
  CHECK(j.at("results")[1].at("scene") == packed + "/state.bin");
  for (const auto& row : j.at("results")) {
    CHECK(row.at("series") == "state");
    CHECK(row.at("elements") == 3);
    CHECK(row.at("vertices").get<int>() > 0);
  }
  // A folder without a state is bad input naming the file.
  r = run_animpak("bench --state " + scratch.path().string() + " --steps 1 --examples " + examples());
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Matchers::Contains((scratch / "state.bin").string()));
}

TEST_CASE("animpak bench --scene with a missing file is bad input naming the file") {
  const animpak::test::TempDir scratch("animpak-bench-");
  const std::string missing = (scratch / "no-such-scene.json").string();
  const CommandResult r = run_animpak("bench --scene " + missing + " --steps 1 --examples " + examples());
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Matchers::Contains(missing));
}

TEST_CASE("bench fit: least-squares slope and intercept over one device's rows of one series") {
  using animpak::BenchRow;
  auto row = [](std::string device, std::string series, int vertices, double ms, std::int64_t visits) {
    BenchRow r;
    r.device = std::move(device);
    r.series = std::move(series);
    r.vertices = vertices;
    r.timing.ms_per_iter = ms;
    r.timing.phases_ms.forces = ms / 2;
    r.neighbour_visits = visits;
    return r;
  };
  // ms = 2 + 0.5 per 1,000 vertices with a residual of +1, -2, +1 (which leaves the line unchanged),
  // among rows of another series, another device and a scene that the fit must leave out.
  const std::vector<BenchRow> rows{
      row("reference", "constant", 10000, 8.0, 1000000), row("reference", "dense", 20000, 500.0, 9000000),
      row("pocl", "constant", 20000, 1.0, 2400000),      row("reference", "constant", 20000, 10.0, 2400000),
      row("reference", "scene", 30000, 900.0, 1),        row("reference", "constant", 30000, 18.0, 3300000)};
  const animpak::LinearFit f = animpak::fit_series(rows, "reference", "constant");
  CHECK(f.points == 3);
  CHECK(f.slope_ms_per_kvertex == Approx(0.5));
  CHECK(f.intercept_ms == Approx(2.0));
  CHECK(f.min_visits_per_vertex == Approx(100.0));
  CHECK(f.max_visits_per_vertex == Approx(120.0));
  CHECK(f.cost_ratio == Approx((18.0 / 30000) / (8.0 / 10000)));
  // Forces (half of each step here) per neighbour visit, largest over smallest size.
  CHECK(f.visit_cost_ratio == Approx((9.0 / 3300000) / (4.0 / 1000000)));
  CHECK(animpak::fit_series(rows, "reference", "dense").points == 1);

  // A world with under one visit per vertex costs what its springs and overlap test cost, not its
  // visits: the ratio compares the worlds that visit.
  std::vector<BenchRow> sparse = rows;
  sparse.push_back(row("reference", "constant", 5000, 3.0, 2000));
  const animpak::LinearFit g = animpak::fit_series(sparse, "reference", "constant");
  CHECK(g.points == 4);
  CHECK(g.min_visits_per_vertex == Approx(0.4));
  CHECK(g.visit_cost_ratio == Approx(f.visit_cost_ratio));
}

TEST_CASE("animpak bench --repeat: every device timed once per round, in turn, and the median round reported") {
  const animpak::test::TempDir scratch("animpak-bench-");
  const std::string scene = (scratch / "scene.json").string();
  std::ofstream(scene) << animpak::test::star_scene(3, 5, 2);
  const auto json_file = scratch / "bench-repeat.json";
  const CommandResult r = run_animpak("bench --scene " + scene +
                                      " --device pocl --steps 1 --warmup 0 --repeat 3 --json " + json_file.string());
  INFO(r.err);
  REQUIRE(r.code == 0);
  // Rounds alternate between the devices.
  const std::size_t r1 = r.err.find("on reference, round 1"), p1 = r.err.find("on pocl, round 1"),
                    r2 = r.err.find("on reference, round 2"), p3 = r.err.find("on pocl, round 3");
  REQUIRE(p3 != std::string::npos);
  CHECK(r1 < p1);
  CHECK(p1 < r2);
  CHECK(r2 < p3);
  const nlohmann::json j = nlohmann::json::parse(read_text(json_file));
  REQUIRE(j.at("results").size() == 2);
  const auto& reference = j.at("results")[0];
  const auto& pocl = j.at("results")[1];
  REQUIRE(pocl.at("rounds_ms_per_iter").size() == 3);
  // The row is the median round, and the speedup the median of the rounds' own ratios.
  std::vector<double> rounds = pocl.at("rounds_ms_per_iter").get<std::vector<double>>();
  std::sort(rounds.begin(), rounds.end());
  CHECK(pocl.at("ms_per_iter").get<double>() == rounds[1]);
  std::vector<double> ratios;
  for (int k = 0; k < 3; ++k)
    ratios.push_back(reference.at("rounds_ms_per_iter")[k].get<double>() /
                     pocl.at("rounds_ms_per_iter")[k].get<double>());
  CHECK(pocl.at("rounds_speedup").get<std::vector<double>>() == ratios);
  std::sort(ratios.begin(), ratios.end());
  CHECK(pocl.at("speedup").get<double>() == ratios[1]);
  CHECK(reference.at("speedup").get<double>() == 1.0);
  CHECK_THAT(r.out, Catch::Matchers::Contains("spread%"));
}

TEST_CASE("bench: median_round picks the middle round by ms per step, the lower middle of an even count") {
  using animpak::StepTiming;
  const auto timing = [](double ms, double forces) {
    StepTiming t;
    t.ms_per_iter = ms;
    t.phases_ms.forces = forces;
    return t;
  };
  const StepTiming odd = animpak::median_round({timing(9, 1), timing(3, 2), timing(5, 3)});
  CHECK(odd.ms_per_iter == 5);
  CHECK(odd.phases_ms.forces == 3);  // the phases of that same round
  CHECK(animpak::median_round({timing(9, 1), timing(3, 2), timing(5, 3), timing(7, 4)}).ms_per_iter == 5);
  CHECK(animpak::median_round({}).ms_per_iter == 0);
  CHECK(animpak::median({4.0, 1.0, 2.0, 3.0}) == 2.5);
  CHECK(animpak::median({3.0, 1.0, 2.0}) == 2.0);
  CHECK(animpak::median({}) == 0.0);
}
