// The time left that `pack` prints (docs/cli.md, "Progress and the time left"): StopModel replayed over
// progress traces recorded from the examples' packs (tests/solver/traces/*.csv, the "progress" rows of
// their stats.json). After a fifth of a run, every estimate puts the end within ±50 % of the real one.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "animpak/progress.hpp"

using namespace animpak;

namespace {

struct Trace {
  double unit_density = 0;
  bool secondary = false;
  Params::Stop stop;  // the stop test the run had: its stall window and growth
  std::vector<ProgressSample> rows;
};

// The stop test with this stall window, growth and tests per window. Before 0.10.0 the stall test
// compared windows of 1,000 steps against a 1 % rise: the traces recorded then carry no "# stall:" line,
// and the model's arithmetic below is worked out by hand for those windows. Before 0.13.0 it tested once
// per window: the traces recorded then give no third number.
Params::Stop stall_test(int window, double growth, int tests = 1) {
  Params::Stop stop;
  stop.stall_window = window;
  stop.stall_growth = growth;
  stop.stall_tests = tests;
  return stop;
}

// A trace: comment lines (the command, "# unit_mesh_density: D" of its world, and "# stall: WINDOW
// GROWTH [TESTS]", the run's stall_window, stall_growth and stall_tests), the columns of stats.json's "progress" rows, then
// the rows.
Trace read_trace(const std::filesystem::path& file) {
  std::ifstream in(file);
  REQUIRE(in);
  Trace trace;
  trace.stop = stall_test(1000, 0.01);
  std::vector<ProgressSample>& rows = trace.rows;
  std::string line;
  bool header = false;
  const std::string density = "# unit_mesh_density: ";
  while (std::getline(in, line)) {
    if (line.rfind(density, 0) == 0) trace.unit_density = std::stod(line.substr(density.size()));
    if (line.rfind("# secondary: ", 0) == 0) trace.secondary = true;
    if (line.rfind("# stall: ", 0) == 0) {
      std::istringstream stall(line.substr(9));
      int window = 0, tests = 1;
      double growth = 0;
      REQUIRE(stall >> window >> growth);
      if (!(stall >> tests)) tests = 1;
      trace.stop = stall_test(window, growth, tests);
    }
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      REQUIRE(line == "iteration,seconds,mean_growth,growing_share,max_gap,overlapping_vertices,outside_vertices");
      header = true;
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    cells.resize(7);
    ProgressSample p;
    p.iteration = std::stoull(cells[0]);
    p.seconds = std::stod(cells[1]);
    p.mean_growth = std::stod(cells[2]);
    p.growing_share = std::stod(cells[3]);
    p.max_gap = cells[4].empty() ? std::numeric_limits<double>::infinity() : std::stod(cells[4]);
    p.overlapping = std::stoll(cells[5]);
    p.outside = std::stoll(cells[6]);
    rows.push_back(p);
  }
  REQUIRE(trace.unit_density > 0);
  return trace;
}

std::vector<std::filesystem::path> traces() {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(std::string(ANIMPAK_SOURCE_DIR) + "/tests/solver/traces"))
    if (e.path().extension() == ".csv") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("progress: after a fifth of each recorded run the predicted end is within 50 % of the real one") {
  const std::vector<std::filesystem::path> files = traces();
  REQUIRE(files.size() >= 3);
  for (const auto& file : files) {
    const Trace t = read_trace(file);
    const std::vector<ProgressSample>& trace = t.rows;
    REQUIRE(trace.size() > 100);
    const double end = trace.back().seconds;
    const auto end_iteration = static_cast<double>(trace.back().iteration);
    // Every example packs at the default growth_rate and dt.
    const Params defaults;
    StopModel model(t.stop, t.secondary, t.unit_density, defaults.growth.growth_rate * defaults.forces.dt);
    int estimates = 0;
    double worst = 1.0, worst_at = 0.0, next_row = 0.2;
    std::ostringstream table;  // the predicted end over the real one, in time and in steps, every tenth of the run
    table << std::setprecision(2);
    for (const ProgressSample& s : trace) {
      model.observe(s);
      const std::optional<StopEstimate> e = model.estimate();
      if (s.seconds < end / 5) continue;
      INFO(file.filename().string() << " at " << s.seconds << " s (iteration " << s.iteration << ") of " << end
                                    << " s (" << end_iteration << ")");
      REQUIRE(e.has_value());
      ++estimates;
      const double ratio = (s.seconds + e->seconds_left) / end;
      CHECK(ratio >= 0.5);
      CHECK(ratio <= 1.5);
      CHECK(double(e->iteration) / end_iteration >= 0.5);
      CHECK(double(e->iteration) / end_iteration <= 1.5);
      if (std::abs(std::log(ratio)) > std::abs(std::log(worst))) worst = ratio, worst_at = s.seconds / end;
      if (s.seconds >= next_row * end) {
        table << " " << next_row << ": " << ratio << " (" << double(e->iteration) / end_iteration << ")";
        next_row += 0.1;
      }
    }
    // The worst estimate of each trace, for the test log (docs/results.md quotes them).
    WARN(file.filename().string() << ": " << estimates << " estimates after a fifth, worst end " << worst
                                  << " of the real one at " << worst_at << " of the run;" << table.str());
  }
}

TEST_CASE("progress: during free growth, the growth that fills the container to the density of a packing") {
  // g = 1 + 0.0005 per step, every slice growing, the gap steady; meshes filling 0.155 at g = 1 reach the
  // model's 0.62 at g = 2.
  auto sample = [](std::uint64_t i) {
    return ProgressSample{i, 0.01 * double(i), 1.0 + 0.0005 * double(i), 1.0, 0.1, 0, 0};
  };
  StopModel unknown(stall_test(1000, 0.01), false, 0.0), model(stall_test(1000, 0.01), false, 0.155);
  for (std::uint64_t i = 10; i <= 70; i += 10) model.observe(sample(i));
  CHECK_FALSE(model.estimate().has_value());  // seven samples
  for (std::uint64_t i = 80; i <= 1000; i += 10) model.observe(sample(i)), unknown.observe(sample(i));
  CHECK_FALSE(unknown.estimate().has_value());
  const std::optional<StopEstimate> e = model.estimate();
  REQUIRE(e.has_value());
  // From g 1.5 at 0.0005 a step, the rate falling to nothing: 2 · 0.5 / 0.0005 steps, plus 4 % settling.
  CHECK(e->iteration == 3120);
  // 2000 steps at 0.01 s, the pace scaled by the mean of g now and at the stop over g now (1.17).
  CHECK(e->seconds_left == Approx(0.01 * 2120 * 0.5 * (1 + 2 / 1.5)));
}

TEST_CASE("progress: once the elements meet, the stall windows' rises decay until one is below stall_growth") {
  // ln g rises 0.08 over the window to 2000 and 0.04 to 3000 (q = 0.5): then 0.02 to 4000 and 0.01 to 5000,
  // both at least ln 1.01, and 0.005 to 6000, which stalls.
  auto ln_g = [](double i) {
    if (i <= 1000) return 0.5 * i / 1000;
    if (i <= 2000) return 0.5 + 0.08 * (i - 1000) / 1000;
    return 0.58 + 0.04 * (i - 2000) / 1000;
  };
  StopModel model(stall_test(1000, 0.01), false, 0.1);
  for (std::uint64_t i = 10; i <= 3100; i += 10)
    model.observe({i, 0.01 * double(i), std::exp(ln_g(double(i))), 0.5, 0.02, 0, 0});
  const std::optional<StopEstimate> e = model.estimate();
  REQUIRE(e.has_value());
  CHECK(e->iteration == 6240);  // 6000 and 4 % settling
  // And the gap test first where the largest gap falls to stop_gap sooner: 0.02 · e^(-0.001 (i - 2100)).
  StopModel closing(stall_test(1000, 0.01), false, 0.1);
  for (std::uint64_t i = 10; i <= 3100; i += 10)
    closing.observe(
        {i, 0.01 * double(i), std::exp(ln_g(double(i))), 0.5, 0.02 * std::exp(-0.001 * (double(i) - 2100)), 0, 0});
  const std::optional<StopEstimate> c = closing.estimate();
  REQUIRE(c.has_value());
  CHECK(double(c->iteration) == Approx((2100 + 1000 * std::log(0.02 / 0.006)) * 1.04).epsilon(0.002));
}

TEST_CASE("progress: a stall test run four times a window is replayed at its own marks") {
  // g rises 0.001 a step to 3.05 at 2050, then stays. Four tests per 400-step window test every 100
  // steps against the mark 400 back: 2400 against 2000's 3.0 (a 1.7 % rise) grows on, 2500 against
  // 2100's 3.05 stalls. One test per window tests at 2400 (against 2000) and next at 2800.
  auto sample = [](std::uint64_t i) {
    return ProgressSample{i, 0.01 * double(i), 1.0 + 0.001 * double(std::min<std::uint64_t>(i, 2050)), 0.5, 0.02, 0, 0};
  };
  StopModel quarters(stall_test(400, 0.004, 4), false, 0.1);
  StopModel once(stall_test(400, 0.004, 1), false, 0.1);
  for (std::uint64_t i = 10; i <= 2490; i += 10) quarters.observe(sample(i)), once.observe(sample(i));
  REQUIRE(quarters.estimate().has_value());
  CHECK(quarters.estimate()->iteration > 2490);  // not stalled yet
  quarters.observe(sample(2500)), once.observe(sample(2500));
  const std::optional<StopEstimate> q = quarters.estimate(), o = once.estimate();
  REQUIRE(q.has_value());
  REQUIRE(o.has_value());
  CHECK(q->iteration == 2500);  // settling now
  CHECK(q->seconds_left == 0.0);
  CHECK(o->iteration > 2500);
}

TEST_CASE("progress: once growth has stopped, the settling left") {
  StopModel model(stall_test(1000, 0.01), false, 0.1);
  // Growth stops at 1900 (the gap test fired between samples); the run settles from there.
  for (std::uint64_t i = 10; i <= 1950; i += 10)
    model.observe(
        {i, 0.01 * double(i), 1.0 + 0.0005 * double(std::min<std::uint64_t>(i, 1900)), i < 1900 ? 0.5 : 0.0, 0.01});
  const std::optional<StopEstimate> e = model.estimate();
  REQUIRE(e.has_value());
  CHECK(e->iteration == 1976);  // 1900 · 1.04
  CHECK(e->seconds_left == Approx(0.01 * 26));
}
