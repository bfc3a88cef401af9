#include <limits>

#include "animpak/simulation.hpp"

namespace animpak {

void reduce_slice_statistics(const SliceStatistics& slices, const std::vector<float>& growth, std::int32_t grown,
                             StepStatistics& st) {
  st.max_slice_gap = 0.0f;
  st.min_slice_gap = std::numeric_limits<float>::infinity();
  for (const float g : slices.gap) {
    st.max_slice_gap = g > st.max_slice_gap ? g : st.max_slice_gap;
    st.min_slice_gap = g < st.min_slice_gap ? g : st.min_slice_gap;
  }
  st.growing_share = slices.gap.empty() ? 0.0 : double(grown) / double(slices.gap.size());
  st.overlapping_vertices = st.outside_vertices = 0;
  st.finite = true;
  st.first_bad_vertex = -1;
  for (std::size_t s = 0; s < slices.gap.size(); ++s) {
    st.overlapping_vertices += slices.overlapping[s];
    st.outside_vertices += slices.outside[s];
    if (st.finite && slices.first_bad[s] >= 0) st.finite = false, st.first_bad_vertex = slices.first_bad[s];
  }
  st.min_growth = st.max_growth = growth.empty() ? 1.0f : growth[0];
  double sum = 0.0;
  for (const float g : growth) {
    st.min_growth = g < st.min_growth ? g : st.min_growth;
    st.max_growth = g > st.max_growth ? g : st.max_growth;
    sum += g;
  }
  st.mean_growth = growth.empty() ? 1.0 : sum / double(growth.size());
}

}  // namespace animpak
