// Collision grid invariants: the sort is stable and a permutation, and near/far queries find exactly
// what brute force over all triangles finds, on seeded random worlds including points on cell
// borders, at 0 and 1, outside the unit cube, and worlds with empty cells.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "animpak/reference.hpp"

using namespace animpak;
using namespace animpak::reference;

namespace {

// A world of loose envelope triangles (random vertex triples, random elements): the grid only reads
// positions, env_* and env_element.
struct GridWorld {
  Topology topo;
  SimState state;
};

float special_or_random(std::mt19937& rng) {
  static const float specials[] = {0.0f, 1.0f, 0.04f, 0.08f, 0.48f, 0.96f, -0.3f, 1.7f, 0.9999f, 0.04f * 13};
  std::uniform_int_distribution<int> pick(0, 3);
  if (pick(rng) == 0) return specials[std::uniform_int_distribution<int>(0, 9)(rng)];
  return std::uniform_real_distribution<float>(-0.2f, 1.2f)(rng);
}

GridWorld random_world(std::mt19937& rng, int vertices, int triangles, int elements) {
  GridWorld w;
  for (int v = 0; v < vertices; ++v) {
    w.state.x.push_back(special_or_random(rng));
    w.state.y.push_back(special_or_random(rng));
    w.state.t.push_back(special_or_random(rng));
  }
  std::uniform_int_distribution<int> vid(0, vertices - 1), eid(0, elements - 1);
  for (int i = 0; i < triangles; ++i) {
    // A third of the triangles are a repeated vertex, so their centroid is that exact (special) point.
    const int a = vid(rng);
    const bool point = i % 3 == 0;
    w.topo.env_a.push_back(a);
    w.topo.env_b.push_back(point ? a : vid(rng));
    w.topo.env_c.push_back(point ? a : vid(rng));
    w.topo.env_element.push_back(eid(rng));
  }
  return w;
}

std::int32_t cell_of(const CollisionGrid& g, Vec3f p) {
  return (grid_axis_cell(p.t, g.cell, g.n) * g.n + grid_axis_cell(p.y, g.cell, g.n)) * g.n +
         grid_axis_cell(p.x, g.cell, g.n);
}

// Brute force: every triangle of another element whose centroid cell is at Chebyshev distance in
// [lo, hi] from the query's cell, ordered by (cell, id) as the grid promises.
std::vector<std::int32_t> brute(const GridWorld& w, const CollisionGrid& g, Vec3f q, std::int32_t own, int lo, int hi) {
  const int qx = grid_axis_cell(q.x, g.cell, g.n), qy = grid_axis_cell(q.y, g.cell, g.n),
            qt = grid_axis_cell(q.t, g.cell, g.n);
  std::vector<std::pair<std::int32_t, std::int32_t>> hits;
  for (std::int32_t i = 0; i < w.topo.envelope_count(); ++i) {
    if (w.topo.env_element[i] == own) continue;
    const Vec3f c = envelope_centroid(w.topo, w.state, i);
    const int cx = grid_axis_cell(c.x, g.cell, g.n), cy = grid_axis_cell(c.y, g.cell, g.n),
              ct = grid_axis_cell(c.t, g.cell, g.n);
    const int ring = std::max({std::abs(cx - qx), std::abs(cy - qy), std::abs(ct - qt)});
    if (ring >= lo && ring <= hi) hits.push_back({cell_of(g, c), i});
  }
  std::sort(hits.begin(), hits.end());
  std::vector<std::int32_t> ids;
  for (const auto& h : hits) ids.push_back(h.second);
  return ids;
}

}  // namespace

TEST_CASE("grid: cells per axis and the cell of a coordinate") {
  CHECK(grid_cells_per_axis(0.04) == 25);
  CHECK(grid_cells_per_axis(0.1) == 10);
  CHECK(grid_cells_per_axis(0.3) == 4);
  CHECK(grid_cells_per_axis(1.0) == 1);
  CHECK_THROWS(grid_cells_per_axis(0.0));
  CHECK_THROWS(grid_cells_per_axis(-0.1));
  CHECK_THROWS(grid_cells_per_axis(1.5));
  const float cell = 0.04f;
  CHECK(grid_axis_cell(0.0f, cell, 25) == 0);
  CHECK(grid_axis_cell(0.0399f, cell, 25) == 0);
  CHECK(grid_axis_cell(0.04f, cell, 25) == 1);  // a border belongs to the upper cell
  CHECK(grid_axis_cell(0.5f, cell, 25) == 12);
  CHECK(grid_axis_cell(1.0f, cell, 25) == 24);  // clamped into the last cell
  CHECK(grid_axis_cell(-0.3f, cell, 25) == 0);
  CHECK(grid_axis_cell(1.7f, cell, 25) == 24);
  CHECK(grid_axis_cell(1e30f, cell, 25) == 24);
  CHECK(grid_axis_cell(std::numeric_limits<float>::quiet_NaN(), cell, 25) == 0);
}

