// Synthetic benchmark worlds (docs/benchmark.md): the constant-density series keeps the copies' share of
// the container at every size; the dense series crowds more copies of one size into it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "animpak/synthetic.hpp"

using namespace animpak;

namespace {

SyntheticWorld world_of(SyntheticDensity density, int vertices) {
  SyntheticSpec spec;
  spec.element_art = std::string(ANIMPAK_SOURCE_DIR) + "/examples/default/star.svg";
  spec.target_vertices = vertices;
  spec.density = density;
  return make_synthetic_world(spec);
}

// The copies' first slices (their outlines as placed), summed, over the container's area.
double covered_share(const World& w) {
  const Topology& topo = w.topology;
  double area = 0.0;
  for (std::int32_t e = 0; e < topo.element_count(); ++e) {
    const std::int32_t s = topo.element_slice_begin[e];
    std::vector<Vec2> ring;
    for (std::int32_t v = topo.slice_begin[s]; v < topo.slice_begin[s] + topo.slice_boundary[s]; ++v)
      ring.push_back({w.state.x[v], w.state.y[v]});
    area += std::abs(signed_area(ring));
  }
  return area / w.container.area();
}

}  // namespace

TEST_CASE("Synthetic worlds: constant density keeps the covered share from 4k to 64k vertices, dense crowds") {
  std::vector<double> constant, dense;
  for (int vertices : {4000, 16000, 64000}) {
    INFO(vertices);
    const SyntheticWorld c = world_of(SyntheticDensity::constant, vertices);
    const SyntheticWorld d = world_of(SyntheticDensity::dense, vertices);
    // Whole copies: each series lands within 15 % of the target.
    CHECK(std::abs(c.world.topology.vertex_count() - vertices) < 0.15 * vertices);
    CHECK(std::abs(d.world.topology.vertex_count() - vertices) < 0.15 * vertices);
    // A container √(copies / 45) times wider than the reference world's, seen in unit space: the
    // cell and the slice gap shrink with the copies.
    CHECK(c.world.params.forces.cell_size * std::sqrt(double(c.elements)) ==
          Approx(0.04 * std::sqrt(45.0)).epsilon(1e-9));
    CHECK(c.slices - 1 == std::lround(19 * std::sqrt(c.elements / 45.0)));
    CHECK(d.slices == 20);
    constant.push_back(covered_share(c.world));
    dense.push_back(covered_share(d.world));
  }
  const auto [lo, hi] = std::minmax_element(constant.begin(), constant.end());
  INFO("constant-density covered shares " << constant[0] << ", " << constant[1] << ", " << constant[2]);
  CHECK(*hi < 1.2 * *lo);
  // Dense: 16 times the copies of one size in the same container.
  INFO("dense covered shares " << dense[0] << ", " << dense[2]);
  CHECK(dense[2] > 8.0 * dense[0]);
}
