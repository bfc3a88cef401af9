// animpak trajectory (docs/cli.md, "`trajectory`"): one element's path through the loop in two packings,
// drawn into one well-formed SVG with a line per packing in every panel, and measured: the length and
// acceleration of known paths, and across the loop's seam the element it loops into.
#include <catch2/catch.hpp>

#include <libxml/parser.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <regex>

#include "animpak/report.hpp"
#include "run_animpak.hpp"
#include "scene/tiny_scenes.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using animpak::trajectory_stats;
using animpak::TrajectoryRun;
using animpak::Vec2;
using Catch::Matchers::Contains;

namespace {

// Points of every polyline whose attributes match `attributes` (a regex over the start tag), in order.
std::vector<std::size_t> polyline_points(const std::string& svg, const std::string& attributes) {
  std::vector<std::size_t> counts;
  const std::regex line("<polyline " + attributes + "[^>]*points=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), line); it != std::sregex_iterator(); ++it) {
    const std::string points = (*it)[1];
    counts.push_back(points.empty() ? 0 : std::count(points.begin(), points.end(), ' ') + 1);
  }
  return counts;
}

// The <svg> with this id, to the first </svg> after it.
std::string panel(const std::string& svg, const std::string& id) {
  const std::size_t at = svg.find("id=\"" + id + "\"");
  if (at == std::string::npos) return {};
  return svg.substr(at, svg.find("</svg>", at) - at);
}

bool well_formed(const std::string& xml) {
  xmlDocPtr doc = xmlReadMemory(xml.data(), int(xml.size()), "trajectory.svg", nullptr,
                                XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
  const bool ok = doc != nullptr;
  xmlFreeDoc(doc);
  return ok;
}

TrajectoryRun circle(int n, double radius, double turn_start = 0.0, double turns = 1.0) {
  TrajectoryRun run;
  for (int i = 0; i < n; ++i) {
    const double t = double(i) / n, a = 2.0 * std::numbers::pi * (turn_start + turns * t);
    run.t.push_back(t);
    run.path.push_back({50.0 + radius * std::cos(a), 50.0 + radius * std::sin(a)});
  }
  return run;
}

}  // namespace

TEST_CASE("trajectory_stats: a circle's length and centripetal acceleration, a line's none") {
  // One turn of radius 20 in a container 100 wide: 2π · 0.2 widths long, acceleration (2π)² · 0.2.
  const auto stats = trajectory_stats(circle(400, 20.0), 100.0, true);
  CHECK(stats.length == Approx(2.0 * std::numbers::pi * 0.2).epsilon(1e-4));
  CHECK(stats.acceleration_median == Approx(4.0 * std::numbers::pi * std::numbers::pi * 0.2).epsilon(1e-3));
  CHECK(stats.acceleration_p99 == Approx(stats.acceleration_median).epsilon(1e-6));
  // A swapping pair: each element runs half the circle and goes on as the other, so the seam is smooth;
  // read as a closed path of its own, the half circle would jump back across it.
  TrajectoryRun half = circle(200, 20.0, 0.0, 0.5);
  const TrajectoryRun other = circle(200, 20.0, 0.5, 0.5);
  const auto closed = trajectory_stats(half, 100.0, true);
  CHECK(closed.acceleration_p99 > 20.0 * closed.acceleration_median);
  half.after = other.path.front();
  half.before = other.path.back();
  const auto joined = trajectory_stats(half, 100.0, true);
  CHECK(joined.length == Approx(std::numbers::pi * 0.2).epsilon(1e-4));
  CHECK(joined.acceleration_p99 == Approx(joined.acceleration_median).epsilon(1e-6));
  CHECK(closed.length > joined.length + 0.39);  // back across the diameter, 0.4 widths
  // A straight line at one speed, not looping: no acceleration.
  TrajectoryRun line;
  for (int i = 0; i < 11; ++i) line.t.push_back(i / 10.0), line.path.push_back({10.0 + 3.0 * i, 5.0});
  const auto straight = trajectory_stats(line, 100.0, false);
  CHECK(straight.length == Approx(0.3));
  CHECK(straight.acceleration_p99 == Approx(0.0).margin(1e-9));
  // Uneven times or too few are refused.
  line.t[3] = 0.35;
  CHECK_THROWS_WITH(trajectory_stats(line, 100.0, false), Contains("not evenly spaced"));
  line.t.resize(2), line.path.resize(2);
  CHECK_THROWS_WITH(trajectory_stats(line, 100.0, false), Contains("at least three"));
}

TEST_CASE("trajectory: a guided element in two packings, one line each, on across the seam as its partner") {
  const animpak::test::TempDir dir("animpak-trajectory-");
  const std::string stiff = (dir / "stiff").string(), loose = (dir / "loose").string();
  std::ofstream(dir / "stiff.json") << animpak::test::star_scene(2, 5, 3, animpak::test::swapping_pair());
  std::ofstream(dir / "loose.json") << animpak::test::star_scene(2, 5, 3,
                                                                 animpak::test::swapping_pair(R"("k_time": 0.05)"));
  for (const std::string name : {"stiff", "loose"})
    REQUIRE(run_animpak("pack " + (dir / (name + ".json")).string() + " --out " + (dir / name).string() +
                        " --max-iterations 30 --no-render")
                .code == 0);
  const fs::path svg_file = dir / "up.svg";
  const CommandResult drawn =
      run_animpak("trajectory " + stiff + " " + loose + " --element up --samples 60 --out " + svg_file.string());
  INFO(drawn.err);
  REQUIRE(drawn.code == 0);
  CHECK(std::regex_search(drawn.out, std::regex(R"(stiff: path [0-9.]+ container widths per loop, acceleration)")));
  CHECK(std::regex_search(drawn.out, std::regex(R"(loose: path [0-9.]+ container widths per loop, acceleration)")));
  const std::string svg = read_text(svg_file);
  CHECK(well_formed(svg));
  // x(t) and y(t): one line of 60 points per packing, named by its folder.
  for (const std::string id : {"plot-x", "plot-y"}) {
    const std::string plot = panel(svg, id);
    REQUIRE_FALSE(plot.empty());
    CHECK(polyline_points(plot, "class=\"series main\" data-series=\"stiff\"") == std::vector<std::size_t>{60});
    CHECK(polyline_points(plot, "class=\"series main\" data-series=\"loose\"") == std::vector<std::size_t>{60});
  }
  // The top view: each path's 60 points and the point it goes on to, which for "up" (it loops into
  // "down", 60 units to its right at t = 0) is not where it started.
  const std::string view = panel(svg, "view");
  CHECK(polyline_points(view, "class=\"path\" data-run=\"0\"") == std::vector<std::size_t>{61});
  CHECK(polyline_points(view, "class=\"path\" data-run=\"1\"") == std::vector<std::size_t>{61});
  std::smatch path;
  REQUIRE(std::regex_search(view, path, std::regex("class=\"path\" data-run=\"0\"[^>]*points=\"([^\"]*)\"")));
  const std::string points = path[1];
  const std::string first = points.substr(0, points.find(' ')), last = points.substr(points.rfind(' ') + 1);
  const auto coordinates = [](const std::string& p) {
    return Vec2{std::stod(p.substr(0, p.find(','))), std::stod(p.substr(p.find(',') + 1))};
  };
  CHECK(animpak::norm(coordinates(last) - coordinates(first)) > 20.0);  // pixels
  CHECK(polyline_points(view, "class=\"art\" data-run=\"0\"").size() > 0);

  // Refusals: an unknown element (its list of names says what to use), a folder pack did not write.
  const CommandResult unknown = run_animpak("trajectory " + stiff + " --element nosuch");
  CHECK(unknown.code == 2);
  CHECK_THAT(unknown.err, Contains("no element named \"nosuch\"") && Contains("up, down"));
  const CommandResult empty = run_animpak("trajectory " + (dir / "nothing").string() + " --element up");
  CHECK(empty.code == 2);
  CHECK_THAT(empty.err, Contains("no state.bin"));

  // Written into the first folder by default; a render there removes it with the other pictures.
  REQUIRE(run_animpak("trajectory " + stiff + " --element star#1 --samples 16").code == 0);
  CHECK(fs::exists(fs::path(stiff) / "trajectory.svg"));
  REQUIRE(run_animpak("render " + stiff + " --frames 2 --size 32 --format png").code == 0);
  CHECK_FALSE(fs::exists(fs::path(stiff) / "trajectory.svg"));
}
