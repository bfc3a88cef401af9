// animpak report: the page shows stats.json's own numbers, its five plots and the animation, and headless
// Chromium loads it with no console message and draws something; a page missing a plot or the animation
// fails the same check.
#include <catch2/catch.hpp>

#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <regex>
#include <set>

#include "animpak/report.hpp"
#include "run_animpak.hpp"
#include "scene/tiny_scenes.hpp"
#include "shown_figures.hpp"
#include "skip.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using nlohmann::json;

namespace {

bool have_chromium() { return std::system("command -v chromium >/dev/null 2>&1") == 0; }

// The <svg> element with this id, from its start tag to its </svg>, or empty.
std::string svg_with_id(const std::string& dom, const std::string& id) {
  const std::size_t at = dom.find("id=\"" + id + "\"");
  if (at == std::string::npos) return {};
  const std::size_t begin = dom.rfind("<svg", at), end = dom.find("</svg>", at);
  if (begin == std::string::npos || end == std::string::npos) return {};
  return dom.substr(begin, end + 6 - begin);
}

// Points of the plot's main series (its polylines), counted.
std::size_t main_points(const std::string& plot) {
  std::size_t count = 0;
  const std::regex line("<polyline class=\"series main\"[^>]*points=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(plot.begin(), plot.end(), line); it != std::sregex_iterator(); ++it) {
    const std::string points = (*it)[1];
    count += points.empty() ? 0 : std::count(points.begin(), points.end(), ' ') + 1;
  }
  return count;
}

std::size_t finite_count(const std::vector<double>& values) {
  return std::size_t(std::count_if(values.begin(), values.end(), [](double v) { return std::isfinite(v); }));
}

// What is wrong with a page as Chromium built it (its DOM after the script ran), held against stats.json:
// empty when nothing is.
std::vector<std::string> page_problems(const std::string& dom, const animpak::Stats& stats) {
  std::vector<std::string> problems;
  if (dom.find("data-ready=\"yes\"") == std::string::npos) problems.push_back("the page's script did not finish");
  const std::size_t animation = dom.find("<div id=\"animation\">");
  const std::size_t animation_end = dom.find("</div>", animation);
  if (animation == std::string::npos ||
      dom.substr(animation, animation_end - animation).find("<animate") == std::string::npos)
    problems.push_back("no animated SVG in #animation");
  std::set<std::string> present;
  std::size_t frames_with_wall = 0;
  const std::vector<animpak::StatsFrame> frames = stats.frames.value_or(std::vector<animpak::StatsFrame>{});
  for (const animpak::StatsFrame& f : frames) frames_with_wall += f.evenness && std::isfinite(f.evenness->wall_ratio);
  const std::map<std::string, std::size_t> expected = {
      {"plot-coverage", frames.size()},
      {"plot-channel", frames.size()},
      {"plot-wall", frames_with_wall},
      {"plot-kink", stats.motion && stats.motion->frame_peak ? finite_count(*stats.motion->frame_peak) : 0},
      {"plot-contact",
       stats.quality && stats.quality->frames.evenness ? stats.quality->frames.evenness->contact_mean.size() : 0}};
  for (const std::string& id : animpak::kReportPlots) {
    const std::string plot = svg_with_id(dom, id);
    if (plot.empty()) {
      problems.push_back(id + ": missing");
      continue;
    }
    if (main_points(plot) != expected.at(id) || expected.at(id) == 0)
      problems.push_back(id + ": " + std::to_string(main_points(plot)) + " points, stats.json has " +
                         std::to_string(expected.at(id)));
  }
  // Every number shown is stats.json's at its path, to the decimals shown.
  int numbers = 0;
  for (const std::string& problem : animpak::test::shown_figure_problems(dom, stats, numbers))
    problems.push_back(problem);
  if (numbers < 25) problems.push_back("only " + std::to_string(numbers) + " numbers are tied to stats.json");
  return problems;
}

struct Loaded {
  std::string dom;
  std::vector<std::string> console;  ///< every console message the page logged
};

Loaded load_in_chromium(const fs::path& page, const fs::path& scratch) {
  const fs::path dom = scratch / "dom.html", log = scratch / "chromium.log";
  // Root (CI) needs --no-sandbox; a profile of its own keeps another Chromium from taking the page over.
  const std::string command = "chromium --headless --no-sandbox --disable-gpu --user-data-dir='" +
                              (scratch / "profile").string() + "' --enable-logging=stderr --v=0 --dump-dom 'file://" +
                              page.string() + "' >'" + dom.string() + "' 2>'" + log.string() + "'";
  REQUIRE(std::system(command.c_str()) == 0);
  Loaded loaded{read_text(dom), {}};
  std::istringstream lines(read_text(log));
  for (std::string line; std::getline(lines, line);)
    if (line.find(":CONSOLE") != std::string::npos) loaded.console.push_back(line);
  return loaded;
}

}  // namespace

