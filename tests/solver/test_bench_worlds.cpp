// The neighbour visits `animpak bench` reports beside every row (docs/benchmark.md), on its two series
// of synthetic worlds: flat at constant density, growing in the dense series.
#include <catch2/catch.hpp>

#include <algorithm>

#include "animpak/synthetic.hpp"
#include "animpak/timing.hpp"

using namespace animpak;

namespace {

double visits_per_vertex(SyntheticDensity density, int vertices) {
  SyntheticSpec spec;
  spec.element_art = std::string(ANIMPAK_SOURCE_DIR) + "/examples/default/star.svg";
  spec.target_vertices = vertices;
  spec.density = density;
  const World w = make_synthetic_world(spec).world;
  return double(neighbour_visits(w.topology, w.state, w.params)) / w.topology.vertex_count();
}

}  // namespace

TEST_CASE("Bench worlds: neighbour visits per vertex stay within 1.5x at constant density, dense ones grow") {
  std::vector<double> constant, dense;
  for (int vertices : {10000, 30000, 100000}) {
    constant.push_back(visits_per_vertex(SyntheticDensity::constant, vertices));
    dense.push_back(visits_per_vertex(SyntheticDensity::dense, vertices));
  }
  INFO("constant density: " << constant[0] << ", " << constant[1] << ", " << constant[2]);
  INFO("dense: " << dense[0] << ", " << dense[1] << ", " << dense[2]);
  const auto [lo, hi] = std::minmax_element(constant.begin(), constant.end());
  // The copies have neighbours in reach at every size. A visit is a near triangle or a far cell
  // aggregate (far_cells, docs/parameters.md "Far field"): about 6 per vertex in these worlds of small
  // stars, against about 120 when every far triangle counted.
  CHECK(*lo > 3.0);
  CHECK(*hi < 1.5 * *lo);
  CHECK(dense[2] > 5.0 * std::max(dense[0], 1.0));
  CHECK(dense[2] > 3.0 * constant[2]);
}
