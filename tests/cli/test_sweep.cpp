// animpak sweep, sweep-task and sweep collect (docs/sweeps.md) as a user runs them, on scenes of three stars
// and a few slices packed for a few dozen iterations: the plan and its ids, a local sweep stopped midway and
// run again (only the unfinished runs run), a run that dies beside runs that finish, a value the parameter
// table refuses, the cluster files (commands.txt under xargs -P 2), and the page in headless Chromium. The
// real Slurm cluster's test is tests/sweep/slurm.sh.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <set>

#include "animpak/error.hpp"
#include "animpak/report.hpp"
#include "run_animpak.hpp"
#include "scene/tiny_scenes.hpp"
#include "shown_figures.hpp"
#include "skip.hpp"
#include "sweep_plan.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using nlohmann::json;

// The helpers and the test cases in a namespace of their own: the test stage is compiled a few files to a unit
// (unity build), beside other files' helpers of the same names.
namespace sweep_test {

// Three stars in the heart, six slices: a run packs in a second or two.
std::string tiny_scene() { return animpak::test::star_scene(3, 6, 1, {"", R"("initial_scale": 0.15)"}); }

// Small frames, so that a run renders and writes its report page in a second.
const std::string kRunOptions = " --frames 4 --size 64 --format png,gif";

json read_json(const fs::path& file) { return json::parse(read_text(file)); }

animpak::Stats read_stats(const fs::path& file) { return animpak::parse_stats(read_text(file), file); }

// A sweep measure's figure in a run's stats.json, by its key (coverage_min), read through the model.
std::optional<double> measure(const animpak::Stats& stats, const std::string& key) {
  for (const animpak::SweepMeasure& m : animpak::sweep_measures())
    if (m.key == key) return m.value(stats);
  FAIL("no sweep measure " << key);
  return std::nullopt;
}

std::vector<std::map<std::string, std::string>> read_csv(const fs::path& file) {
  std::vector<std::map<std::string, std::string>> rows;
  std::istringstream lines(read_text(file));
  std::vector<std::string> header;
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> fields;
    std::string field;
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
      const char c = line[i];
      if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
        field += '"', ++i;
      else if (c == '"')
        quoted = !quoted;
      else if (c == ',' && !quoted)
        fields.push_back(field), field.clear();
      else
        field += c;
    }
    fields.push_back(field);
    if (header.empty()) {
      header = fields;
      continue;
    }
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < header.size() && i < fields.size(); ++i) row[header[i]] = fields[i];
    rows.push_back(row);
  }
  return rows;
}

