// The figures library (animpak_report, docs/architecture.md, "Layers"): the pages and pictures animpak draws
// from what a packing wrote, linked by `animpak` only. `animpak report DIR`'s page (docs/cli.md, "`report`"):
// one self-contained HTML file with the packing's animation, its quality and motion per frame as plots, its
// elements and its provenance, built from stats.json's figures as they are (docs/quality.md, "stats.json"), so
// every number the page shows is one of that file's, named by its path in a data-stat attribute. The
// trajectory figure of `animpak trajectory` (docs/cli.md, "`trajectory`"), the sweep's page and table
// (docs/sweeps.md, "Choosing a packing") and the plot of `animpak bench`'s rows.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "animpak/bench.hpp"
#include "animpak/geometry.hpp"
#include "animpak/stats.hpp"

namespace animpak {

/// `value` with `decimals` decimals, thousands separated by commas ("5,400", "43.5").
std::string report_number(double value, int decimals);

/// One row of the page's table of elements.
struct ReportElement {
  std::string name;       ///< the element's name in stats.json ("star#3", a guided element's own name)
  std::string library;    ///< its library element's name
  std::string art;        ///< the art file as the scene names it
  std::string kind;       ///< "unguided", "guided" or "secondary"
  std::string thumbnail;  ///< an inline <svg> of its art (our own drawing of the imported art, never the file)
};

struct ReportInput {
  std::string title;          ///< the packed folder's name
  Stats stats;                ///< DIR/stats.json
  std::string animation_svg;  ///< DIR/animation.svg (animpak's own svg-anim output), inline
  /// Instead of the SVG, when it is too large to open quickly: DIR/animation.gif's bytes, embedded as a
  /// data URI (the slider then moves the plots' cursor and the readout, not the animation).
  std::string animation_gif;
  std::string animation_note;           ///< a line under the animation saying which one the page shows, and why
  std::vector<ReportElement> elements;  ///< in stats.json's element order
};

/// The ids of the page's plots, each an inline <svg> holding one <polyline> per series: coverage,
/// channel CV, wall ratio and kink against the frame time, and the contact function H(r).
inline const std::vector<std::string> kReportPlots = {"plot-coverage", "plot-channel", "plot-wall", "plot-kink",
                                                      "plot-contact"};

/// animation.svg files larger than this are not inlined when animation.gif can stand in (report.cpp): a
/// 61 MB one (32 elements of detailed clip art over 100 slices) took headless Chromium a minute to open.
inline constexpr std::uintmax_t kInlineSvgLimit = 16u << 20;

/// The whole page. InputError when stats.json lacks the per-frame figures (a folder packed with
/// --no-render or by animpak-solve).
std::string report_page(const ReportInput& input);

/// RFC 4648 base64 of `bytes` (the GIF's data URI).
std::string base64(const std::string& bytes);

// The picture `animpak trajectory` draws: one element's path through spacetime in one or more packings, as
// one standalone SVG. The paper's Fig. 16c sets the path of one fish in a packing with stiff time springs
// beside the same fish's with springs 1 % as stiff, to show how much more the second one fluctuates; this
// draws that comparison for any element of any packings.

/// One packing's element: where its art centroid is at each time.
struct TrajectoryRun {
  std::string label;                            ///< how the legend names the packing (its folder's name)
  std::vector<double> t;                        ///< the times, increasing, evenly spaced over [0, 1)
  std::vector<Vec2> path;                       ///< the art centroid at each time (element_path)
  std::vector<std::vector<Vec2>> outline_at_0;  ///< the element's art at t = 0, as polylines, drawn faintly
  /// When the packing loops: where the path goes on after the last time (the first point of the element
  /// this one loops into, loop_neighbours) and where it was before the first (the last point of the
  /// element that loops into this one). Unset: the path's own first and last points.
  std::optional<Vec2> after, before;
};

/// How far and how jerkily an element travels, in container widths and loops (the time axis' unit).
struct TrajectoryStats {
  double length = 0.0;  ///< the path's length over the times (and on to `after` when it loops)
  /// |second difference| / Δt² at each time, in container widths per loop²: its median and 99th
  /// percentile. With times a few per slice interval this is the curve's acceleration, whose
  /// high-frequency part the paper's Fig. 16c shows.
  double acceleration_median = 0.0, acceleration_p99 = 0.0;
};

/// The statistics of one run; `width` is the container's width (the unit), `loop` whether the last time
/// wraps round to the first. InputError for fewer than three times or times not evenly spaced.
TrajectoryStats trajectory_stats(const TrajectoryRun& run, double width, bool loop);

struct TrajectoryFigure {
  std::string element;                   ///< the element's name, as stats.json names it
  std::vector<Vec2> outline;             ///< the container as the frames show it
  std::vector<std::vector<Vec2>> holes;  ///< its holes
  bool loop = true;                      ///< whether the packings loop
  std::vector<TrajectoryRun> runs;       ///< one per packing, drawn in this order
};

/// The standalone SVG: a top view of the container with every run's path and the element at t = 0;
/// x(t) and y(t) with one line per run (src/report/svg_plot.hpp, ids plot-x and plot-y); and one legend line per
/// run with its TrajectoryStats. Each run's lines carry data-run="<index>".
std::string trajectory_svg(const TrajectoryFigure& figure);

// What `animpak sweep collect DIR` writes: DIR/sweep.html, one self-contained page with a card per run,
// sorted by a measure chosen on the page, and plots of each measure against the one setting a sweep varies;
// and DIR/runs.csv, the same figures for a notebook. Every figure is a run's stats.json's, named by its path
// there (data-stat), as on the report page.

/// A figure of every run, the page sorts by and the CSV lists: its path in stats.json, how the page shows it
/// and which way is better.
struct SweepMeasure {
  std::string key;    ///< the CSV's column and the page's sort key (coverage_min)
  std::string label;  ///< "coverage, lowest frame"
  std::string path;   ///< in stats.json (quality.frames.coverage.min): the page's data-stat
  std::function<std::optional<double>(const Stats&)> value;  ///< the figure at `path`, none when the file has none
  bool whole = false;  ///< a count: runs.csv writes it without a decimal point, as stats.json does
  double scale = 1.0;
  int decimals = 2;
  std::string unit;
  std::string better;  ///< high, low, or half (closest to 0.5: the wall ratio of an even packing)
};

/// The measures in the order the cards and the CSV show them; the first is the page's default sort.
const std::vector<SweepMeasure>& sweep_measures();

/// One run as collect found it.
struct CollectedRun {
  std::size_t index = 0;  ///< its place in the plan
  std::string id;         ///< seed3-k_time0.5: its folder's name under runs/
  std::uint64_t seed = 0;
  std::vector<std::pair<std::string, nlohmann::json>> set;  ///< the settings' values, in the plan's order
  std::string state;                                        ///< done, failed, running, unfinished, not started
  std::string message;                                      ///< a failed run's error; what an unfinished one needs
  std::optional<Stats> stats;                               ///< its stats.json (done runs)
  std::string frame_png;      ///< frames/frame_0000.png's bytes, when there and not too large
  std::string animation_gif;  ///< animation.gif's bytes, likewise
  std::string picture_note;   ///< why a picture is missing
  bool report = false;        ///< runs/ID/report.html is there
};

struct SweepCollection {
  std::string title;                ///< the sweep folder's name
  std::string scene_file;           ///< the plan's scene, as its input/ names it
  std::vector<std::string> varied;  ///< the swept settings' names, in the plan's order
  std::vector<CollectedRun> runs;   ///< in plan order
};

/// The page (self-contained: pictures as data URIs; the only links are to each run's report page).
std::string sweep_page(const SweepCollection& collection);

/// runs.csv: one row per run, every measure as stats.json has it (coverage as a share, not a percentage).
std::string sweep_csv(const SweepCollection& collection);

/// The plot of `animpak bench`'s rows (animpak/bench.hpp): ms per step against vertices, one line per device
/// and synthetic series, example and --scene scenes as labelled squares; axes with ticks and a legend.
void write_bench_plot(const std::vector<BenchRow>& rows, const std::filesystem::path& file);

}  // namespace animpak
