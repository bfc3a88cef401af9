// What pack and render print (docs/cli.md, "Progress and the time left"): lines within 80 columns, the
// render's progress, and every file the run wrote listed with its size at the end.
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "console.hpp"
#include "run_animpak.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using namespace animpak::cli;

namespace {

// The longest line of `text`, with `folder` (a temporary path of any length) counted as "DIR".
std::size_t longest_line(const std::string& text, const std::string& folder = "") {
  std::istringstream in(text);
  std::size_t longest = 0;
  for (std::string line; std::getline(in, line);) {
    for (std::size_t at; !folder.empty() && (at = line.find(folder)) != std::string::npos;)
      line.replace(at, folder.size(), "DIR");
    longest = std::max(longest, line.size());
  }
  return longest;
}

}  // namespace

TEST_CASE("console: sizes and the render's progress text") {
  CHECK(size_text(812) == "812 B");
  CHECK(size_text(24 * 1024 + 10) == "24.0 KiB");
  CHECK(size_text(3565158) == "3.4 MiB");
  CHECK(clock_text(3725.9) == "01:02:05");
  CHECK(render_progress_text("frame", 25, 100, 10.0) == "render: frame 25/100  00:00:10  ~00:00:30 left");
  CHECK(render_progress_text("frame", 100, 100, 40.0) == "render: frame 100/100  00:00:40");
  CHECK(render_progress_text("animation.gif", 0, 1, 41.0) == "render: writing animation.gif  00:00:41");
  // The longest a line can be: "animpak: " and the largest counts and clocks.
  CHECK(9 + render_progress_text("frame", 99999, 100000, 359999.0).size() <= 80);
}

TEST_CASE("console: the pack's progress line fits 80 columns on a terminal and in a log") {
  animpak::StepStatistics st;
  st.iteration = 99999999;
  st.max_slice_gap = 0.0149f;
  st.growing_share = 1.0f;
  const animpak::StopEstimate worst{100000000, 359999.0, true};
  const std::string line = pack_progress_text(st, 359999.0, worst, false);
  CHECK(line == "iter 99999999  gap 0.0149  growing 100%  99:59:59  ~99:59:59 left+");
  CHECK(progress_bar(0.5) == "[####....]");
  CHECK(progress_bar(1.2) == "[########]");
  CHECK(progress_bar(0.5).size() + 1 + line.size() <= 80);  // the terminal's redrawn line
  CHECK(std::string("animpak: ").size() + line.size() <= 80);
  CHECK(pack_progress_text(st, 1.0, std::nullopt, false) ==
        "iter 99999999  gap 0.0149  growing 100%  00:00:01  estimating");
  st.max_slice_gap = std::numeric_limits<float>::infinity();
  CHECK_THAT(pack_progress_text(st, 1.0, std::nullopt, true), Contains("gap inf") && Contains("overlaps 0"));
}

TEST_CASE("console: the pack's progress bar never moves back when the time left grows") {
  ProgressShare share;
  CHECK(share.update(5.0, std::nullopt) == 0.0);  // estimating
  CHECK(share.update(60.0, 60.0) == Approx(0.5));
  // The estimate jumps from a minute left to five (as a run leaving free growth can): the bar holds.
  CHECK(share.update(80.0, 300.0) == Approx(0.5));
  CHECK(progress_bar(share.update(80.0, 300.0)) == "[####....]");
  CHECK(share.update(100.0, std::nullopt) == Approx(0.5));  // no estimate: the bar stays
  // The run catches up with the bar, then passes it.
  CHECK(share.update(300.0, 100.0) == Approx(0.75));
  CHECK(share.update(310.0, -5.0) == Approx(1.0));  // a stop already passed reads as done
  // The swings a user saw (17, 23, 38, 32, 7, 6, 8, 4 minutes left, a minute apart): never back.
  double before = 0.0, elapsed = 0.0;
  ProgressShare swings;
  for (const double left : {1020.0, 1380.0, 2280.0, 1920.0, 420.0, 360.0, 480.0, 240.0}) {
    elapsed += 60.0;
    const double now = swings.update(elapsed, left);
    CHECK(now >= before);
    before = now;
  }
}

