// The simulation loop (paper §5): a backend advances the state one step at a time; the Simulation
// around it checks statistics every params.stop.check_interval steps, stops on the paper's criteria and
// keeps the last good state. Backends: the scalar reference (src/solver/reference) and OpenCL.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "animpak/params.hpp"
#include "animpak/state.hpp"

namespace animpak {

enum class StopReason { running, gap, stalled, unsettled, growth, max_iterations, interrupted, non_finite };
const char* stop_reason_name(StopReason r);

/// Reduced statistics of the latest step (no full read-back needed).
struct StepStatistics {
  std::uint64_t iteration = 0;
  float max_slice_gap = 0.0f;  ///< largest per-slice closest distance to another element (§5.3 stop test)
  float min_slice_gap = 0.0f;
  double growing_share = 0.0;             ///< share of slices whose g grew in the last step
  std::int64_t overlapping_vertices = 0;  ///< boundary vertices inside another element or crossing one
  std::int64_t outside_vertices = 0;      ///< vertices outside the container (before containment moved them)
  float min_growth = 1.0f, max_growth = 1.0f;
  double mean_growth = 1.0;            ///< mean g over all slices, summed in slice order
  bool finite = true;                  ///< every position and velocity is finite
  std::int32_t first_bad_vertex = -1;  ///< when not finite
};

/// The per-slice statistics of the latest step, one entry per global slice, in slice order: computed by
/// each backend in the same way (reference::slice_statistics, kernels/stats.cl) so the host reads a few
/// numbers per slice instead of the whole state.
struct SliceStatistics {
  std::vector<float> gap;                 ///< least closest distance of the slice's vertices; 0 when held back
  std::vector<std::int32_t> overlapping;  ///< vertices with contact_overlap
  std::vector<std::int32_t> outside;      ///< vertices with contact_outside
  std::vector<std::int32_t> first_bad;    ///< first vertex with a non-finite position or velocity, or -1
  void resize(std::size_t slices) {
    gap.resize(slices), overlapping.resize(slices), outside.resize(slices), first_bad.resize(slices);
  }
};

/// StepStatistics from the per-slice statistics, reduced in slice order the same way for every backend:
/// the range of the gaps (max from 0, min from +inf), the share of the slices that grew (`grown` of
/// them), the vertex counts, the first non-finite vertex, and the range and mean of g (1 when there are
/// no slices).
void reduce_slice_statistics(const SliceStatistics& slices, const std::vector<float>& growth, std::int32_t grown,
                             StepStatistics& st);

/// Seconds spent per phase, summed over steps.
struct PhaseTimes {
  double grid = 0, forces = 0, integrate = 0, constraints = 0, loop = 0, growth = 0, statistics = 0, transfer = 0;
};

/// One kernel's share of a run: its device time and launches (profiling events), and the phase it belongs to.
struct KernelTime {
  std::string name;
  const char* phase;
  double seconds = 0;
  std::uint64_t launches = 0;
};

/// Every phase of PhaseTimes with its name, in step order: one list for every report and sum.
struct NamedPhase {
  const char* name;
  double PhaseTimes::*seconds;
};
inline constexpr NamedPhase phase_fields[] = {{"grid", &PhaseTimes::grid},
                                              {"forces", &PhaseTimes::forces},
                                              {"integrate", &PhaseTimes::integrate},
                                              {"constraints", &PhaseTimes::constraints},
                                              {"loop", &PhaseTimes::loop},
                                              {"growth", &PhaseTimes::growth},
                                              {"statistics", &PhaseTimes::statistics},
                                              {"transfer", &PhaseTimes::transfer}};

/// Adds the seconds of its own lifetime to `sink`: a named timing scope per phase of a step.
class PhaseStopwatch {
 public:
  explicit PhaseStopwatch(double& sink) : sink_(sink), start_(std::chrono::steady_clock::now()) {}
  ~PhaseStopwatch() { sink_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  PhaseStopwatch(const PhaseStopwatch&) = delete;
  PhaseStopwatch& operator=(const PhaseStopwatch&) = delete;

 private:
  double& sink_;
  std::chrono::steady_clock::time_point start_;
};

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string name() const = 0;
  /// One step: grid (every grid_rebuild_interval steps), forces, integration, per-element constraints,
  /// the loop pass, containment, growth and rest lengths.
  virtual void step() = 0;
  virtual StepStatistics statistics() = 0;
  virtual SimState state() = 0;  ///< a full read-back (checkpoints, rendering)
  /// Stops growth for good (slices may still shrink): the settling phase of the stop test. Recorded in
  /// the state's settling_since.
  virtual void stop_growth() = 0;
  /// Lets the secondary elements grow (docs/parameters.md, "Secondary elements"), recorded in the state's
  /// secondary_since. False, changing nothing, when the world has none or they already grow.
  virtual bool start_secondary_growth() = 0;
  /// Records the stall test's progress marks in the state (mark_iteration, mark_growth and
  /// mark_growth_1 … 3 from `marks`), so a resumed run tests at the same iterations against the same marks.
  virtual void set_progress_mark(const SimState& marks) = 0;
  /// Phase times so far. A device backend adds a launch's time once it has completed: call finish()
  /// before reading them (statistics() and state() finish too).
  virtual const PhaseTimes& times() const = 0;
  /// Device time per kernel so far (pack --profile), in step order; empty for a backend without kernels.
  /// Read after finish(), as times().
  virtual std::vector<KernelTime> kernel_times() const { return {}; }
  /// Waits until every step enqueued so far has completed (a no-op for backends that step in place).
  virtual void finish() {}
};

/// The scalar reference backend: plain C++, the specification the kernels are tested against.
std::unique_ptr<Backend> make_reference_backend(const Topology& topology, SimState initial, const Params& params);

}  // namespace animpak
