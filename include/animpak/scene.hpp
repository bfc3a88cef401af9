// Scene set-up (paper §4): the container normalized into the unit square and extruded over t, the
// element instances placed in it, and the initial simulation state.
#pragma once

#include <vector>

#include "animpak/element.hpp"
#include "animpak/io.hpp"
#include "animpak/random.hpp"
#include "animpak/scene_spec.hpp"

namespace animpak {

/// The container in unit coordinates: its outline and holes, each a simple ring without repeats.
struct Container {
  std::vector<Vec2> outline;
  std::vector<std::vector<Vec2>> holes;
  ArtFrame frame;  ///< container art coordinates → unit square (targets, field centres use it)
  ArtShape art;    ///< the container's own paths in unit coordinates, for drawing

  /// Inside the outline and outside every hole.
  bool contains(Vec2 p) const;
  /// Distance to the nearest point of the outline or of a hole.
  double distance_to_boundary(Vec2 p) const;
  /// Outline area minus hole areas.
  double area() const;
};

/// Picks the outline and holes from the container art (spec.outline / spec.holes by source index;
/// defaults: holes are `.path` type-7 paths, the outline is the largest remaining closed polyline) and
/// normalizes them like element art (longer side 1, centred). InputError names the file and the path
/// index for a missing index, an outline with fewer than 3 points or no area, or a hole outside it.
Container make_container(const ArtShape& art, const ContainerSpec& spec);

/// Blue-noise (Poisson-disk, Bridson) points inside the container, at least `min_distance` apart and
/// at least `margin` from the boundary, in generation order. Deterministic for the generator's state.
std::vector<Vec2> poisson_disk(const Container& container, double min_distance, double margin, Rng& rng);

}  // namespace animpak