TEST_CASE("console: the files of a run, each with its size, within 80 columns") {
  const animpak::test::TempDir dir("animpak-console-");
  fs::create_directories(dir / "frames");
  fs::create_directories(dir / "input/art");
  std::ofstream(dir / "state.bin") << std::string(2048, 's');
  std::ofstream(dir / "stats.json") << "{}";
  std::ofstream(dir / "input/scene.json") << "{}";
  std::ofstream(dir / "input/art/a.svg") << "<svg/>";
  for (int i = 0; i < 3; ++i) std::ofstream(dir / ("frames/frame_000" + std::to_string(i) + ".png")) << "png!";
  std::ofstream(dir / "frames/notes.txt") << "not a frame";
  std::ofstream(dir / "animation.json") << std::string(1536, 'j');
  const std::string pack = written_files(dir.path(), WrittenBy::pack);
  CHECK_THAT(pack, Contains("state.bin         2.0 KiB") && Contains("stats.json        2 B") &&
                       Contains("input/            2 files, 8 B") && Contains("frames/           3 PNG frames, 12 B") &&
                       Contains("animation.json    1.5 KiB"));
  CHECK_THAT(pack, !Contains("animation.gif") && !Contains("notes"));
  const std::string render = written_files(dir.path(), WrittenBy::render);
  CHECK_THAT(render, !Contains("state.bin") && !Contains("input/") && Contains("frames/"));
  CHECK(longest_line(pack) <= 80);
  CHECK_THAT(pack, !Contains("removed"));
  // The run before's files, all of them gone: after `removed:`, wrapped within 80 columns under the sizes.
  std::vector<fs::path> removed;
  for (int i = 0; i < 100000; i += 7) {
    char frame[32];
    std::snprintf(frame, sizeof frame, "frames/frame_%05d", i);
    removed.push_back(std::string(frame) + ".png");
    removed.push_back(std::string(frame) + ".svg");
  }
  for (const char* name : {"animation.gif", "animation.mp4", "animation.lottie", "animation.svg", "contact.png",
                           "report.html", "trajectory.svg"})
    removed.push_back(name);
  removed.push_back("animation.json");  // written again: listed above, not as removed
  const std::string replaced = written_files(dir.path(), WrittenBy::render, removed);
  INFO(replaced);
  CHECK_THAT(replaced, Contains("\n  removed:          frames/ (14286 PNG and 14286 SVG frames), animation.gif,\n"
                                "                    animation.mp4, animation.lottie, animation.svg, contact.png,\n"
                                "                    report.html, trajectory.svg\n"));
  CHECK(longest_line(replaced) <= 80);
}

TEST_CASE("animpak render: says what it renders and lists every file it wrote with its size") {
  const animpak::test::TempDir dir("animpak-console-render-");
  const std::string out = (dir / "out").string();
  const std::string scene = std::string(ANIMPAK_SOURCE_DIR) + "/examples/default/scene.json";
  const CommandResult packed = run_animpak("pack " + scene + " --out " + out +
                                           " --device reference --max-iterations 10 --frames 3 --size 32"
                                           " --format png,gif,lottie");
  REQUIRE(packed.code == 0);
  CHECK_THAT(packed.err, Contains("rendering 3 frames at 32 px") && Contains("state.bin") && Contains("input/") &&
                             Contains("3 PNG frames") && Contains("animation.gif") && Contains("animation.json"));
  const CommandResult rendered = run_animpak("render " + out + " --frames 4 --size 32 --format png,svg");
  REQUIRE(rendered.code == 0);
  CHECK_THAT(rendered.err, Contains("rendering 4 frames") && Contains("4 PNG and 4 SVG frames") &&
                               Contains("stats.json") && !Contains("state.bin") && !Contains("animation.gif  "));
  // The pack's GIF and Lottie, not rendered again: named as removed, not as written.
  CHECK_THAT(rendered.err, Contains("\n  removed:          animation.gif, animation.json\n"));
  // Not a terminal: a line at each file written after the frames, none redrawn in place.
  CHECK_THAT(rendered.err, !Contains("\r"));
  CHECK(longest_line(packed.err, out) <= 80);
  CHECK(longest_line(rendered.err, out) <= 80);
}

TEST_CASE("console: pack --profile's table, each phase and each kernel, the largest kernel first, within 80 columns") {
  animpak::PhaseTimes times;
  times.grid = 1.0, times.forces = 6.0, times.integrate = 0.5, times.growth = 0.25;
  const std::vector<animpak::KernelTime> kernels = {
      {"slot_positions", "grid", 1.0, 400},
      {"repulsion_force", "forces", 5.0, 400},
      {"a_kernel_with_a_name_far_longer_than_any_column_of_the_table", "forces", 0.5, 400},
      {"never_launched", "growth", 0.0, 0},
      {"host: overlap broadphase", "forces", 0.5, 400},
  };
  const std::string text = profile_text(times, kernels, 400, 10.0);
  INFO(text);
  CHECK(longest_line(text) <= 80);
  CHECK_THAT(text, Contains("profile: 400 iterations, 00:00:10 of simulation"));
  // forces: 6 s of 10 is 60 %, 15 ms per iteration; the 2.25 s no phase timed are listed as such.
  CHECK_THAT(text, Contains("forces                                  6.00 s  60.0 %    15.000 ms"));
  CHECK_THAT(text, Contains("(not in a phase)                        2.25 s  22.5 %     5.625 ms"));
  CHECK_THAT(text, Contains("repulsion_force (forces)                5.00 s  50.0 %    12.500 ms 400"));
  CHECK(text.find("repulsion_force") < text.find("slot_positions (grid)"));
  CHECK(text.find("slot_positions (grid)") < text.find("host: overlap broadphase (forces)"));
  CHECK(text.find("never_launched") == std::string::npos);
  // The reference backend has no kernels: the phases alone.
  const std::string phases = profile_text(times, {}, 400, 10.0);
  CHECK(phases.find("kernel") == std::string::npos);
  CHECK_THAT(phases, Contains("growth"));
}