// Runs a shell script (bash), returning its exit code; `log` gets what it printed.
int run_script(const std::string& script, const fs::path& log) {
  const fs::path file = log.string() + ".sh";
  std::ofstream(file) << "set -u\n" << script;
  const int status = std::system(("bash '" + file.string() + "' >'" + log.string() + "' 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// Waits in a script until `condition` (a shell test) holds, for at most about 120 s.
std::string wait_until(const std::string& condition) {
  return "for i in $(seq 1200); do if " + condition + "; then break; fi; sleep 0.1; done\n" + condition +
         " || { echo 'waited 120 s for: " + condition + "'; exit 99; }\n";
}

bool have_chromium() { return std::system("command -v chromium >/dev/null 2>&1") == 0; }

// The page as Chromium built it (its DOM after the script ran) at `fragment`, and its console messages.
std::pair<std::string, std::vector<std::string>> load_page(const fs::path& page, const std::string& fragment,
                                                           const fs::path& scratch) {
  const fs::path dom = scratch / "dom.html", log = scratch / "chromium.log";
  const std::string command = "chromium --headless --no-sandbox --disable-gpu --user-data-dir='" +
                              (scratch / "profile").string() + "' --enable-logging=stderr --v=0 --dump-dom 'file://" +
                              page.string() + fragment + "' >'" + dom.string() + "' 2>'" + log.string() + "'";
  REQUIRE(std::system(command.c_str()) == 0);
  std::vector<std::string> console;
  std::istringstream lines(read_text(log));
  for (std::string line; std::getline(lines, line);)
    if (line.find(":CONSOLE") != std::string::npos) console.push_back(line);
  return {read_text(dom), console};
}

// The cards' run ids in the order the page shows them.
std::vector<std::string> card_order(const std::string& dom) {
  std::vector<std::string> ids;
  const std::regex card(R"re(<div class="card" id="run-[^"]*" data-id="([^"]+)")re");
  for (auto it = std::sregex_iterator(dom.begin(), dom.end(), card); it != std::sregex_iterator(); ++it)
    ids.push_back((*it)[1]);
  return ids;
}

// The order a measure sorts finished runs in: best first (higher coverage, fewer iterations), ties in plan
// order; reversed, worst first.
std::vector<std::string> expected_order(const json& plan, const fs::path& dir, const std::string& key, bool higher,
                                        bool reversed) {
  std::vector<std::pair<double, std::pair<std::size_t, std::string>>> runs;
  for (const json& run : plan["runs"]) {
    const animpak::Stats stats = read_stats(dir / "runs" / run["id"].get<std::string>() / "stats.json");
    const double v = measure(stats, key).value();
    runs.push_back({higher ? -v : v, {run["index"].get<std::size_t>(), run["id"].get<std::string>()}});
  }
  std::stable_sort(runs.begin(), runs.end(), [&](const auto& a, const auto& b) {
    if (a.first != b.first) return reversed ? a.first > b.first : a.first < b.first;
    return a.second.first < b.second.first;
  });
  std::vector<std::string> ids;
  for (const auto& r : runs) ids.push_back(r.second.second);
  return ids;
}

// Every figure a card shows against its run's stats.json, to the decimals shown; the problems found.
std::vector<std::string> figure_problems(const std::string& dom, const fs::path& dir, int& figures) {
  std::vector<std::string> problems;
  const std::regex card(R"re(<div class="card" id="run-[^"]*" data-id="([^"]+)")re");
  std::vector<std::pair<std::size_t, std::string>> starts;
  for (auto it = std::sregex_iterator(dom.begin(), dom.end(), card); it != std::sregex_iterator(); ++it)
    starts.push_back({std::size_t(it->position()), (*it)[1]});
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const std::size_t end = k + 1 < starts.size() ? starts[k + 1].first : dom.find("<script", starts[k].first);
    const std::string body = dom.substr(starts[k].first, end - starts[k].first);
    const animpak::Stats stats = read_stats(dir / "runs" / starts[k].second / "stats.json");
    for (const std::string& problem : animpak::test::shown_figure_problems(body, stats, figures))
      problems.push_back(starts[k].second + ": " + problem);
  }
  return problems;
}

