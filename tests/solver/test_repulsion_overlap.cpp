// Eq. 1 on one vertex and one triangle, and overlap detection (Eq. 3's trigger) with several elements.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "tiny_worlds.hpp"

using namespace animpak;
using namespace animpak::reference;
using animpak::test::WorldBuilder;

namespace {

// Vertex 0 (element 0) at (0.5, 0.5, 0.5); one envelope triangle (element 1) flat in t at `tri_t`,
// covering (0.5, 0.5) in x, y.
test::TinyWorld vertex_and_triangle(float tri_t) {
  WorldBuilder b;
  b.add_element({{{{0.5f, 0.5f}}, 0.5f}}, false);
  b.add_element({{{{0.48f, 0.48f}, {0.56f, 0.48f}, {0.48f, 0.56f}}, tri_t}}, false);
  test::TinyWorld w = b.build();
  w.topo.env_a = {1};
  w.topo.env_b = {2};
  w.topo.env_c = {3};
  w.topo.env_element = {1};
  return w;
}

struct Query {
  std::vector<std::int32_t> near, far;
};

Query query(const test::TinyWorld& w, const CollisionGrid& g, std::int32_t v) {
  Query q;
  const Vec3f p{w.state.x[v], w.state.y[v], w.state.t[v]};
  repulsion_near_slots(g, p, w.topo.element[v], q.near);
  repulsion_far_slots(g, p, w.topo.element[v], q.far);
  return q;
}

std::vector<float> times26() {
  std::vector<float> t;
  for (int k = 0; k <= 25; ++k) t.push_back(static_cast<float>(k) / 25.0f);
  return t;
}

// A diamond ring whose first vertex is (x, y), extending to +x.
test::Ring diamond(float x, float y, float r) { return {{x, y}, {x + r, y - r}, {x + 2 * r, y}, {x + r, y + r}}; }

}  // namespace

TEST_CASE("repulsion: Eq. 1 from the exact closest point of a near triangle") {
  const Params p = test::paper_params();
  const test::TinyWorld w = vertex_and_triangle(0.53125f);  // centroid one cell above in t
  const CollisionGrid g = build_collision_grid(w.topo, w.state, p);
  const Query q = query(w, g, 0);
  REQUIRE(q.near.size() == 1);
  REQUIRE(q.far.empty());
  const RepulsionResult r = repulsion_force(w.topo, w.state, step_params(p), g, 0, q.near, q.far, false);
  // u = x − (0.5, 0.5, 0.53125) = (0, 0, −0.03125): F = 10 · (0, 0, −1) / (1 + 0.03125²).
  CHECK(r.force.x == 0.0f);
  CHECK(r.force.y == 0.0f);
  CHECK(r.force.t == Approx(-10.0 / (1.0 + 0.0009765625)).epsilon(1e-6));
  CHECK(r.closest == 0.03125f);

  const RepulsionResult inside = repulsion_force(w.topo, w.state, step_params(p), g, 0, q.near, q.far, true);
  CHECK((inside.force.x == 0.0f && inside.force.y == 0.0f && inside.force.t == 0.0f));
  CHECK(inside.closest == 0.03125f);  // growth and the stop test still see the distance
}

TEST_CASE("repulsion: Eq. 1 from the centroid of a far triangle") {
  const Params p = test::paper_params();
  const test::TinyWorld w = vertex_and_triangle(0.59375f);  // centroid two cells above in t
  const CollisionGrid g = build_collision_grid(w.topo, w.state, p);
  const Query q = query(w, g, 0);
  REQUIRE(q.near.empty());
  REQUIRE(q.far.size() == 1);
  const RepulsionResult r = repulsion_force(w.topo, w.state, step_params(p), g, 0, q.near, q.far, false);
  const double ux = 0.5 - g.cx[0], uy = 0.5 - g.cy[0], ut = 0.5 - g.ct[0];
  const double d2 = ux * ux + uy * uy + ut * ut, s = 10.0 / std::sqrt(d2) / (1.0 + d2);
  CHECK(r.force.x == Approx(ux * s).epsilon(1e-5));
  CHECK(r.force.y == Approx(uy * s).epsilon(1e-5));
  CHECK(r.force.t == Approx(ut * s).epsilon(1e-5));
  CHECK(std::isinf(r.closest));  // far centroids are not closest points
}

