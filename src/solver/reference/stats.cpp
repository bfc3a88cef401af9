// Per-slice statistics for the stop test (kernels/stats.cl computes the same per slice on the device).
#include <cmath>
#include <limits>

#include "animpak/reference/growth.hpp"

namespace animpak::reference {

void slice_statistics(const Topology& topo, const SimState& state, const std::vector<float>& closest,
                      const std::vector<std::uint8_t>& contact, const std::vector<std::uint8_t>& changed,
                      SliceStatistics& out) {
  out.resize(static_cast<std::size_t>(topo.slice_count()));
  for (std::int32_t s = 0; s < topo.slice_count(); ++s) {
    float gap = std::numeric_limits<float>::infinity();
    std::int32_t overlapping = 0, outside = 0, bad = -1;
    for (std::int32_t v = topo.slice_begin[s]; v < topo.slice_begin[s + 1]; ++v) {
      gap = closest[v] < gap ? closest[v] : gap;
      overlapping += (contact[v] & contact_overlap) != 0;
      outside += (contact[v] & contact_outside) != 0;
      const bool ok = std::isfinite(state.x[v]) && std::isfinite(state.y[v]) && std::isfinite(state.t[v]) &&
                      std::isfinite(state.vx[v]) && std::isfinite(state.vy[v]) && std::isfinite(state.vt[v]);
      if (!ok && bad < 0) bad = v;
    }
    // A slice its element's growth limits hold back cannot grow: it counts as touching.
    out.gap[s] = (changed[s] & growth_held) != 0 ? 0.0f : gap;
    out.overlapping[s] = overlapping;
    out.outside[s] = outside;
    out.first_bad[s] = bad;
  }
}

}  // namespace animpak::reference