TEST_CASE("report: stats.json's numbers, five plots and the animation, loaded by Chromium with no console message") {
  if (!have_chromium())
    return animpak::test::skip("chromium is not on PATH (Debian package chromium); the page was not loaded");
  const animpak::test::TempDir dir("animpak-report-");
  std::ofstream(dir / "scene.json") << animpak::test::star_scene(4, 8, 3, {"", R"("initial_scale": 0.15)"});
  const std::string packed = (dir / "packed").string();
  const CommandResult pack = run_animpak("pack " + (dir / "scene.json").string() + " --out " + packed +
                                         " --max-iterations 150 --frames 8 --size 96 --format png,svg-anim");
  REQUIRE(pack.code == 0);
  const CommandResult report = run_animpak("report " + packed);
  INFO(report.err);
  REQUIRE(report.code == 0);
  CHECK_THAT(report.err, Contains("report.html") && Contains("self-contained"));
  const fs::path page = fs::path(packed) / "report.html";
  const std::string html = read_text(page);
  // Self-contained: nothing is fetched (no src or href to another file, no link element, no @import).
  CHECK(std::regex_search(html, std::regex(R"((src|href)\s*=)")) == false);
  CHECK(html.find("@import") == std::string::npos);
  const animpak::Stats stats = animpak::parse_stats(read_text(fs::path(packed) / "stats.json"), "stats.json");

  const Loaded loaded = load_in_chromium(page, dir.path());
  for (const std::string& line : loaded.console) UNSCOPED_INFO(line);
  CHECK(loaded.console.empty());
  const std::vector<std::string> problems = page_problems(loaded.dom, stats);
  for (const std::string& p : problems) UNSCOPED_INFO(p);
  CHECK(problems.empty());

  // The same check sees a page without a plot or without the animation (held to the page as written, the
  // DOM Chromium built being that page with the script's marks).
  const auto doctored = [&](const std::string& from, const std::string& to) {
    std::string text = loaded.dom;
    const std::size_t begin = text.find(from);
    REQUIRE(begin != std::string::npos);
    const std::size_t end = text.find(to, begin);
    REQUIRE(end != std::string::npos);
    text.erase(begin, end + to.size() - begin);
    std::string all;
    for (const std::string& p : page_problems(text, stats)) all += p + "\n";
    return all;
  };
  CHECK_THAT(doctored("<svg class=\"plot\" id=\"plot-kink\"", "</svg>"), Contains("plot-kink: missing"));
  CHECK_THAT(doctored("<div id=\"animation\">", "</svg>"), Contains("no animated SVG in #animation"));

  // The screenshot shows the page: many colours, most of the page not background.
  const fs::path shot = dir / "shot.png";
  const std::string command = "chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --user-data-dir='" +
                              (dir / "profile").string() + "' --window-size=1000,1400 --screenshot='" + shot.string() +
                              "' 'file://" + page.string() + "' >/dev/null 2>&1";
  REQUIRE(std::system(command.c_str()) == 0);
  auto in = OIIO::ImageInput::open(shot.string());
  REQUIRE(in);
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<unsigned char> pixels(std::size_t(spec.width) * spec.height * spec.nchannels);
  REQUIRE(in->read_image(0, 0, 0, -1, OIIO::TypeDesc::UINT8, pixels.data()));
  std::set<unsigned> colours;
  std::size_t off_background = 0;
  for (std::size_t i = 0; i + 2 < pixels.size(); i += spec.nchannels) {
    const unsigned rgb = pixels[i] << 16 | pixels[i + 1] << 8 | pixels[i + 2];
    colours.insert(rgb);
    off_background += rgb != 0xfafafa ? 1 : 0;
  }
  CHECK(colours.size() > 200);
  CHECK(off_background > pixels.size() / spec.nchannels / 4);

  // The page describes one render: the next render removes it.
  REQUIRE(run_animpak("render " + packed + " --frames 2 --size 32 --format png").code == 0);
  CHECK_FALSE(fs::exists(page));
}

