#include "animpak/levels.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace animpak {

int coarse_slices(const Params& params) {
  const int slices = params.element.slices, step = params.element.coarse_step;
  if (step <= 1 || slices < 3) return 0;
  const int coarse = (slices - 1 + step - 1) / step + 1;
  // build_world's warning: slices more than three collision-grid cells apart in t do not see each other.
  // The coarse level keeps twice that many: at the grid's least, a traveller's path and the settling fail
  // (docs/parameters.md, "Coarse to fine", has the packs that chose the bound).
  const int grid_least = static_cast<int>(std::ceil(1.0 / (3.0 * params.forces.cell_size))) + 1;
  return coarse >= 2 * grid_least && 2 * coarse <= slices ? coarse : 0;
}

std::string level_mismatch(const World& coarse, const World& fine) {
  if (coarse.elements.size() != fine.elements.size())
    return "the coarse level places " + std::to_string(coarse.elements.size()) + " elements, the scene's slices " +
           std::to_string(fine.elements.size());
  for (std::size_t i = 0; i < fine.elements.size(); ++i) {
    const ElementInstance &c = coarse.elements[i], &f = fine.elements[i];
    if (c.library != f.library || c.guided != f.guided ||
        coarse.library[c.library].vertices_per_slice() != fine.library[f.library].vertices_per_slice())
      return "element " + std::to_string(i) + " (" + f.name +
             ") differs between the coarse level and the scene's slices";
  }
  // Loop pairs: which element's last slice joins which element's first, in the order build_world writes them.
  const auto partners = [](const World& w) {
    std::vector<std::pair<std::int32_t, std::int32_t>> pairs;
    for (std::size_t k = 0; k < w.topology.loop_end.size(); ++k)
      pairs.emplace_back(w.topology.element[w.topology.loop_end[k]], w.topology.element[w.topology.loop_start[k]]);
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
  };
  if (partners(coarse) != partners(fine)) return "the elements loop into each other differently at the two levels";
  return {};
}

SimState refine_state(const World& coarse, const SimState& coarse_state, const World& fine) {
  if (const std::string why = level_mismatch(coarse, fine); !why.empty())
    throw std::invalid_argument("refine_state: " + why);
  const Topology& topo = fine.topology;
  SimState out;
  const std::size_t n = static_cast<std::size_t>(topo.vertex_count());
  out.x.resize(n), out.y.resize(n), out.t.resize(n), out.vx.resize(n), out.vy.resize(n), out.vt.resize(n);
  out.growth.resize(static_cast<std::size_t>(topo.slice_count()));
  for (std::size_t i = 0; i < fine.elements.size(); ++i) {
    const ElementInstance &ci = coarse.elements[i], &fi = fine.elements[i];
    const int P = fine.library[fi.library].vertices_per_slice();
    const int nf = fine.library[fi.library].slice_count;
    const std::vector<Vec2> tangents = element_tangents(coarse, coarse_state, static_cast<int>(i));
    for (int sf = 0; sf < nf; ++sf) {
      const std::int32_t first = fi.vertex_begin + sf * P;
      const double tf = double(topo.rest_t[first]);
      const std::vector<Vec2> at = element_at(coarse, coarse_state, static_cast<int>(i), tf, tangents);
      // The two coarse slices around tf (the interval element_at reads) and tf's share of the way between.
      const SliceInterval around = slice_interval(coarse, coarse_state, static_cast<int>(i), tf);
      const double w = around.share;
      const auto lerp = [w](double a, double b) { return static_cast<float>(a + (b - a) * w); };
      const std::int32_t cs = ci.slice_begin + around.slice, cn = cs + 1;
      out.growth[fi.slice_begin + sf] = lerp(coarse_state.growth[cs], coarse_state.growth[cn]);
      for (int v = 0; v < P; ++v) {
        const std::size_t a = static_cast<std::size_t>(coarse.topology.slice_begin[cs] + v),
                          b = static_cast<std::size_t>(coarse.topology.slice_begin[cn] + v);
        const auto k = static_cast<std::size_t>(first + v);
        out.x[k] = static_cast<float>(at[v].x);
        out.y[k] = static_cast<float>(at[v].y);
        out.t[k] = topo.rest_t[k];
        out.vx[k] = lerp(coarse_state.vx[a], coarse_state.vx[b]);
        out.vy[k] = lerp(coarse_state.vy[a], coarse_state.vy[b]);
        out.vt[k] = lerp(coarse_state.vt[a], coarse_state.vt[b]);
      }
    }
  }
  out.spring_rest.resize(topo.spring_other.size());
  for (std::int32_t v = 0; v < topo.vertex_count(); ++v)
    for (std::int32_t k = topo.spring_begin[v]; k < topo.spring_begin[v + 1]; ++k)
      out.spring_rest[k] = rest_copy_length(topo, out.growth, v, k);
  out.iteration = coarse_state.iteration;
  out.secondary_since = coarse_state.secondary_since;
  // The coarse level's stop is the packing's: growth stays stopped, and the scene's slices settle from the
  // refinement on (docs/parameters.md, "Coarse to fine", has the measurement that chose this).
  out.settling_since = coarse_state.iteration;
  copy_progress_marks(coarse_state, out);
  return out;
}

}  // namespace animpak
