// The reference's growth, paper §5.3 (src/solver/reference/growth.cpp), with the containment and steadiness
// rules of docs/parameters.md ("Growth", "Growth that follows the room"): each slice's g grows while it is
// free, pauses or shrinks back on contact, and is held within growth_ratio of its element's smallest and
// neighbour_growth_ratio of its time neighbours; springs then take their rest lengths from the rest copy
// scaled by g (rest_copy_length, state.hpp). Beside it, the per-slice statistics the stop test reduces
// (stats.cpp). kernels/growth.cl and stats.cl are their twins.
#pragma once

#include <cstdint>
#include <vector>

#include "animpak/simulation.hpp"
#include "animpak/solver/step.hpp"
#include "animpak/state.hpp"
#include "animpak/step_params.hpp"

namespace animpak::reference {

/// How many times growth_rate a free slice grows (docs/parameters.md, "Growth that follows the room"): its gap (the least
/// `closest` over its vertices: the nearest other element or the wall) over boost_gap, clamped to
/// [1, boost], and to at most speed_limit (the multiplier at which the slice's outline moves outwards
/// boost_speed × the velocity cap per step) unless that is below 1. Not in the paper, which grows every
/// free slice at one rate.
float growth_multiplier(float gap, float boost_gap, float boost, float speed_limit);

/// Each slice's own next g from its contacts (docs/parameters.md, "Growth"), into `proposed`: a slice
/// with a vertex outside the container, or one that overlaps an element no larger there (contact_yield),
/// shrinks by shrink_rate · Δt_sim (not below 1); one that overlaps only larger elements, has a boundary
/// vertex nearer the wall than stop_gap, or is at max_growth keeps its g; any other grows by growth_rate ·
/// Δt_sim × growth_multiplier of its gap. Without `growing` (the settling phase) no slice grows, and every overlapping or spilling slice
/// shrinks by settle_shrink_rate · Δt_sim.
void propose_growth(const Topology& topo, const std::vector<std::uint8_t>& contact, const std::vector<float>& closest,
                    const ForceParams& params, bool growing, const SimState& state, std::vector<float>& proposed);

/// Every slice's new g: its proposal, limited to growth_ratio × the smallest proposal of its element and
/// to neighbour_growth_ratio × the proposal of each time neighbour. `changed` marks what moved (GrowthChange,
/// include/animpak/solver/step.hpp); returns how many slices grew.
std::int32_t grow_slices(const Topology& topo, const std::vector<float>& proposed, const ForceParams& params,
                         SimState& state, std::vector<std::uint8_t>& changed);

/// Recomputes the rest length of every spring with an end on a slice marked in `changed`.
void update_rest_lengths(const Topology& topo, const std::vector<std::uint8_t>& changed, SimState& state);

/// Per slice, for the stop test (§5.3), from the latest step's `closest` and `contact` (StepForces) and
/// growth's `changed`: the least gap (0 for a slice growth_held marks), the overlapping and outside vertices,
/// and the first vertex whose position or velocity is not finite. stats.cpp.
void slice_statistics(const Topology& topo, const SimState& state, const std::vector<float>& closest,
                      const std::vector<std::uint8_t>& contact, const std::vector<std::uint8_t>& changed,
                      SliceStatistics& out);

}  // namespace animpak::reference
