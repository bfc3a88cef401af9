// Results of `animpak bench`, shared by the table, the JSON and the plot.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "animpak/synthetic.hpp"
#include "animpak/timing.hpp"

namespace animpak::cli {

struct BenchRow {
  std::string device;
  std::string scene;   ///< "<series>-<target>", the example's folder name, or the --scene path as given
  std::string series;  ///< "constant" or "dense" (synthetic worlds), "example", or "scene" (--scene)
  int vertices = 0;
  int elements = 0;
  StepTiming timing;
  double reference_ms_per_iter = 0.0;  ///< the reference backend's ms per step on the same world
  std::int64_t neighbour_visits = 0;   ///< envelope triangles the repulsion queries visit per step
  std::string grid_sort;               ///< OpenCL devices: where the grid was sorted (host, device)
  /// ms per step of every round (bench --repeat), in round order; `timing` is the median round's
  std::vector<double> rounds_ms;
  /// the reference's ms per step over this device's, round by round (the same round's two timings)
  std::vector<double> rounds_speedup;

  bool synthetic() const { return series == "constant" || series == "dense"; }
  /// Envelope triangles of other elements visited per step, over all vertices (docs/benchmark.md).
  double visits_per_vertex() const { return vertices > 0 ? double(neighbour_visits) / vertices : 0.0; }
  /// The median of the rounds' speedups (docs/benchmark.md, "Rounds").
  double speedup() const;
  /// The slowest round's ms per step minus the fastest's, as a percentage of the median round's.
  double spread_percent() const;
};

/// The median of `rounds` by ms per step (of an even count, the lower of the two middle ones), so that
/// the reported phases belong to one real round.
StepTiming median_round(const std::vector<StepTiming>& rounds);

/// The median of `values` (of an even count, the mean of the two middle ones); 0 for none.
double median(std::vector<double> values);

/// Least-squares line of ms per step against thousands of vertices over one device's rows of one
/// synthetic series.
struct LinearFit {
  int points = 0;
  double slope_ms_per_kvertex = 0.0;
  double intercept_ms = 0.0;
  double cost_ratio = 0.0;  ///< ms per vertex at the largest size over ms per vertex at the smallest
  PhaseTimes phase_ratios;  ///< the same ratio phase by phase: locates a step that grows faster than linear
  /// Forces ms per neighbour visit at the largest size over the smallest of the rows with at least one
  /// visit per vertex: near 1 when the force phase costs what its neighbourhoods hold, i.e. when any
  /// growth of cost per vertex is density, not code; 0 with fewer than two such rows.
  double visit_cost_ratio = 0.0;
  double min_visits_per_vertex = 0.0, max_visits_per_vertex = 0.0;  ///< over the fitted rows
};
LinearFit fit_series(const std::vector<BenchRow>& rows, const std::string& device, const std::string& series);

/// ms per step against vertices, one line per device and synthetic series, example and --scene scenes
/// as labelled squares; axes with ticks and a legend.
void write_bench_plot(const std::vector<BenchRow>& rows, const std::filesystem::path& file);

}  // namespace animpak::cli
