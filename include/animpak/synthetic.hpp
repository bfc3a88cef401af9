// Synthetic benchmark worlds (scene stage): copies of one animated element in a square container,
// sized to a chosen vertex count. `animpak bench` times them (animpak/timing.hpp); tests use the same
// worlds, so a figure in a report and a test mean the same scene.
#pragma once

#include <cstdint>
#include <filesystem>

#include "animpak/scene.hpp"

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

}  // namespace animpak
