#include <algorithm>
#include <chrono>

#include "animpak/reference/grid.hpp"
#include "animpak/timing.hpp"

namespace animpak {
namespace {

PhaseTimes per_step_ms(const PhaseTimes& after, const PhaseTimes& before, int steps) {
  const double k = 1000.0 / steps;
  PhaseTimes d;
  for (const NamedPhase& phase : phase_fields) d.*phase.seconds = (after.*phase.seconds - before.*phase.seconds) * k;
  return d;
}

}  // namespace

StepTiming time_steps(Backend& backend, const Params& params, int warmup, int steps) {
  const auto interval = static_cast<std::uint64_t>(std::max(1, params.stop.check_interval));
  // The statistics check belongs to every real run's cost, so it is timed at run_simulation's rate;
  // the iteration is counted here because reading it back from a device would cost a transfer.
  std::uint64_t iteration = backend.statistics().iteration;
  auto advance = [&] {
    backend.step();
    if (++iteration % interval == 0) backend.statistics();
  };
  for (int i = 0; i < warmup; ++i) advance();
  backend.finish();

  StepTiming timing;
  timing.steps = std::max(1, steps);
  const PhaseTimes before = backend.times();
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < timing.steps; ++i) advance();
  // A device backend only enqueues steps; the clock stops when the last one has run.
  backend.finish();
  const auto stop = std::chrono::steady_clock::now();
  timing.ms_per_iter = std::chrono::duration<double, std::milli>(stop - start).count() / timing.steps;
  timing.phases_ms = per_step_ms(backend.times(), before, timing.steps);
  return timing;
}

std::int64_t neighbour_visits(const Topology& topology, const SimState& state, const Params& params) {
  const CollisionGrid grid = reference::build_collision_grid(topology, state, params);
  std::vector<std::int32_t> near, far;
  std::int64_t visits = 0;
  for (std::int32_t v = 0; v < topology.vertex_count(); ++v) {
    if ((topology.flags[v] & vertex_boundary) == 0) continue;
    const Vec3f q{state.x[v], state.y[v], state.t[v]};
    reference::repulsion_near_slots(grid, q, topology.element[v], near);
    reference::repulsion_far_slots(grid, q, topology.element[v], far);
    visits += static_cast<std::int64_t>(near.size() + far.size());
  }
  return visits;
}

}  // namespace animpak
