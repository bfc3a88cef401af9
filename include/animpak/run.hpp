// Running a backend to a stop (paper §5.3), with statistics every params.stop.check_interval steps.
#pragma once

#include <atomic>
#include <functional>

#include "animpak/simulation.hpp"

namespace animpak {

/// How a run talks to its caller; what stops it is in Params (params.stop).
struct RunControl {
  const std::atomic<bool>* interrupt = nullptr;         ///< set by a signal handler (Ctrl-C)
  std::function<void(const StepStatistics&)> on_check;  ///< progress, after every statistics check
  /// Called with the state at most every `checkpoint_seconds` of wall time (0: at every check), on a
  /// finite check on a grid-rebuild boundary: the state an interrupt there would save, from which a resumed
  /// run continues bit-identically. Empty: no checkpoints.
  std::function<void(const SimState&)> on_checkpoint;
  double checkpoint_seconds = 60.0;
};

struct RunResult {
  StopReason reason = StopReason::running;
  StepStatistics last;  ///< the latest statistics
  SimState last_good;   ///< the latest state known to be finite (the final state unless non_finite)
  double seconds = 0.0;
};

/// Steps until the largest per-slice gap falls below params.stop.stop_gap, every g passes
/// params.stop.stop_growth (when set), the iteration count reaches params.stop.max_iterations (an absolute
/// count: a resumed state's earlier steps count; a state already there, or a limit below 1, steps no more),
/// an interrupt arrives, or a NaN/Inf appears (then last_good holds the last finite state).
RunResult run_simulation(Backend& backend, const Params& params, const RunControl& control);

}  // namespace animpak
