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
  std::string scene;      ///< "synthetic-<target>" or the example's folder name
  bool synthetic = false;
  int vertices = 0;
  int elements = 0;
  StepTiming timing;
  double reference_ms_per_iter = 0.0;  ///< the reference backend's ms per step on the same world
  std::int64_t neighbour_visits = 0;   ///< envelope triangles the repulsion queries visit per step
  std::string grid_sort;               ///< OpenCL devices: where the grid was sorted (host, device)
};

/// Least-squares line of ms per step against thousands of vertices over one device's synthetic rows.
struct LinearFit {
  int points = 0;
  double slope_ms_per_kvertex = 0.0;
  double intercept_ms = 0.0;
  double cost_ratio = 0.0;  ///< ms per vertex at the largest size over ms per vertex at the smallest
  PhaseTimes phase_ratios;  ///< the same ratio phase by phase: locates a step that grows faster than linear
  /// Forces ms per neighbour visit at the largest size over the smallest: near 1 when the force phase
  /// costs what its neighbourhoods hold, i.e. when any growth of cost per vertex is density, not code.
  double visit_cost_ratio = 0.0;
};
LinearFit fit_synthetic(const std::vector<BenchRow>& rows, const std::string& device);

/// ms per step against vertices, one line per device over its synthetic rows, example scenes as
/// labelled squares; axes with ticks and a legend.
void write_bench_plot(const std::vector<BenchRow>& rows, const std::filesystem::path& file);

}  // namespace animpak::cli