TEST_CASE("report: a packing rendered without animation.svg gets one drawn, and one never rendered is refused") {
  const animpak::test::TempDir dir("animpak-report-");
  std::ofstream(dir / "scene.json") << animpak::test::star_scene(2, 5, 4, {"", R"("initial_scale": 0.15)"});
  const std::string packed = (dir / "packed").string(), bare = (dir / "bare").string();
  REQUIRE(run_animpak("pack " + (dir / "scene.json").string() + " --out " + packed +
                      " --max-iterations 40 --frames 4 --size 64 --format png")
              .code == 0);
  const CommandResult report = run_animpak("report " + packed + " --out " + (dir / "page.html").string());
  INFO(report.err);
  REQUIRE(report.code == 0);
  CHECK_THAT(report.err, Contains("has no animation.svg; drawing one"));
  CHECK_THAT(read_text(dir / "page.html"), Contains("<animate"));
  CHECK_FALSE(fs::exists(fs::path(packed) / "animation.svg"));
  CHECK_FALSE(fs::exists(fs::path(packed) / ".report-partial"));
  CHECK_FALSE(fs::exists(fs::path(packed) / "report.html"));

  REQUIRE(run_animpak("pack " + (dir / "scene.json").string() + " --out " + bare + " --max-iterations 20 --no-render")
              .code == 0);
  const CommandResult refused = run_animpak("report " + bare);
  CHECK(refused.code == 2);
  CHECK_THAT(refused.err, Contains("stats.json: no frames") && Contains("animpak render " + bare));
  CHECK_FALSE(fs::exists(fs::path(bare) / "report.html"));
  const CommandResult empty = run_animpak("report " + (dir / "nothing").string());
  CHECK(empty.code == 2);
  CHECK_THAT(empty.err, Contains("no state.bin"));
}

TEST_CASE("report: numbers with thousands separated and no negative zero, and a page needs frames") {
  using animpak::report_number;
  CHECK(report_number(5400, 0) == "5,400");
  CHECK(report_number(1234567.891, 2) == "1,234,567.89");
  CHECK(report_number(43.46, 1) == "43.5");
  CHECK(report_number(-0.001, 2) == "0.00");
  CHECK(report_number(-1234.5, 1) == "-1,234.5");
  CHECK(report_number(999.96, 1) == "1,000.0");
  animpak::ReportInput input;
  input.stats.frames.emplace();
  CHECK_THROWS_WITH(animpak::report_page(input), Contains("no frames") && Contains("animpak render"));
  // A folder rendered before frame_peak existed: the kink plot says how to get it, the others plot.
  input.stats.frames = {animpak::StatsFrame{}, animpak::StatsFrame{}};
  (*input.stats.frames)[0].coverage = 0.4;
  (*input.stats.frames)[1].t = 0.5;
  (*input.stats.frames)[1].coverage = 0.5;
  input.stats.motion = animpak::StatsMotion{};
  input.stats.motion->acceleration_median = 1e-4;
  input.stats.motion->kink = 7;
  const std::string page = animpak::report_page(input);
  CHECK_THAT(page, Contains("rendered before animpak 0.11.0: run animpak render DIR"));
  CHECK_THAT(page, Contains(R"(<span data-stat="motion.kink">7.0</span>)"));
  // Too large an SVG: the GIF stands in, as a data URI, and the page says so.
  CHECK(animpak::base64("") == "");
  CHECK(animpak::base64("f") == "Zg==");
  CHECK(animpak::base64("fo") == "Zm8=");
  CHECK(animpak::base64("foo") == "Zm9v");
  CHECK(animpak::base64(std::string("\xff\xfe\x00", 3)) == "//4A");
  input.animation_gif = "GIF89a";
  input.animation_note = "animation.svg (61 MB) is too large";
  const std::string with_gif = animpak::report_page(input);
  CHECK_THAT(with_gif,
             Contains(R"(<img id="animation-gif" alt="the animation" src="data:image/gif;base64,R0lGODlh">)"));
  CHECK_THAT(with_gif, Contains("animation.svg (61 MB) is too large"));
}