TEST_CASE("sweep: seeds, settings and run ids, each value checked against the parameter table") {
  using animpak::cli::parse_seeds;
  using animpak::cli::parse_setting;
  CHECK(parse_seeds("1-3,7, 5") == std::vector<std::uint64_t>{1, 2, 3, 7, 5});
  CHECK(parse_seeds("2,2,1-2") == std::vector<std::uint64_t>{2, 1});
  CHECK_THROWS_AS(parse_seeds("3-1"), animpak::UsageError);
  CHECK_THROWS_AS(parse_seeds("-1"), animpak::UsageError);
  CHECK_THROWS_AS(parse_seeds("1-100000"), animpak::UsageError);
  CHECK_THROWS_WITH(parse_seeds("a"), Contains("--seeds a") && Contains("1,3,5-7"));

  const animpak::cli::SweepSetting k_time = parse_setting("k_time=0.05,0.50,5");
  CHECK(k_time.texts == std::vector<std::string>{"0.05", "0.5", "5"});
  CHECK_THROWS_WITH(parse_setting("k_time=-1"), Contains("k_time") && Contains("outside the range") &&
                                                    Contains("[0, inf]") && Contains("animpak params"));
  CHECK_THROWS_WITH(parse_setting("slices=2.5"), Contains("not a whole number"));
  CHECK_THROWS_WITH(parse_setting("slices=1"), Contains("[2, 1000]"));
  CHECK_THROWS_WITH(parse_setting("k_tme=1"), Contains("not a setting a sweep varies"));
  CHECK_THROWS_WITH(parse_setting("k_time"), Contains("NAME=V1,V2"));
  CHECK_THROWS_WITH(parse_setting("k_time=1,,2"), Contains("empty"));
  CHECK_THROWS_WITH(parse_setting("k_time=nan"), Contains("not a number"));
  CHECK(parse_setting("star.count=3,4").values.size() == 2);

  const auto runs = animpak::cli::plan_runs({3, 1}, {k_time, parse_setting("slices=8")});
  REQUIRE(runs.size() == 6);
  CHECK(runs[0].id == "seed3-k_time0.05-slices8");
  CHECK(runs[1].id == "seed3-k_time0.5-slices8");
  CHECK(runs[5].id == "seed1-k_time5-slices8");
  CHECK(runs[5].index == 5);
  CHECK(animpak::cli::plan_runs({1}, {parse_setting("k_time=0.00005")})[0].id == "seed1-k_time5e-05");
  for (const auto& r : runs) CHECK(animpak::cli::valid_run_id(r.id));
  CHECK_FALSE(animpak::cli::valid_run_id("../x"));
  CHECK_FALSE(animpak::cli::valid_run_id(".hidden"));
  CHECK(animpak::cli::index_ranges({0, 1, 2, 4, 6, 7}) == "0-2,4,6-7");

  // The run's scene: its seed and settings put in, where the scene gives them.
  const std::string scene =
      R"({"container": "c.svg", "elements": [{"art": "a/star.svg", "count": 2}, {"name": "fish", "art": "f.svg", "weight": 2}], "params": {"slices": 6}})";
  animpak::cli::SweepRun run = runs[0];
  const json text =
      json::parse(animpak::cli::run_scene_text(scene, run, [](const std::string& w) { return "X/" + w; }));
  CHECK(text["seed"] == 3);
  CHECK(text["params"]["k_time"] == 0.05);
  CHECK(text["params"]["slices"] == 8);
  CHECK_FALSE(text.contains("slices"));
  CHECK(text["container"] == "X/c.svg");
  CHECK(text["elements"][0]["art"] == "X/a/star.svg");
  run.set = {{"star.count", 5}};
  CHECK(json::parse(animpak::cli::run_scene_text(scene, run,
                                                 [](const std::string& w) { return w; }))["elements"][0]["count"] == 5);
  run.set = {{"fish.count", 5}};
  CHECK_THROWS_WITH(animpak::cli::run_scene_text(scene, run, [](const std::string& w) { return w; }),
                    Contains("drawn by weight"));
  run.set = {{"bird.count", 5}};
  CHECK_THROWS_WITH(animpak::cli::run_scene_text(scene, run, [](const std::string& w) { return w; }),
                    Contains("no element named \"bird\"") && Contains("star, fish"));
}

TEST_CASE(
    "sweep: a value the parameter table refuses, or an element the scene lacks, is refused before anything runs") {
  const animpak::test::TempDir dir("animpak-sweep-refused-");
  std::ofstream(dir / "scene.json") << tiny_scene();
  const std::string scene = (dir / "scene.json").string(), out = (dir / "sweep").string();
  const CommandResult bad = run_animpak("sweep " + scene + " --out " + out + " --seeds 1-2 --set k_time=0.5,-1");
  CHECK(bad.code == 1);
  CHECK_THAT(bad.err, Contains("--set k_time=0.5,-1") && Contains("\"-1\" is outside the range"));
  const CommandResult element = run_animpak("sweep " + scene + " --out " + out + " --set bird.count=1,2");
  CHECK(element.code == 1);
  CHECK_THAT(element.err, Contains("no element named \"bird\""));
  // The scene's own checks, on every run's scene: a count the scene cannot build.
  const CommandResult count = run_animpak("sweep " + scene + " --out " + out + " --set star.count=2,20000");
  CHECK(count.code == 2);
  CHECK_THAT(count.err, Contains("run seed1-star.count20000") && Contains("10000"));
  CHECK_FALSE(fs::exists(out));
  const CommandResult collect = run_animpak("sweep collect " + (dir / "nothing").string());
  CHECK(collect.code == 2);
  CHECK_THAT(collect.err, Contains("plan.json: not found"));
  const CommandResult task = run_animpak("sweep-task " + out);
  CHECK(task.code == 2);

  // A value in range that blows the simulation up fails its run with pack's own message; the other run stands.
  const CommandResult nan =
      run_animpak("sweep " + scene + " --out " + out + " --set k_edge=10,1e300 --max-iterations 30" + kRunOptions);
  CHECK(nan.code == 2);
  CHECK_THAT(nan.err, Contains("1 of 2 runs failed") && Contains("seed1-k_edge1e+300: ") && Contains("NaN/Inf"));
  const auto rows = read_csv(fs::path(out) / "runs.csv");
  REQUIRE(rows.size() == 2);
  CHECK(rows[0].at("state") == "done");
  CHECK_FALSE(rows[0].at("coverage_min").empty());
  CHECK(rows[1].at("state") == "failed");
  CHECK_THAT(rows[1].at("message"), Contains("NaN/Inf") && Contains("lower params.dt or the stiffnesses"));
}

