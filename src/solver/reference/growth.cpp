// Growth of §5.3 with the containment and steadiness rules of docs/parameters.md ("Growth"): the paper
// pauses a slice that overlaps; here a spilling slice, and an overlapping slice that is the larger of
// the two there, shrink back (while settling, every overlapping slice does), while a smaller overlapping
// slice and a slice touching the wall pause;
// and no slice outgrows growth_ratio × the smallest slice of its element nor neighbour_growth_ratio ×
// either time neighbour, so an element's size changes smoothly over the loop.
#include <cmath>
#include <limits>

#include "animpak/reference/growth.hpp"

namespace animpak::reference {

float growth_multiplier(float gap, float boost_gap, float boost, float speed_limit) {
  float m = gap / boost_gap;
  if (m > boost) m = boost;  // also a gap of +inf (no boundary vertex)
  if (m > speed_limit) m = speed_limit;
  return m > 1.0f ? m : 1.0f;
}

void propose_growth(const Topology& topo, const std::vector<std::uint8_t>& contact, const std::vector<float>& closest,
                    const ForceParams& params, bool growing, const SimState& state, std::vector<float>& proposed) {
  const float step = params.growth_step;  // growth_rate · Δt_sim
  // Settling (growing false) only clears overlaps, so it may back off faster than growth came in.
  const float shrink = growing ? params.shrink_step : params.settle_shrink_step;
  const float cap = params.max_growth;
  const float boost = params.growth_boost;
  const float boost_gap = params.boost_gap;
  const float largest_step = params.boost_step;  // boost_speed · velocity_cap · Δt²
  const std::int32_t slices = topo.slice_count();
  proposed.assign(slices, 0.0f);
  for (std::int32_t s = 0; s < slices; ++s) {
    std::uint8_t bits = 0;
    float gap = std::numeric_limits<float>::infinity(), radius2 = 0.0f;
    for (std::int32_t v = topo.slice_begin[s]; v < topo.slice_begin[s + 1]; ++v) {
      bits |= contact[v];
      gap = closest[v] < gap ? closest[v] : gap;
      const float dx = topo.rest_copy_x[v] - topo.slice_rest_copy_cx[s],
                  dy = topo.rest_copy_y[v] - topo.slice_rest_copy_cy[s];
      const float r2 = dx * dx + dy * dy;
      radius2 = r2 > radius2 ? r2 : radius2;
    }
    const float g = state.growth[s];
    float next = g;
    // Growing, the larger of two overlapping slices yields; settling, both do, so that an overlap one side
    // alone sees (their slices' times differ a little) still clears. Only overlaps with elements that do
    // not give way count (contact_block): a primary slice neither pauses nor shrinks for a secondary one.
    const bool yields = (bits & contact_block) != 0 && (!growing || (bits & contact_yield) != 0);
    // Secondary elements keep their start size until the primary ones have stopped growing.
    const bool held = state.secondary_since == 0 && topo.secondary(topo.slice_element[s]);
    if ((bits & contact_outside) != 0 || yields) {
      next = g - shrink;
      if (next < 1.0f) next = 1.0f;  // never below the overlap-free start (§4)
    } else if (growing && !held && (bits & (contact_wall | contact_block)) == 0 && g < cap) {
      // The outline's farthest vertex moves sqrt(radius2) per unit of g: at most largest_step per step.
      const float speed_limit = largest_step / (std::sqrt(radius2) * step);
      next = g + step * growth_multiplier(gap, boost_gap, boost, speed_limit);
      if (next > cap) next = cap;
    }
    proposed[s] = next;
  }
}

std::int32_t grow_slices(const Topology& topo, const std::vector<float>& proposed, const ForceParams& params,
                         SimState& state, std::vector<std::uint8_t>& changed) {
  const float ratio = params.growth_ratio;
  const float step = params.growth_step;
  const float neighbour_ratio = params.neighbour_growth_ratio;
  // The element's smallest proposal bounds every slice of it, and each slice's time neighbours bound it.
  changed.assign(topo.slice_count(), growth_kept);
  std::int32_t grown = 0;
  for (std::int32_t e = 0; e < topo.element_count(); ++e) {
    const std::int32_t first = topo.element_slice_begin[e], end = topo.element_slice_begin[e + 1];
    if (first == end) continue;
    float smallest = proposed[first];
    for (std::int32_t s = first + 1; s < end; ++s) smallest = proposed[s] < smallest ? proposed[s] : smallest;
    const float limit = ratio * smallest;
    for (std::int32_t s = first; s < end; ++s) {
      float bound = limit;
      if (s > first && neighbour_ratio * proposed[s - 1] < bound) bound = neighbour_ratio * proposed[s - 1];
      if (s + 1 < end && neighbour_ratio * proposed[s + 1] < bound) bound = neighbour_ratio * proposed[s + 1];
      const float g = proposed[s] < bound ? proposed[s] : bound;
      // Held: a limit keeps it below what it proposed, or below one growth step at the paper's rate where
      // the room's boost proposed more; a slice the limits let grow at least that much is not held,
      // however much faster its room would let it grow (docs/parameters.md, "Growth that follows the room").
      const float base = state.growth[s] + step;
      const float wanted = proposed[s] < base ? proposed[s] : base;
      std::uint8_t bits = wanted < bound ? growth_kept : growth_held;
      if (g > state.growth[s]) bits |= growth_grew, ++grown;
      if (g < state.growth[s]) bits |= growth_shrank;
      changed[s] = bits;
      state.growth[s] = g;
    }
  }
  return grown;
}

// Rest lengths of every spring with an end on a slice whose g changed, from the scaled rest copy.
void update_rest_lengths(const Topology& topo, const std::vector<std::uint8_t>& changed, SimState& state) {
  for (std::int32_t v = 0; v < topo.vertex_count(); ++v)
    for (std::int32_t k = topo.spring_begin[v]; k < topo.spring_begin[v + 1]; ++k)
      if (((changed[topo.slice[v]] | changed[topo.slice[topo.spring_other[k]]]) & (growth_grew | growth_shrank)) != 0)
        state.spring_rest[k] = rest_copy_length(topo, state.growth, v, k);
}

}  // namespace animpak::reference
