// The overlap test's broadphase (OverlapGrid, docs/architecture.md "The overlap test"): it
// must list every element whose slice pair around a query's t passes the box test, in increasing order
// and each once, so that the overlap test gives the same bits as a walk over every element.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <random>

#include "tiny_worlds.hpp"

using namespace animpak;
using namespace animpak::reference;
using animpak::test::WorldBuilder;

namespace {

// `elements` rings of 6 vertices, `slices` slices each at jittered times (sometimes out of order, so
// the pair walk meets flat and reversed pairs), radii in [r0, r1], spread over [0, 1]².
test::TinyWorld spread_world(std::uint32_t seed, int elements, int slices, float r0, float r1) {
  std::mt19937 rng(seed);
  auto uniform = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); };
  WorldBuilder b;
  for (int e = 0; e < elements; ++e) {
    const float cx = uniform(0.0f, 1.0f), cy = uniform(0.0f, 1.0f), r = uniform(r0, r1);
    std::vector<test::TinySlice> ring_slices;
    for (int s = 0; s < slices; ++s) {
      test::TinySlice sl;
      sl.t = std::min(1.0f, std::max(0.0f, float(s) / float(slices - 1) + uniform(-0.12f, 0.12f)));
      const float dx = uniform(-0.05f, 0.05f), dy = uniform(-0.05f, 0.05f);
      for (int k = 0; k < 6; ++k) {
        const float a = 6.2831853f * (float(k) + uniform(-0.2f, 0.2f)) / 6.0f, rr = r * uniform(0.6f, 1.2f);
        sl.ring.push_back({cx + dx + rr * std::cos(a), cy + dy + rr * std::sin(a)});
      }
      ring_slices.push_back(sl);
    }
    b.add_element(ring_slices);
  }
  return b.build();
}

// The box test of overlap_point, written out: e's pair around pt (walked from slice index `start`)
// holds pt in its t range and its two slices' boxes meet the query's box.
bool box_test_accepts(const test::TinyWorld& w, const SliceBoxes& boxes, std::int32_t e, std::int32_t start, float px,
                      float py, float pt, float nx, float ny) {
  const Topology& topo = w.topo;
  const std::int32_t first = topo.element_slice_begin[e], count = topo.element_slice_begin[e + 1] - first;
  if (count < 2) return false;
  auto t_of = [&](std::int32_t s) { return w.state.t[topo.slice_begin[s]]; };
  std::int32_t k = std::min(start, count - 2);
  while (k > 0 && pt < t_of(first + k)) --k;
  while (k < count - 2 && pt > t_of(first + k + 1)) ++k;
  const std::int32_t s = first + k;
  if (!(std::min(t_of(s), t_of(s + 1)) <= pt && pt <= std::max(t_of(s), t_of(s + 1)))) return false;
  const float bx0 = std::min(boxes.x0[s], boxes.x0[s + 1]), bx1 = std::max(boxes.x1[s], boxes.x1[s + 1]);
  const float by0 = std::min(boxes.y0[s], boxes.y0[s + 1]), by1 = std::max(boxes.y1[s], boxes.y1[s + 1]);
  return !(std::max(px, nx) < bx0 || std::min(px, nx) > bx1 || std::max(py, ny) < by0 || std::min(py, ny) > by1);
}

struct Tally {
  long accepted = 0, candidates = 0, queries = 0;
};

// One query against the brute-force box test: every accepted element is a candidate, and the
// candidates increase strictly.
void check_query(const test::TinyWorld& w, const SliceBoxes& boxes, const OverlapGrid& grid, std::int32_t start,
                 float px, float py, float pt, float nx, float ny, Tally& tally) {
  std::vector<std::int32_t> found;
  overlap_candidates(grid, w.topo.element_count(), std::min(px, nx), std::max(px, nx), std::min(py, ny),
                     std::max(py, ny), pt, found);
  INFO("query (" << px << ", " << py << ", " << pt << ") to (" << nx << ", " << ny << "), start " << start);
  REQUIRE(std::adjacent_find(found.begin(), found.end(), [](std::int32_t a, std::int32_t b) { return a >= b; }) ==
          found.end());
  for (std::int32_t e = 0; e < w.topo.element_count(); ++e) {
    if (!box_test_accepts(w, boxes, e, start, px, py, pt, nx, ny)) continue;
    INFO("element " << e << " passes the box test");
    REQUIRE(std::binary_search(found.begin(), found.end(), e));
    ++tally.accepted;
  }
  tally.candidates += static_cast<long>(found.size());
  ++tally.queries;
}

}  // namespace