TEST_CASE(
    "sweep: 2 seeds x 2 values, stopped midway and run again: only the unfinished runs run, four packed folders, "
    "runs.csv and sweep.html") {
  // The page is checked in Chromium at the end; a skip comes before any check (docs/testing.md, "Skipped tests").
  if (!have_chromium())
    return animpak::test::skip("chromium is not on PATH (Debian package chromium); sweep.html cannot be loaded");
  const animpak::test::TempDir dir("animpak-sweep-local-");
  std::ofstream(dir / "scene.json") << tiny_scene();
  const fs::path out = dir / "sweep";
  const std::string command = std::string(ANIMPAK_EXE) + " sweep " + (dir / "scene.json").string() + " --out " +
                              out.string() + " --seeds 1-2 --set k_time=0.05,5 --jobs 1 --max-iterations 300" +
                              " --checkpoint-every 0" + kRunOptions;
  // Stopped as `timeout` or a cluster's time limit stops it (SIGTERM) while its second run packs.
  const std::string second = (out / "runs/seed1-k_time5").string();
  const int stopped = run_script(command + " >'" + (dir / "first.log").string() + "' 2>&1 &\npid=$!\n" +
                                     wait_until("[ -f '" + second + "/.pack-new/state.bin' ]") +
                                     "kill -TERM $pid\nwait $pid\necho \"exit $?\"\n",
                                 dir / "stop.log");
  INFO(read_text(dir / "stop.log") << read_text(dir / "first.log"));
  REQUIRE(stopped == 0);
  CHECK_THAT(read_text(dir / "stop.log"), Contains("exit 143"));
  CHECK_THAT(read_text(dir / "first.log"), Contains("sweep stopped by SIGTERM"));
  const json plan = read_json(out / "plan.json");
  REQUIRE(plan["runs"].size() == 4);
  CHECK(plan["runs"][0]["id"] == "seed1-k_time0.05");
  CHECK(plan["runs"][3]["folder"] == "runs/seed2-k_time5");
  CHECK(read_json(out / "status/seed1-k_time0.05.json")["state"] == "done");
  CHECK(read_json(out / "status/seed1-k_time5.json")["state"] == "interrupted");
  CHECK_FALSE(fs::exists(out / "runs/seed2-k_time0.05/state.bin"));
  const auto first_state = fs::last_write_time(out / "runs/seed1-k_time0.05/state.bin");
  // The page was written for the runs so far.
  CHECK(read_csv(out / "runs.csv").size() == 4);

  const CommandResult again = run_command(command);
  INFO(again.err);
  REQUIRE(again.code == 0);
  CHECK_THAT(again.err, Contains("1 complete, 3 to run"));
  CHECK_THAT(again.err, Contains("seed1-k_time5: pack --resume") || Contains("seed1-k_time5: render"));
  CHECK_THAT(again.err, !Contains("seed1-k_time0.05: pack") && !Contains("seed1-k_time5: pack\n"));
  CHECK(fs::last_write_time(out / "runs/seed1-k_time0.05/state.bin") == first_state);

  // Four ordinary packed folders; the table holds each one's stats.json figures.
  const auto rows = read_csv(out / "runs.csv");
  REQUIRE(rows.size() == 4);
  for (const auto& row : rows) {
    const fs::path run = out / "runs" / row.at("id");
    CHECK(row.at("state") == "done");
    REQUIRE(fs::exists(run / "state.bin"));
    CHECK(fs::exists(run / "report.html"));
    CHECK(fs::exists(run / "frames/frame_0000.png"));
    const json stats = read_json(run / "stats.json");
    CHECK(std::stod(row.at("coverage_min")) == stats["quality"]["frames"]["coverage"]["min"].get<double>());
    CHECK(std::stod(row.at("coverage_mean")) == stats["quality"]["frames"]["coverage"]["mean"].get<double>());
    CHECK(std::stoull(row.at("iterations")) == stats["iterations"].get<std::uint64_t>());
    CHECK(std::stoull(row.at("seed")) == stats["seed"].get<std::uint64_t>());
    const json scene = read_json(run / "input" / (row.at("id") + ".json"));
    CHECK(scene["params"]["k_time"].get<double>() == std::stod(row.at("k_time")));
  }
  // Every run's folder is an ordinary packed folder.
  const std::string one = (out / "runs/seed2-k_time5").string();
  CHECK(run_animpak("render " + one + " --frames 2 --size 32 --format png").code == 0);
  const CommandResult resumed = run_animpak("pack --resume " + one);
  CHECK(resumed.code == 0);
  CHECK_THAT(resumed.err, Contains("holds a finished packing"));
  CHECK(run_animpak("trajectory " + one + " " + (out / "runs/seed2-k_time0.05").string() + " --element star#1").code ==
        0);
  // The run rendered again has no report page now; collect says so without one.
  const CommandResult collect = run_animpak("sweep collect " + out.string());
  CHECK(collect.code == 0);
  CHECK_THAT(collect.out, Contains("best by coverage, lowest frame: seed"));
  // Running the sweep again only writes the report page that render removed.
  const CommandResult third = run_command(command);
  CHECK(third.code == 0);
  CHECK_THAT(third.err, Contains("3 complete, 1 to run") && Contains("seed2-k_time5: report"));

  const std::string html = read_text(out / "sweep.html");
  // Self-contained: every picture inside the page; the only links are the runs' report pages.
  const std::regex src(R"re(src="([^"]{0,12}))re"), href(R"re(href="([^"]*)")re");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), src); it != std::sregex_iterator(); ++it)
    CHECK(std::string((*it)[1]).rfind("data:image/", 0) == 0);
  int links = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), href); it != std::sregex_iterator(); ++it, ++links)
    CHECK(std::regex_match(std::string((*it)[1]), std::regex(R"(runs/seed[12]-k_time(0\.05|5)/report\.html)")));
  CHECK(links == 4);
  CHECK(html.find("http") == std::string::npos);
  // One parameter varies: a plot of each measure against it, on a log axis (0.05 to 5).
  CHECK_THAT(html, Contains("id=\"plot-coverage_min\"") && Contains("id=\"plot-kink\"") && Contains("Against k_time"));

  const auto [dom, console] = load_page(out / "sweep.html", "", dir.path());
  for (const std::string& line : console) UNSCOPED_INFO(line);
  CHECK(console.empty());
  CHECK_THAT(dom, Contains("data-ready=\"yes\""));
  const std::vector<std::string> order = card_order(dom);
  CHECK(order.size() == 4);
  CHECK(order == expected_order(plan, out, "coverage_min", true, false));
  int figures = 0;
  const std::vector<std::string> problems = figure_problems(dom, out, figures);
  for (const std::string& p : problems) UNSCOPED_INFO(p);
  CHECK(problems.empty());
  // Seven figures a card, less those a run's stats.json has none of (a wall ratio where no element is near the
  // wall).
  int expected_figures = 0;
  for (const json& run : plan["runs"]) {
    const animpak::Stats stats = read_stats(out / "runs" / run["id"].get<std::string>() / "stats.json");
    for (const char* key :
         {"coverage_min", "coverage_mean", "wall_ratio", "empty_disc", "kink", "iterations", "seconds"}) {
      const std::optional<double> v = measure(stats, key);
      expected_figures += v && std::isfinite(*v) ? 1 : 0;
    }
  }
  CHECK(figures == expected_figures);
  CHECK(figures >= 4 * 5);
  // The sort chosen on the page (here by the address, as the select writes it) changes the order.
  const auto reversed = load_page(out / "sweep.html", "#sort=coverage_min&reverse=1", dir.path());
  CHECK(card_order(reversed.first) == expected_order(plan, out, "coverage_min", true, true));
  CHECK(card_order(reversed.first) != order);
  CHECK_THAT(reversed.first, Contains("data-sort=\"coverage_min reversed\""));
  const auto by_mean = load_page(out / "sweep.html", "#sort=coverage_mean", dir.path());
  CHECK(card_order(by_mean.first) == expected_order(plan, out, "coverage_mean", true, false));
  CHECK(by_mean.second.empty());
}

TEST_CASE(
    "sweep: a run that dies is marked failed with its message, the other runs' results stand, and the next "
    "sweep resumes it") {
  const animpak::test::TempDir dir("animpak-sweep-dies-");
  std::ofstream(dir / "scene.json") << tiny_scene();
  const fs::path out = dir / "sweep";
  const std::string command = std::string(ANIMPAK_EXE) + " sweep " + (dir / "scene.json").string() + " --out " +
                              out.string() + " --seeds 1-2 --jobs 1 --max-iterations 300 --checkpoint-every 0" +
                              kRunOptions;
  // The first run's pack is killed outright (a crash, the OOM killer) once it has saved a state.
  const std::string first = (out / "runs/seed1").string();
  const int code = run_script(command + " >'" + (dir / "sweep.log").string() + "' 2>&1 &\npid=$!\n" +
                                  wait_until("[ -f '" + first + "/.pack-new/state.bin' ]") +
                                  "kill -KILL $(sed -n 's/^pid \\([0-9]*\\):.*/\\1/p' '" + first +
                                  "/.animpak.lock')\nwait $pid\necho \"exit $?\"\n",
                              dir / "kill.log");
  INFO(read_text(dir / "kill.log") << read_text(dir / "sweep.log"));
  REQUIRE(code == 0);
  CHECK_THAT(read_text(dir / "kill.log"), Contains("exit 2"));
  CHECK_THAT(read_text(dir / "sweep.log"), Contains("1 of 2 runs failed") && Contains("killed by signal 9"));
  const json status = read_json(out / "status/seed1.json");
  CHECK(status["state"] == "failed");
  CHECK_THAT(status["message"].get<std::string>(), Contains("killed by signal 9"));
  CHECK(read_json(out / "status/seed2.json")["state"] == "done");
  const auto rows = read_csv(out / "runs.csv");
  REQUIRE(rows.size() == 2);
  CHECK(rows[0].at("state") == "failed");
  CHECK_THAT(rows[0].at("message"), Contains("killed by signal 9"));
  CHECK(rows[1].at("state") == "done");
  CHECK_FALSE(rows[1].at("coverage_min").empty());
  const std::string html = read_text(out / "sweep.html");
  CHECK_THAT(html, Contains("data-state=\"failed\"") && Contains("killed by signal 9"));
  const auto second_state = fs::last_write_time(out / "runs/seed2/state.bin");

  const CommandResult again = run_command(command);
  INFO(again.err);
  CHECK(again.code == 0);
  CHECK_THAT(again.err, Contains("1 complete, 1 to run") && Contains("seed1: pack --resume"));
  CHECK(fs::last_write_time(out / "runs/seed2/state.bin") == second_state);
  CHECK(read_json(out / "status/seed1.json")["state"] == "done");
}

TEST_CASE("sweep --plan-only: plan.json, slurm.sbatch, an Indexed Job and commands.txt, which runs under xargs -P 2") {
  const animpak::test::TempDir dir("animpak-sweep-plan-");
  std::ofstream(dir / "scene.json") << tiny_scene();
  const fs::path out = dir / "sweep";
  const CommandResult planned =
      run_animpak("sweep " + (dir / "scene.json").string() + " --out " + out.string() +
                  " --seeds 4-6 --plan-only --max-iterations 40 --cpus-per-task 3" + kRunOptions);
  INFO(planned.err);
  REQUIRE(planned.code == 0);
  CHECK_THAT(planned.err, Contains("planned 3 runs") && Contains("sbatch") && Contains("kubectl apply"));
  CHECK_FALSE(fs::exists(out / "runs/seed4/state.bin"));
  const json plan = read_json(out / "plan.json");
  REQUIRE(plan["runs"].size() == 3);
  CHECK(plan["runs"][2]["id"] == "seed6");
  CHECK(plan["pack"]["max_iterations"] == 40);
  CHECK(plan["pack"]["size"] == 64);
  CHECK(fs::exists(out / "scenes/seed5.json"));
  CHECK(read_json(out / "scenes/seed5.json")["seed"] == 5);
  CHECK(fs::exists(out / "input/manifest.json"));

  const std::string home = fs::absolute(out).lexically_normal().string();
  const std::string sbatch = read_text(out / "slurm.sbatch");
  CHECK_THAT(sbatch, Contains("#SBATCH --array=0-2\n") && Contains("#SBATCH --cpus-per-task=3\n") &&
                         Contains(" sweep-task " + home + "\n") && Contains("#SBATCH --output=" + home + "/logs/"));
  // What an Indexed Job needs: batch/v1 Job, Indexed completion, a completion per run, pods that do not restart,
  // and the command that reads JOB_COMPLETION_INDEX with the sweep's folder mounted where the plan says.
  const std::string job = read_text(out / "k8s-job.yaml");
  for (const std::string& line : std::vector<std::string>{
           "apiVersion: batch/v1\n", "kind: Job\n", "  completionMode: Indexed\n", "  completions: 3\n",
           "      restartPolicy: Never\n", "          command: [\"animpak\", \"sweep-task\", \"" + home + "\"]\n",
           "              mountPath: \"" + home + "\"\n", "            claimName: \"animpak-sweeps\"\n",
           "              cpu: \"3\"\n"})
    CHECK_THAT(job, Contains(line));
  CHECK(std::regex_search(job, std::regex("\n  name: animpak-sweep-[0-9a-f]{10}\n")));
  CHECK(std::regex_search(job, std::regex("\n  parallelism: [1-3]\n")));
  CHECK(std::regex_search(job, std::regex("\n          image: \"animpak:[0-9.]+\"\n")));
  const std::string commands = read_text(out / "commands.txt");
  CHECK(std::count(commands.begin(), commands.end(), '\n') == 3);
  CHECK_THAT(commands, Contains(" sweep-task " + home + " --index 2\n"));

  // Without an index, sweep-task takes the cluster's; with none it says what it needs.
  const CommandResult no_index = run_animpak("sweep-task " + out.string());
  CHECK(no_index.code == 1);
  CHECK_THAT(no_index.err, Contains("SLURM_ARRAY_TASK_ID") && Contains("JOB_COMPLETION_INDEX"));
  CHECK(run_animpak("sweep-task " + out.string(), "SLURM_ARRAY_TASK_ID=3").code == 1);

  const CommandResult xargs =
      run_command("cd / && xargs -a '" + (out / "commands.txt").string() + "' -d '\\n' -n 1 -P 2 sh -c");
  INFO(xargs.err);
  CHECK(xargs.code == 0);
  const CommandResult collect = run_animpak("sweep collect " + out.string());
  CHECK(collect.code == 0);
  CHECK_THAT(collect.err, Contains("3 runs in") && Contains("3 done"));
  for (const auto& row : read_csv(out / "runs.csv")) CHECK(row.at("state") == "done");
  // A task of a run already complete does nothing.
  const CommandResult done = run_animpak("sweep-task " + out.string(), "JOB_COMPLETION_INDEX=1");
  CHECK(done.code == 0);
  CHECK_THAT(done.err, Contains("seed5: already complete"));
  // The same sweep with one more seed keeps the three runs and their indices.
  const CommandResult more =
      run_animpak("sweep " + (dir / "scene.json").string() + " --out " + out.string() +
                  " --seeds 4-7 --plan-only --max-iterations 40 --cpus-per-task 3" + kRunOptions);
  CHECK(more.code == 0);
  const json grown = read_json(out / "plan.json");
  REQUIRE(grown["runs"].size() == 4);
  CHECK(grown["runs"][3]["id"] == "seed7");
  CHECK(grown["runs"][0]["id"] == "seed4");
  // Another sweep into the same folder is refused.
  const CommandResult other = run_animpak("sweep " + (dir / "scene.json").string() + " --out " + out.string() +
                                          " --seeds 4 --plan-only --max-iterations 41" + kRunOptions);
  CHECK(other.code == 2);
  CHECK_THAT(other.err, Contains("differs in the pack options"));
}

TEST_CASE("sweep: docs/cli.md documents every option of sweep, sweep collect and sweep-task") {
  const std::string cli = read_text(fs::path(ANIMPAK_SOURCE_DIR) / "docs/cli.md");
  int options = 0;
  for (const std::string command : {"sweep", "sweep collect", "sweep-task"}) {
    const CommandResult help = run_animpak(command + " --help");
    REQUIRE(help.code == 0);
    const std::regex option(R"((^|[ ,])(--[a-z][a-z0-9-]*))");
    for (auto it = std::sregex_iterator(help.out.begin(), help.out.end(), option); it != std::sregex_iterator(); ++it) {
      const std::string name = (*it)[2];
      if (name == "--help") continue;
      ++options;
      INFO(command << " " << name);
      CHECK_THAT(cli, Contains("`" + name));
    }
  }
  CHECK(options >= 20);
}

}  // namespace sweep_test