TEST_CASE("repulsion: a far cell's triangles of one element act from their mean centroid, once per triangle") {
  // Vertex 0 (element 0) at (0.5, 0.5, 0.5); two triangles of element 1 two cells above in t, in one
  // cell, with centroids 0.012 apart in x.
  WorldBuilder b;
  b.add_element({{{{0.5f, 0.5f}}, 0.5f}}, false);
  b.add_element(
      {{{{0.482f, 0.482f}, {0.494f, 0.482f}, {0.482f, 0.494f}, {0.494f, 0.494f}, {0.506f, 0.482f}, {0.494f, 0.494f}},
        0.59375f}},
      false);
  test::TinyWorld w = b.build();
  w.topo.env_a = {1, 4};
  w.topo.env_b = {2, 5};
  w.topo.env_c = {3, 6};
  w.topo.env_element = {1, 1};
  Params p = test::paper_params();
  const auto term = [](double ux, double uy, double ut, double weight, double out[3]) {
    const double d2 = ux * ux + uy * uy + ut * ut, s = weight * 10.0 / std::sqrt(d2) / (1.0 + d2);
    out[0] += ux * s, out[1] += uy * s, out[2] += ut * s;
  };

  p.forces.far_cells = 0;  // the paper: each centroid
  const CollisionGrid each = build_collision_grid(w.topo, w.state, p);
  Query q = query(w, each, 0);
  REQUIRE(q.far.size() == 2);
  const RepulsionResult r0 = repulsion_force(w.topo, w.state, step_params(p), each, 0, q.near, q.far, false);
  double expected0[3] = {0, 0, 0};
  for (int tri = 0; tri < 2; ++tri) term(0.5 - each.cx[tri], 0.5 - each.cy[tri], 0.5 - each.ct[tri], 1.0, expected0);
  CHECK(r0.force.x == Approx(expected0[0]).epsilon(1e-5));
  CHECK(r0.force.t == Approx(expected0[2]).epsilon(1e-5));

  p.forces.far_cells = 1;  // one aggregate for the cell and element
  const CollisionGrid cells = build_collision_grid(w.topo, w.state, p);
  q = query(w, cells, 0);
  REQUIRE(q.far.size() == 1);
  const RepulsionResult r1 = repulsion_force(w.topo, w.state, step_params(p), cells, 0, q.near, q.far, false);
  const double mx = (cells.cx[0] + cells.cx[1]) / 2, my = (cells.cy[0] + cells.cy[1]) / 2,
               mt = (cells.ct[0] + cells.ct[1]) / 2;
  double expected1[3] = {0, 0, 0};
  term(0.5 - mx, 0.5 - my, 0.5 - mt, 2.0, expected1);
  CHECK(r1.force.x == Approx(expected1[0]).epsilon(1e-5));
  CHECK(r1.force.y == Approx(expected1[1]).epsilon(1e-5));
  CHECK(r1.force.t == Approx(expected1[2]).epsilon(1e-5));
  // The aggregate is an approximation of the two terms, not a different force.
  CHECK(r1.force.t == Approx(r0.force.t).epsilon(0.01));
  CHECK(r1.force.x != r0.force.x);
}