TEST_CASE("overlap broadphase: every element the box test accepts is a candidate, in increasing order") {
  Tally tally;
  for (std::uint32_t seed = 1; seed <= 4; ++seed) {
    const test::TinyWorld w = spread_world(seed, 120, 5, 0.01f, 0.06f);
    SliceBoxes boxes;
    slice_boxes(w.topo, w.state, test::tangents(w), boxes);
    OverlapGrid grid;
    build_overlap_grid(w.topo, boxes, grid);
    REQUIRE(grid.nx > 0);
    std::mt19937 rng(seed);
    auto uniform = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); };
    // Random points with short edges, anywhere (also outside the grid, in every direction).
    for (int q = 0; q < 2000; ++q) {
      const float px = uniform(-0.1f, 1.1f), py = uniform(-0.1f, 1.1f), pt = uniform(-0.05f, 1.05f);
      check_query(w, boxes, grid, q % 5, px, py, pt, px + uniform(-0.03f, 0.03f), py + uniform(-0.03f, 0.03f), tally);
    }
    // Queries exactly on a pair's box edges and t ends, where the box test accepts with equality, and
    // on cell borders (multiples of the cell from the grid's corner).
    for (std::int32_t s = 0; s + 1 < w.topo.slice_count(); ++s) {
      if (w.topo.slice_element[s] != w.topo.slice_element[s + 1]) continue;
      const float bx0 = std::min(boxes.x0[s], boxes.x0[s + 1]), bx1 = std::max(boxes.x1[s], boxes.x1[s + 1]);
      const float by0 = std::min(boxes.y0[s], boxes.y0[s + 1]), by1 = std::max(boxes.y1[s], boxes.y1[s + 1]);
      const std::int32_t start = s - w.topo.element_slice_begin[w.topo.slice_element[s]];
      for (const float pt : {boxes.t[s], boxes.t[s + 1]}) {
        check_query(w, boxes, grid, start, bx1, by1, pt, bx1 + 0.02f, by1 + 0.01f, tally);  // edge from the corner
        check_query(w, boxes, grid, start, bx0 - 0.02f, by0 - 0.02f, pt, bx0, by0, tally);  // edge to the corner
        check_query(w, boxes, grid, start, bx0, by1, pt, bx0, by1, tally);                  // a point
      }
      const float cx = grid.x0 + grid.cell * std::ceil((bx0 - grid.x0) / grid.cell);
      const float cy = grid.y0 + grid.cell * std::ceil((by0 - grid.y0) / grid.cell);
      check_query(w, boxes, grid, start, cx, cy, boxes.t[s], cx - 0.001f, cy - 0.001f, tally);
    }
  }
  CHECK(tally.accepted > 1000);
  // The point of the broadphase: most elements are never tried.
  CHECK(tally.candidates < tally.queries * 120 / 10);
}

TEST_CASE("overlap broadphase: the overlap test gives the same bits as a walk over every element") {
  long overlapping = 0, inside = 0;
  for (std::uint32_t seed = 5; seed <= 8; ++seed) {
    const test::TinyWorld w = spread_world(seed, 80, 6, 0.03f, 0.09f);
    SliceBoxes boxes;
    slice_boxes(w.topo, w.state, test::tangents(w), boxes);
    OverlapGrid grid;
    build_overlap_grid(w.topo, boxes, grid);
    const OverlapGrid every;  // no cells: every query tries every element
    const CurveTangents m = test::tangents(w);
    for (std::int32_t v = 0; v < w.topo.vertex_count(); ++v) {
      const OverlapResult a = overlap_test(w.topo, w.state, boxes, grid, m, v, Params{}.forces.interval_points);
      const OverlapResult b = overlap_test(w.topo, w.state, boxes, every, m, v, Params{}.forces.interval_points);
      INFO("seed " << seed << ", vertex " << v);
      CHECK(a.overlap == b.overlap);
      CHECK(a.inside == b.inside);
      CHECK(std::bit_cast<std::uint32_t>(a.out_x) == std::bit_cast<std::uint32_t>(b.out_x));
      CHECK(std::bit_cast<std::uint32_t>(a.out_y) == std::bit_cast<std::uint32_t>(b.out_y));
      overlapping += b.overlap;
      inside += b.inside;
    }
  }
  CHECK(overlapping > 100);
  CHECK(inside > 100);
}

TEST_CASE("overlap broadphase: a NaN box leaves the grid without cells") {
  test::TinyWorld w = spread_world(9, 10, 3, 0.02f, 0.05f);
  w.state.x[6] = std::numeric_limits<float>::quiet_NaN();  // the first vertex of slice 1: its box
  SliceBoxes boxes;
  slice_boxes(w.topo, w.state, test::tangents(w), boxes);
  OverlapGrid grid;
  build_overlap_grid(w.topo, boxes, grid);
  CHECK(grid.nx == 0);
  std::vector<std::int32_t> found;
  overlap_candidates(grid, w.topo.element_count(), 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, found);
  CHECK(found.size() == 10u);
}
