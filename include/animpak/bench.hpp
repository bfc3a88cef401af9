// The measurements behind `animpak bench` (solver stage): every device timed on one world round by round,
// the rows, medians and least-squares fits; the CLI builds the worlds and prints the rows.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "animpak/opencl.hpp"
#include "animpak/timing.hpp"

namespace animpak {

/// One column of the table: a device, and for OpenCL devices where the grid is sorted.
struct BenchTarget {
  std::string device;  ///< name fragment as given
  GridSort sort = GridSort::automatic;
  std::string label;  ///< the table's and the JSON's device name: "pocl", or "pocl:host" under --grid-sort both
};

/// The reference first (the baseline every speedup is measured against), then each named OpenCL device
/// once, resolved now so that a typo fails before minutes of world building; under `both_sorts` each
/// device twice, its grid sorted on the host and on the device.
std::vector<BenchTarget> bench_targets(const std::vector<std::string>& devices, GridSort sort, bool both_sorts);

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

/// What is timed: one world, named as its rows will be.
struct BenchWorldView {
  std::string scene, series;
  int elements = 0;
  const Topology& topology;
  const SimState& state;
  const Params& params;
};

/// Times every target on `world`, `repeat` rounds, every device in turn within a round, each backend
/// stepping on from where its last round ended (`warmup` untimed steps in the first round only); one row
/// per target, its timing the median round. `progress` is told of each round before it runs.
std::vector<BenchRow> bench_world(const BenchWorldView& world, const std::vector<BenchTarget>& targets, int repeat,
                                  int warmup, int steps,
                                  const std::function<void(const BenchTarget&, int round)>& progress);

}  // namespace animpak