TEST_CASE("grid: the counting sort is a stable permutation with correct cell ranges") {
  std::mt19937 rng(7);
  const Params params;
  for (const int triangles : {0, 1, 5, 200, 3000}) {
    const GridWorld w = random_world(rng, 50, triangles, 4);
    const CollisionGrid g = build_collision_grid(w.topo, w.state, params);
    INFO(triangles);
    REQUIRE(g.n == 25);
    REQUIRE(g.cell_start.size() == std::size_t(25 * 25 * 25 + 1));
    CHECK(g.cell_start.front() == 0);
    CHECK(g.cell_start.back() == triangles);
    REQUIRE(g.slot_element.size() == std::size_t(triangles));
    std::vector<std::int32_t> seen = g.sorted_triangles;
    std::sort(seen.begin(), seen.end());
    for (int i = 0; i < triangles; ++i) CHECK(seen[i] == i);
    for (std::size_t c = 0; c + 1 < g.cell_start.size(); ++c) {
      REQUIRE(g.cell_start[c] <= g.cell_start[c + 1]);
      for (std::int32_t k = g.cell_start[c]; k < g.cell_start[c + 1]; ++k) {
        const std::int32_t tri = g.sorted_triangles[k];
        CHECK(g.triangle_cell[tri] == std::int32_t(c));
        CHECK(g.slot_element[k] == w.topo.env_element[tri]);
        CHECK(cell_of(g, envelope_centroid(w.topo, w.state, tri)) == std::int32_t(c));
        if (k > g.cell_start[c]) CHECK(g.sorted_triangles[k - 1] < tri);
      }
    }
  }
}

TEST_CASE("grid: near and far queries equal brute force on random worlds") {
  std::mt19937 rng(12345);
  for (const double cell : {0.04, 0.1, 0.3}) {
    Params params;
    params.forces.cell_size = cell;
    for (int world = 0; world < 4; ++world) {
      // Sparse worlds leave most cells empty; dense ones fill many.
      const GridWorld w = random_world(rng, 80, world % 2 == 0 ? 40 : 2000, 3);
      const CollisionGrid g = build_collision_grid(w.topo, w.state, params);
      std::vector<std::int32_t> near, far;
      for (int query = 0; query < 150; ++query) {
        const Vec3f q{special_or_random(rng), special_or_random(rng), special_or_random(rng)};
        const std::int32_t own = std::uniform_int_distribution<int>(0, 3)(rng);  // 3: owns nothing
        INFO("cell " << cell << " world " << world << " q " << q.x << ", " << q.y << ", " << q.t);
        near_triangles(g, q, own, near);
        far_triangles(g, q, own, far);
        CHECK(near == brute(w, g, q, own, 0, 1));
        CHECK(far == brute(w, g, q, own, 2, 2));
      }
    }
  }
}

TEST_CASE("grid: far runs split each cell into maximal runs of one element, with their mean centroid") {
  std::mt19937 rng(777);
  Params params;
  params.forces.far_cells = 1;
  for (int world = 0; world < 4; ++world) {
    // Few elements make long runs; many make runs of one triangle.
    const GridWorld w = random_world(rng, 80, world % 2 == 0 ? 300 : 2000, world < 2 ? 2 : 6);
    const CollisionGrid g = build_collision_grid(w.topo, w.state, params);
    REQUIRE(g.far_cells);
    REQUIRE(g.run_next.size() == g.sorted_triangles.size());
    std::int64_t covered = 0;
    for (std::int32_t c = 0; c + 1 < static_cast<std::int32_t>(g.cell_start.size()); ++c) {
      for (std::int32_t head = g.cell_start[c]; head < g.cell_start[c + 1];) {
        const std::int32_t next = g.run_next[head];
        INFO("world " << world << " cell " << c << " head " << head);
        REQUIRE(next > head);
        REQUIRE(next <= g.cell_start[c + 1]);
        const std::int32_t owner = w.topo.env_element[g.sorted_triangles[head]];
        double mx = 0.0, my = 0.0, mt = 0.0;
        for (std::int32_t k = head; k < next; ++k) {
          const std::int32_t tri = g.sorted_triangles[k];
          CHECK(w.topo.env_element[tri] == owner);
          if (k > head) CHECK(g.run_next[k] == 0);
          mx += g.cx[tri], my += g.cy[tri], mt += g.ct[tri];
        }
        // Maximal: the slot after the run, in the same cell, belongs to another element.
        if (next < g.cell_start[c + 1]) CHECK(w.topo.env_element[g.sorted_triangles[next]] != owner);
        const double n = next - head;
        CHECK(g.run_cx[head] == Approx(mx / n).margin(1e-6));
        CHECK(g.run_cy[head] == Approx(my / n).margin(1e-6));
        CHECK(g.run_ct[head] == Approx(mt / n).margin(1e-6));
        covered += next - head;
        head = next;
      }
    }
    CHECK(covered == static_cast<std::int64_t>(g.sorted_triangles.size()));
  }
}

TEST_CASE("grid: far slots are the far triangles' slots, or one run head per cell and element") {
  std::mt19937 rng(4242);
  for (const int cells_mode : {0, 1}) {
    Params params;
    params.forces.far_cells = cells_mode;
    const GridWorld w = random_world(rng, 80, 2000, 3);
    const CollisionGrid g = build_collision_grid(w.topo, w.state, params);
    std::vector<std::int32_t> far, slots;
    for (int query = 0; query < 100; ++query) {
      const Vec3f q{special_or_random(rng), special_or_random(rng), special_or_random(rng)};
      const std::int32_t own = std::uniform_int_distribution<int>(0, 3)(rng);
      INFO("mode " << cells_mode << " q " << q.x << ", " << q.y << ", " << q.t << " own " << own);
      far_triangles(g, q, own, far);
      repulsion_far_slots(g, q, own, slots);
      if (cells_mode == 0) {
        std::vector<std::int32_t> as_triangles;
        for (const std::int32_t k : slots) as_triangles.push_back(g.sorted_triangles[k]);
        CHECK(as_triangles == far);
      } else {
        // Expanding every run gives back the far triangles, in order.
        std::vector<std::int32_t> expanded;
        for (const std::int32_t k : slots)
          for (std::int32_t j = k; j < g.run_next[k]; ++j) expanded.push_back(g.sorted_triangles[j]);
        CHECK(expanded == far);
        CHECK(slots.size() <= far.size());
      }
    }
  }
}
