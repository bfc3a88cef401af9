// Coarse to fine (the paper's §8 names it as future work; docs/parameters.md, "Coarse to fine"): a packing
// starts with fewer slices per element, while the elements are small and far apart, and goes on at the
// scene's own slices once the coarse level has stopped. Both backends start the fine level from the same
// host-made state (refine_state), so their steps stay bit-identical across the refinement.
#pragma once

#include <string>

#include "animpak/scene.hpp"

namespace animpak {

/// The slices per element of a scene's coarse level: one for about every params.element.coarse_step of
/// the scene's slice intervals; 0 (the packing runs at the scene's slices from the start) when that is
/// fewer than twice what the collision grid needs to see from one slice to the next (slices at most three
/// cells apart in t: 10 at the default cell_size) or more than half the scene's slices, or coarse_step is 1.
int coarse_slices(const Params& params);

/// Why `coarse` cannot stand for `fine` at the coarse level (the elements or their loop partners differ
/// between the two builds of one scene), or empty when it can: each instance the same library element, as
/// guided, with the same vertices per slice, and the loop pairs joining the same elements.
std::string level_mismatch(const World& coarse, const World& fine);

/// The state of `fine` (the scene at its own slices) from `coarse_state`, a state of `coarse` (the same
/// scene at its coarse level), at the same iteration: every vertex of every fine slice on the curve its
/// vertex follows in the coarse state at the fine slice's time (include/animpak/curve.hpp, as the frames
/// draw it), its t the slice's, its velocity and the slice's g interpolated linearly between the two coarse
/// slices around that time; the rest lengths from the fine rest copy at those g (§5.3). The coarse level's
/// stop is the packing's: the state settles from there (settling_since the refinement's iteration; the stall
/// test's marks and secondary_since kept), so the scene's slices only clear what the refinement left.
/// Throws std::invalid_argument when level_mismatch says why.
SimState refine_state(const World& coarse, const SimState& coarse_state, const World& fine);

}  // namespace animpak
