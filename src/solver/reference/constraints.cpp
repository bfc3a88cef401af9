// Slice constraints of paper §5.2, hard projections applied after every integration step.
// End-to-end and simultaneity touch one element each (a kernel runs them per element in parallel);
// the loop pass crosses elements and runs afterwards on its own.
#include "animpak/reference/step.hpp"

namespace animpak::reference {

void apply_end_to_end(const Topology& topo, SimState& state, std::int32_t e) {
  const std::int32_t first = topo.element_slice_begin[e], last = topo.element_slice_begin[e + 1] - 1;
  if (last < first) return;
  for (std::int32_t v = topo.slice_begin[first]; v < topo.slice_begin[first + 1]; ++v) state.t[v] = 0.0f;
  for (std::int32_t v = topo.slice_begin[last]; v < topo.slice_begin[last + 1]; ++v) state.t[v] = 1.0f;
}

void apply_simultaneity(const Topology& topo, SimState& state, std::int32_t e) {
  // Inner slices only: the first and last belong to the end-to-end constraint.
  for (std::int32_t s = topo.element_slice_begin[e] + 1; s + 1 < topo.element_slice_begin[e + 1]; ++s) {
    const std::int32_t lo = topo.slice_begin[s], hi = topo.slice_begin[s + 1];
    if (hi == lo) continue;
    float sum = 0.0f;
    for (std::int32_t v = lo; v < hi; ++v) sum = sum + state.t[v];
    const float mean = sum / static_cast<float>(hi - lo);
    for (std::int32_t v = lo; v < hi; ++v) state.t[v] = mean;
  }
}

void apply_loop(const Topology& topo, SimState& state) {
  // The paper's formula moves p2 to ((x1 + x1)/2, (y2 + y2)/2), a typo: both ends go to the average.
  for (std::size_t i = 0; i < topo.loop_end.size(); ++i) {
    const std::int32_t a = topo.loop_end[i], b = topo.loop_start[i];
    const float mx = (state.x[a] + state.x[b]) * 0.5f;
    const float my = (state.y[a] + state.y[b]) * 0.5f;
    state.x[a] = mx;
    state.x[b] = mx;
    state.y[a] = my;
    state.y[b] = my;
  }
}

}  // namespace animpak::reference