TEST_CASE("repulsion: near terms add into four partial sums by grid slot mod 4, then the far terms one by one") {
  // Vertex 0 (element 0) at (0.5, 0.5, 0.5); eleven small triangles of element 1 in its cell and the next
  // one in t (near slots), and one two cells above in t (a far slot), at uneven distances.
  test::Ring points;
  for (int i = 0; i < 11; ++i) {
    const float x = 0.482f + 0.0031f * static_cast<float>(i), y = 0.487f + 0.0017f * static_cast<float>(i % 5);
    points.insert(points.end(), {{x, y}, {x + 0.002f, y + 0.0007f}, {x + 0.0004f, y + 0.0023f}});
  }
  WorldBuilder b;
  b.add_element({{{{0.5f, 0.5f}}, 0.5f}}, false);
  b.add_element({{points, 0.511f}}, false);
  b.add_element({{{{0.49f, 0.49f}, {0.51f, 0.49f}, {0.49f, 0.51f}}, 0.59375f}}, false);
  test::TinyWorld w = b.build();
  for (std::int32_t tri = 0; tri < 12; ++tri) {
    w.topo.env_a.push_back(1 + 3 * tri);
    w.topo.env_b.push_back(2 + 3 * tri);
    w.topo.env_c.push_back(3 + 3 * tri);
    w.topo.env_element.push_back(tri < 11 ? 1 : 2);
  }
  const Params p;  // ε = 4e-6: terms of very different sizes, so the order shows in the last bits
  const CollisionGrid g = build_collision_grid(w.topo, w.state, p);
  const Query q = query(w, g, 0);
  REQUIRE(q.near.size() == 11);
  REQUIRE(q.far.size() == 1);
  const RepulsionResult r = repulsion_force(w.topo, w.state, step_params(p), g, 0, q.near, q.far, false);

  const auto pt = [&](std::int32_t i) { return Vec3f{w.state.x[i], w.state.y[i], w.state.t[i]}; };
  const float eps = static_cast<float>(p.forces.repulsion_epsilon);
  const auto add = [&](float ux, float uy, float ut, float count, float out[3]) {
    const float d2 = ux * ux + uy * uy + ut * ut;
    const float s = 1.0f / std::sqrt(d2) * (1.0f / (eps + d2)) * count;
    out[0] = out[0] + ux * s, out[1] = out[1] + uy * s, out[2] = out[2] + ut * s;
  };
  float part[4][3] = {}, plain[3] = {};
  for (const std::int32_t k : q.near) {
    const std::int32_t tri = g.sorted_triangles[k];
    const Vec3f c =
        closest_point_on_triangle(pt(0), pt(w.topo.env_a[tri]), pt(w.topo.env_b[tri]), pt(w.topo.env_c[tri]));
    add(0.5f - c.x, 0.5f - c.y, 0.5f - c.t, 1.0f, part[k & 3]);
    add(0.5f - c.x, 0.5f - c.y, 0.5f - c.t, 1.0f, plain);
  }
  float expected[3];
  for (int a = 0; a < 3; ++a) expected[a] = (part[0][a] + part[1][a]) + (part[2][a] + part[3][a]);
  const std::int32_t k = q.far[0];
  const float count = static_cast<float>(g.run_next[k] - k);
  add(0.5f - g.run_cx[k], 0.5f - g.run_cy[k], 0.5f - g.run_ct[k], count, expected);
  add(0.5f - g.run_cx[k], 0.5f - g.run_cy[k], 0.5f - g.run_ct[k], count, plain);
  const float kr = static_cast<float>(p.forces.k_repulsion);
  CHECK(r.force.x == kr * expected[0]);
  CHECK(r.force.y == kr * expected[1]);
  CHECK(r.force.t == kr * expected[2]);
  // One running sum in slot order would round differently here, so this pins the order itself.
  CHECK((kr * plain[0] != r.force.x || kr * plain[1] != r.force.y || kr * plain[2] != r.force.t));
}

TEST_CASE("repulsion: interior vertices get none") {
  const Params p = test::paper_params();
  test::TinyWorld w = vertex_and_triangle(0.53125f);
  w.topo.flags[0] = 0;
  const CollisionGrid g = build_collision_grid(w.topo, w.state, p);
  const Query q = query(w, g, 0);
  const RepulsionResult r = repulsion_force(w.topo, w.state, step_params(p), g, 0, q.near, q.far, false);
  CHECK((r.force.x == 0.0f && r.force.y == 0.0f && r.force.t == 0.0f));
  CHECK(std::isinf(r.closest));
}

namespace {

// A square of half-size h at y 0.5 with two slices: at x0 at t 0, at x1 at t 1.
std::vector<test::TinySlice> moving_square(float x0, float x1, float h) {
  return {{test::square(x0, 0.5f, h), 0.0f}, {test::square(x1, 0.5f, h), 1.0f}};
}

OverlapResult overlap_at(const test::TinyWorld& w, std::int32_t v,
                         std::int32_t interval_points = Params{}.forces.interval_points) {
  const CurveTangents m = test::tangents(w);
  SliceBoxes boxes;
  slice_boxes(w.topo, w.state, m, boxes);
  OverlapGrid grid;
  build_overlap_grid(w.topo, boxes, grid);
  return overlap_test(w.topo, w.state, boxes, grid, m, v, interval_points);
}

// Two thin bars crossing like a plus sign over 26 slices: element 0 horizontal, element 1 vertical.
test::TinyWorld crossing_bars() {
  const auto times = times26();
  const auto bar = [&](float w, float h) {
    std::vector<test::TinySlice> slices;
    for (const float t : times)
      slices.push_back({{{0.5f - w, 0.5f - h}, {0.5f + w, 0.5f - h}, {0.5f + w, 0.5f + h}, {0.5f - w, 0.5f + h}}, t});
    return slices;
  };
  WorldBuilder b;
  b.add_element(bar(0.1f, 0.01f));
  b.add_element(bar(0.01f, 0.1f));
  return b.build();
}

}  // namespace

