// A run's progress as `pack` sees it every params.stop.check_interval steps, and the estimate of when it
// stops (docs/cli.md, "Progress and the time left"): a model of the stop test (paper §5.3 and the stall
// test of docs/parameters.md, "Stop test") fitted to the mean growth so far.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "animpak/params.hpp"

namespace animpak {

/// One statistics check of a run: what stats.json's "progress" rows hold.
struct ProgressSample {
  std::uint64_t iteration = 0;
  double seconds = 0.0;  ///< simulation seconds since the packing started (resumes included)
  double mean_growth = 1.0;
  double growing_share = 0.0;
  double max_gap = 0.0;
  std::int64_t overlapping = 0, outside = 0;
};

struct StopEstimate {
  std::uint64_t iteration = 0;     ///< the predicted stop
  double seconds_left = 0.0;       ///< at the recent pace
  bool secondary_pending = false;  ///< secondary elements will grow after the primary ones stall (counted in)
};

/// Predicts the iteration at which the run stops, and the seconds left (docs/cli.md, "Progress and the time
/// left"). While most slices grow freely, from the container's share the meshes fill at g = 1
/// (unit_mesh_density): they grow until they fill about 0.6 of it. Once they meet, from the stall test's
/// own windows: each window's rise of the mean g decays by the ratio of the last two, until one rises by
/// less than stall_growth (the test itself replayed at its stall_tests marks per window). Either way §5.3's gap test can come first (the largest gap's exponential fall
/// over the last two windows, to stop_gap), and settling adds a share. The pace of the last half window, scaled by the growth still to
/// come, gives the seconds. Nothing (nullopt) until enough samples.
class StopModel {
 public:
  /// `unit_density`: unit_mesh_density of the world (0 when unknown: no estimate during free growth).
  /// `base_rate`: growth_rate · Δt_sim, the g a free slice gains per step without the room's boost
  /// (docs/parameters.md, "Growth that follows the room"); 0 when unknown.
  StopModel(const Params::Stop& stop, bool has_secondary, double unit_density, double base_rate = 0.0)
      : stop_(stop), has_secondary_(has_secondary), unit_density_(unit_density), base_rate_(base_rate) {}
  void observe(const ProgressSample& sample);
  std::optional<StopEstimate> estimate() const;
  const std::vector<ProgressSample>& samples() const { return samples_; }

 private:
  Params::Stop stop_;
  bool has_secondary_;
  double unit_density_;
  double base_rate_;
  std::vector<ProgressSample> samples_;
};

}  // namespace animpak
