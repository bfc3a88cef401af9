#include "animpak/reference.hpp"

namespace animpak::reference {

// §5.3: a slice grows by growth_rate · Δt_sim when none of its vertices is inside another element,
// up to max_growth; otherwise its growth pauses. Returns the number of slices that grew.
std::int32_t grow_slices(const Topology& topo, const std::vector<std::uint8_t>& inside, const Params& params,
                         SimState& state, std::vector<std::uint8_t>& grew) {
  const float step = static_cast<float>(params.growth_rate * params.dt);
  const float cap = static_cast<float>(params.max_growth);
  const std::int32_t slices = topo.slice_count();
  grew.assign(slices, 0);
  std::int32_t count = 0;
  for (std::int32_t s = 0; s < slices; ++s) {
    bool blocked = false;
    for (std::int32_t v = topo.slice_begin[s]; v < topo.slice_begin[s + 1] && !blocked; ++v) blocked = inside[v] != 0;
    if (blocked || state.growth[s] >= cap) continue;
    const float g = state.growth[s] + step;
    state.growth[s] = g < cap ? g : cap;
    grew[s] = 1;
    ++count;
  }
  return count;
}

// Rest lengths of every spring with an end on a slice that grew, from the scaled reference copy.
void update_rest_lengths(const Topology& topo, const std::vector<std::uint8_t>& grew, SimState& state) {
  for (std::int32_t v = 0; v < topo.vertex_count(); ++v)
    for (std::int32_t k = topo.spring_begin[v]; k < topo.spring_begin[v + 1]; ++k)
      if (grew[topo.slice[v]] || grew[topo.slice[topo.spring_other[k]]])
        state.spring_rest[k] = reference_rest_length(topo, state.growth, v, k);
}

}  // namespace animpak::reference
