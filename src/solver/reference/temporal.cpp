// Temporal force, paper Eq. 6: F_tmp = k_tmp u^t (t − t'), t the rest time of the vertex's slice,
// t' its current time, u^t = (0, 0, 1). It draws slices back to their original place in time.
#include "animpak/reference/local_forces.hpp"

namespace animpak::reference {

Vec3f temporal_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v) {
  return {0.0f, 0.0f, params.k_temporal * (topo.rest_t[v] - state.t[v])};
}

}  // namespace animpak::reference
