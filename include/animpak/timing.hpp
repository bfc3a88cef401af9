// Step timing of any backend (solver stage): per-iteration wall clock and per-phase times, and the
// neighbour visits that explain them. `animpak bench` reports these for the synthetic worlds of
// animpak/synthetic.hpp.
#pragma once

#include <cstdint>

#include "animpak/simulation.hpp"

namespace animpak {

/// Step timing of one backend, per iteration.
struct StepTiming {
  int steps = 0;
  double ms_per_iter = 0.0;  ///< wall clock around the timed steps, statistics checks included
  PhaseTimes phases_ms;      ///< Backend::times() difference over the timed steps, in ms per step
};

/// Runs `warmup` untimed steps, then `steps` timed ones, calling statistics() every
/// params.stop.check_interval steps as run_simulation does.
StepTiming time_steps(Backend& backend, const Params& params, int warmup, int steps);

/// Envelope triangles (near block) and far-field slots (far shell: triangles, or cell aggregates with
/// far_cells) the repulsion queries of one step visit, summed over boundary vertices: the work the force
/// phase does, which grows with local density, not with size.
std::int64_t neighbour_visits(const Topology& topology, const SimState& state, const Params& params);

}  // namespace animpak
