// The picture `animpak trajectory` draws (docs/cli.md, "`trajectory`"): one element's path through
// spacetime in one or more packings, as one standalone SVG. The paper's Fig. 16c sets the path of one fish
// in a packing with stiff time springs beside the same fish's with springs 1 % as stiff, to show how much
// more the second one fluctuates; this draws that comparison for any element of any packings.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "animpak/geometry.hpp"

namespace animpak::cli {

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
/// x(t) and y(t) with one line per run (svg_plot.hpp, ids plot-x and plot-y); and one legend line per
/// run with its TrajectoryStats. Each run's lines carry data-run="<index>".
std::string trajectory_svg(const TrajectoryFigure& figure);

}  // namespace animpak::cli
