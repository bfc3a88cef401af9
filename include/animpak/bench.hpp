// Benchmark support (issue 4): synthetic worlds of a chosen size and per-phase step timing of any
// backend. `animpak bench` drives these; they live in the libraries so that tests and a later
// OpenCL comparison use the same worlds and the same clock.
#pragma once

#include <cstdint>
#include <filesystem>

#include "animpak/scene.hpp"
#include "animpak/simulation.hpp"

namespace animpak {

/// A square container holding copies of one animated element, sized to about `target_vertices`.
struct SyntheticSpec {
  std::filesystem::path element_art;  ///< e.g. examples/default/star.svg; animated with preset rotate
  int target_vertices = 10000;
  int slices = 20;                    ///< n_s of every copy
  /// Initial scale of every copy, the same at every size: larger worlds hold more copies of the same
  /// size, so the local density — and with it each vertex's grid neighbourhood — stays the same and
  /// cost per vertex should too. (Shrinking the copies instead crowds more triangles into each cell,
  /// which measures density, not the code's scaling: measured 12× per-vertex cost from 10k to 200k.)
  double element_scale = 0.035;
  std::uint64_t seed = 1;
};

struct SyntheticWorld {
  World world;
  int elements = 0;
  double initial_scale = 0.0;  ///< the scale the copies were placed at
};

/// Builds the library element once, picks the copy count from `target_vertices`, and places them with build_world (lowering the scale when set-up reports an overlap).
SyntheticWorld make_synthetic_world(const SyntheticSpec& spec);

/// Step timing of one backend, per iteration.
struct StepTiming {
  int steps = 0;
  double ms_per_iter = 0.0;  ///< wall clock around the timed steps, statistics checks included
  PhaseTimes phases_ms;      ///< Backend::times() difference over the timed steps, in ms per step
};

/// Runs `warmup` untimed steps, then `steps` timed ones, calling statistics() every
/// params.check_interval steps as run_simulation does.
StepTiming time_steps(Backend& backend, const Params& params, int warmup, int steps);

/// Envelope triangles the repulsion queries of one step visit (near block and far shell, summed over
/// boundary vertices): the work the force phase does, which grows with local density, not with size.
std::int64_t neighbour_visits(const Topology& topology, const SimState& state, const Params& params);

}  // namespace animpak
