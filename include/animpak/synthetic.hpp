// Synthetic benchmark worlds (scene stage): copies of one animated element in a square container,
// sized to a chosen vertex count, in two series (docs/benchmark.md). `animpak bench` times them
// (animpak/timing.hpp); tests use the same worlds, so a figure in a report and a test mean the same scene.
#pragma once

#include <cstdint>
#include <filesystem>

#include "animpak/scene.hpp"

namespace animpak {

/// How a synthetic world's copies fill its container as the vertex count grows.
enum class SyntheticDensity {
  /// Copies of one size in the unit container: more vertices, more copies per area, so every vertex
  /// has more neighbours to visit (the series `animpak bench` timed first; kept for comparison).
  dense,
  /// As many copies per area, in units of the copies' own size, at every vertex count: the container
  /// grows with the copy count. Every container is normalised to the unit square, so the copies
  /// shrink instead (scale ∝ 1/√copies), and the collision grid's cell and the slice gap in t with
  /// them (cells are cubes over x, y and t): each vertex's block of cells then holds the same
  /// neighbourhood at every size. Larger worlds have more copies and more slices.
  constant,
};

/// A square container holding copies of one animated element, sized to about `target_vertices`.
struct SyntheticSpec {
  std::filesystem::path element_art;  ///< e.g. examples/default/star.svg; animated with preset rotate
  int target_vertices = 10000;
  SyntheticDensity density = SyntheticDensity::dense;
  /// n_s of every copy. Constant density: n_s of the reference world of `constant_density_copies`.
  int slices = 20;
  /// Initial scale of every copy. Dense: at every size, so larger worlds crowd more copies of one size
  /// into the unit container. Constant density: the scale in the reference world.
  double element_scale = 0.035;
  /// Constant density: the copies of the reference world, which has `element_scale`, `slices` and the
  /// default cell_size (45: the dense world of 50,000 vertices at 20 slices); a world of n copies has
  /// every length √(45 / n) times the reference's and 1 + (slices − 1)·√(n / 45) slices, rounded.
  int constant_density_copies = 45;
  std::uint64_t seed = 1;
};

struct SyntheticWorld {
  World world;
  int elements = 0;
  double initial_scale = 0.0;  ///< the scale the copies were placed at
  int slices = 0;              ///< n_s of every copy
};

/// Builds the library element, picks the copy count from `target_vertices` (for constant density with
/// the slices and cell size that go with it), and places the copies with build_world (lowering the
/// scale when set-up reports an overlap).
SyntheticWorld make_synthetic_world(const SyntheticSpec& spec);

}  // namespace animpak