TEST_CASE("overlap: found inside a second element even when a third element's triangle is nearer") {
  const Params p = test::paper_params();
  WorldBuilder b;
  const auto times = times26();
  b.add_element(test::square_tube(0.49f, 0.5f, 0.01f, times));    // A: vertex 12·4 + 1 is (0.5, 0.49)
  b.add_element(test::square_tube(0.5f, 0.5f, 0.03f, times));     // B: contains it, boundary 0.02 away
  b.add_element(test::square_tube(0.525f, 0.49f, 0.01f, times));  // C: outside, 0.015 away
  const test::TinyWorld w = b.build();
  const std::int32_t v = 12 * 4 + 1;
  REQUIRE(w.state.x[v] == 0.5f);
  REQUIRE(w.state.y[v] == 0.49f);
  const CollisionGrid g = build_collision_grid(w.topo, w.state, p);
  const Query q = query(w, g, v);

  // The nearest closest point belongs to C, so a nearest-element-only test would miss B.
  float best = 1e9f;
  std::int32_t best_element = -1;
  for (const std::int32_t k : q.near) {
    const std::int32_t tri = g.sorted_triangles[k];
    const auto pt = [&](std::int32_t i) { return Vec3f{w.state.x[i], w.state.y[i], w.state.t[i]}; };
    const Vec3f c =
        closest_point_on_triangle(pt(v), pt(w.topo.env_a[tri]), pt(w.topo.env_b[tri]), pt(w.topo.env_c[tri]));
    const float d = std::hypot(c.x - 0.5f, c.y - 0.49f, c.t - w.state.t[v]);
    if (d < best) best = d, best_element = w.topo.env_element[tri];
  }
  REQUIRE(best_element == 2);
  const OverlapResult r = overlap_at(w, v);
  CHECK(r.overlap);
  CHECK(r.inside);
  // The way out is B's nearest edge, y = 0.47, straight up from the vertex.
  CHECK(r.out_x == 0.0f);
  CHECK(r.out_y == 0.47f - 0.49f);

  WorldBuilder without_b;
  without_b.add_element(test::square_tube(0.49f, 0.5f, 0.01f, times));
  without_b.add_element(test::square_tube(0.525f, 0.49f, 0.01f, times));
  const test::TinyWorld w2 = without_b.build();
  CHECK_FALSE(overlap_at(w2, v).overlap);
}

TEST_CASE("overlap: a vertex two cells deep inside another element stays flagged") {
  // The paper's test looks for the other element's envelope in the 3×3×3 block of cells around the
  // vertex (cells of 0.04). Here the vertex sits at the centre of a large square, 0.1 (2.5 cells) from
  // its outline, where the block finds no envelope triangle of it at all.
  const Params p = test::paper_params();
  const auto times = times26();
  WorldBuilder b;
  b.add_element(test::square_tube(0.5f, 0.5f, 0.005f, times));  // A: tiny, at the centre
  b.add_element(test::square_tube(0.5f, 0.5f, 0.1f, times));    // B: around it
  const test::TinyWorld w = b.build();
  const std::int32_t v = 12 * 4;
  const CollisionGrid g = build_collision_grid(w.topo, w.state, p);
  const Query q = query(w, g, v);
  REQUIRE(std::none_of(q.near.begin(), q.near.end(), [&](std::int32_t tri) { return w.topo.env_element[tri] == 1; }));
  const OverlapResult r = overlap_at(w, v);
  CHECK(r.overlap);
  CHECK(r.inside);
  // The depth term of the overlap force grows with depth: it points to B's outline, 0.095 away.
  const Vec3f f = overlap_force(w.topo, w.state, step_params(p), v, r);
  const Vec3f eq3 = overlap_force(w.topo, w.state, step_params(p), v, OverlapResult{true, false});
  CHECK(std::hypot(f.x - eq3.x, f.y - eq3.y) == Approx(p.forces.k_overlap_depth * 0.095).epsilon(1e-4));
}

