#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "run_animpak.hpp"
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
  CHECK(scenes == std::vector<std::string>{"synthetic-2000", "synthetic-4000", "default", "aquarium", "annulus"});
  // Synthetic worlds land near their target size (whole elements of one size).
  CHECK(std::abs(results[0].at("vertices").get<int>() - 2000) < 700);
  CHECK(std::abs(results[1].at("vertices").get<int>() - 4000) < 700);
  REQUIRE(j.at("fits").size() == 1);
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
  if (run_animpak("devices").out.find("Device:") == std::string::npos) {
    WARN("no OpenCL device: bench --grid-sort both not tested");
    return;
  }
  const animpak::test::TempDir scratch("animpak-bench-");
  const auto json_file = scratch / "bench-sorts.json";
  const CommandResult r = run_animpak("bench --device pocl --grid-sort both --sizes 2000 --steps 2 --warmup 1 "
                                      "--no-example-scenes --examples " + examples() + " --json " + json_file.string());
  INFO(r.err);
  if (r.code == 1 && r.err.find("pocl") != std::string::npos) {
    WARN("no PoCL device: bench --grid-sort both not tested");
    return;
  }
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
                    (scratch / "never").string()).code == 1);
}