TEST_CASE("overlap: two elements whose edges cross with no vertex inside are both flagged") {
  // Two thin bars crossing like a plus sign: no corner of either lies inside the other, but a long
  // edge of each crosses the other's outline twice.
  const test::TinyWorld w = crossing_bars();
  int inside = 0, flagged = 0;
  for (std::int32_t v = 0; v < w.topo.vertex_count(); ++v) {
    const OverlapResult r = overlap_at(w, v);
    inside += r.inside;
    flagged += r.overlap;
  }
  CHECK(inside == 0);
  // Per slice, the horizontal bar's two long edges start at its corners 0 (top, going +x) and 2
  // (bottom, going −x); so for the vertical bar (corners 1 and 3).
  for (int s = 0; s < 26; ++s)
    for (const int e : {0, 1}) {
      const std::int32_t base = (e * 26 + s) * 4;
      CHECK(overlap_at(w, base + (e == 0 ? 0 : 1)).overlap);
      CHECK(overlap_at(w, base + (e == 0 ? 2 : 3)).overlap);
    }
  CHECK(flagged == 2 * 2 * 26);
}

TEST_CASE("overlap: the larger of two overlapping elements yields, the smaller does not") {
  // The crossing bars again, the horizontal one grown larger (g 2 against 1.5) in every slice: its
  // flagged vertices must give way (yield), the vertical bar's only pause. Equal g: both yield.
  test::TinyWorld w = crossing_bars();
  for (int s = 0; s < 26; ++s) w.state.growth[s] = 2.0f, w.state.growth[26 + s] = 1.5f;
  int larger = 0, smaller = 0;
  for (std::int32_t v = 0; v < w.topo.vertex_count(); ++v) {
    const OverlapResult r = overlap_at(w, v);
    if (!r.overlap) continue;
    CHECK(r.yield == (w.topo.element[v] == 0));
    (w.topo.element[v] == 0 ? larger : smaller) += 1;
  }
  CHECK(larger == 2 * 26);
  CHECK(smaller == 2 * 26);
  for (int s = 0; s < 26; ++s) w.state.growth[26 + s] = 2.0f;
  for (std::int32_t v = 0; v < w.topo.vertex_count(); ++v) {
    const OverlapResult r = overlap_at(w, v);
    CHECK(r.yield == r.overlap);
  }
}

TEST_CASE("overlap: a secondary element gives way to a primary one whatever their sizes") {
  // The crossing bars, the vertical one secondary (docs/parameters.md, "Secondary elements"): its
  // flagged vertices block and yield even when it is the smaller; the primary bar's are flagged as
  // overlapping (for the forces and the statistics) but neither block nor yield, even when it is the larger.
  test::TinyWorld w = crossing_bars();
  w.topo.element_secondary = {0, 1};
  for (const float secondary_g : {1.5f, 3.0f}) {
    for (int s = 0; s < 26; ++s) w.state.growth[s] = 2.0f, w.state.growth[26 + s] = secondary_g;
    int primary = 0, secondary = 0;
    for (std::int32_t v = 0; v < w.topo.vertex_count(); ++v) {
      const OverlapResult r = overlap_at(w, v);
      if (!r.overlap) continue;
      const bool is_secondary = w.topo.element[v] == 1;
      INFO("vertex " << v << ", secondary g " << secondary_g);
      CHECK(r.block == is_secondary);
      CHECK(r.yield == is_secondary);
      (is_secondary ? secondary : primary) += 1;
    }
    CHECK(primary == 2 * 26);
    CHECK(secondary == 2 * 26);
  }
  // Both secondary: the rule between equals again (the larger yields, both block).
  w.topo.element_secondary = {1, 1};
  for (int s = 0; s < 26; ++s) w.state.growth[s] = 2.0f, w.state.growth[26 + s] = 1.5f;
  for (std::int32_t v = 0; v < w.topo.vertex_count(); ++v) {
    const OverlapResult r = overlap_at(w, v);
    CHECK(r.block == r.overlap);
    CHECK(r.yield == (r.overlap && w.topo.element[v] == 0));
  }
}

TEST_CASE("overlap: elements that cross only between two slices are found at the middle of the interval") {
  // A (half-size 0.04) moves right and B (0.05) left through the same place: at the slice times 0 and 1
  // they are 0.11 apart, at t = 0.5 A lies inside B. Only the middle of the slice interval sees it.
  WorldBuilder b;
  b.add_element(moving_square(0.4f, 0.6f, 0.04f));
  b.add_element(moving_square(0.6f, 0.4f, 0.05f));
  const test::TinyWorld w = b.build();
  for (std::int32_t v = 0; v < 8; ++v) {
    INFO("vertex " << v);
    const OverlapResult r = overlap_at(w, v);
    CHECK(r.inside);
    // The middle of A's corner lies 0.01 inside B's outline.
    CHECK(std::hypot(r.out_x, r.out_y) == Approx(0.01).epsilon(1e-3));
  }
  for (std::int32_t v = 8; v < 16; ++v) CHECK_FALSE(overlap_at(w, v).inside);

  // The same two squares without the motion never meet.
  WorldBuilder still;
  still.add_element(moving_square(0.4f, 0.4f, 0.04f));
  still.add_element(moving_square(0.6f, 0.6f, 0.05f));
  const test::TinyWorld s = still.build();
  for (std::int32_t v = 0; v < s.topo.vertex_count(); ++v) CHECK_FALSE(overlap_at(s, v).overlap);
}

TEST_CASE(
    "overlap: a pass between the middle and a slice is found at the quarter point, which the middle alone misses") {
  // A (half-size 0.04) moves from x 0.4 to 0.6, B (0.05) from 0.8 to 0.5: their centres are
  // 0.4 - 0.5 t apart, so they overlap only for 0.62 < t < 0.98. The slices (t 0 and 1) and the
  // middle (0.5) are clear; the quarter point 0.75 is 0.065 deep in the pass. The default packs showed
  // such a pass (two star tips, 0.3 % of the smaller) in frames between a middle and a slice.
  WorldBuilder b;
  b.add_element(moving_square(0.4f, 0.6f, 0.04f));
  b.add_element(moving_square(0.8f, 0.5f, 0.05f));
  const test::TinyWorld w = b.build();
  REQUIRE(Params{}.forces.interval_points >= 3);  // the default tests at least the quarter points
  // Quarter points: the vertices at t = 1 test 0.75 (and 0.5), those at t = 0 test 0.25 and 0.5. At
  // 0.75 A spans x 0.51-0.59 and B 0.525-0.625 (y 0.46-0.54 and 0.45-0.55): A's right corners (5, 6) lie
  // inside B, the edges from 4 and 6 cross B's left edge, and B's left edge (from 15) crosses A's.
  const std::vector<std::int32_t> found{4, 5, 6, 15};
  for (std::int32_t v = 0; v < w.topo.vertex_count(); ++v) {
    INFO("vertex " << v);
    CHECK_FALSE(overlap_at(w, v, 1).overlap);  // the middle only
    CHECK(overlap_at(w, v, 3).overlap == (std::find(found.begin(), found.end(), v) != found.end()));
  }
  // A's corner (0.59, 0.46) at t = 0.75 lies 0.01 inside B's bottom edge: the way out.
  const OverlapResult r = overlap_at(w, 5, 3);
  CHECK(r.inside);
  CHECK(std::hypot(r.out_x, r.out_y) == Approx(0.01).epsilon(1e-3));
}

TEST_CASE("overlap: the other element's boundary is interpolated linearly between its slices") {
  const auto times = times26();
  // B grows with t: half-size h(t) = 0.02 + 0.08 t on each slice. The query sits 0.05 right of B's
  // centre, so it is inside exactly when h(t) > 0.05, i.e. t > 0.375 — between slices 0.36 and 0.40.
  std::vector<test::TinySlice> grow;
  for (const float t : times) grow.push_back({test::square(0.5f, 0.5f, 0.02f + 0.08f * t), t});
  for (const auto& [t, inside] : {std::pair{0.365f, false}, {0.385f, true}, {0.48f, true}, {0.24f, false}}) {
    INFO("t = " << t);
    WorldBuilder b;
    b.add_element({{diamond(0.55f, 0.5f, 0.02f), t}}, false);
    b.add_element(grow);
    const test::TinyWorld w = b.build();
    CHECK(overlap_at(w, 0).inside == inside);
  }
}

TEST_CASE("overlap: never inside one's own element, and interior vertices are not tested") {
  const Params p = test::paper_params();
  WorldBuilder b;
  b.add_element(test::square_tube(0.5f, 0.5f, 0.06f, times26()));
  test::TinyWorld w = b.build();
  const CollisionGrid g = build_collision_grid(w.topo, w.state, p);
  const std::int32_t v = 12 * 4;
  CHECK_FALSE(overlap_at(w, v).overlap);
  CHECK(query(w, g, v).near.empty());
  // The same vertex without its boundary flag, inside a second element, is not tested.
  b.add_element(test::square_tube(0.5f, 0.5f, 0.2f, times26()));
  w = b.build();
  REQUIRE(overlap_at(w, v).inside);
  w.topo.flags[v] &= static_cast<std::uint8_t>(~vertex_boundary);
  CHECK_FALSE(overlap_at(w, v).overlap);
}
