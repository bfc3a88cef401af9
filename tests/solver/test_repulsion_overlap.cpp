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
test::World vertex_and_triangle(float tri_t) {
  WorldBuilder b;
  b.add_element({{{{0.5f, 0.5f}}, 0.5f}}, false);
  b.add_element({{{{0.48f, 0.48f}, {0.56f, 0.48f}, {0.48f, 0.56f}}, tri_t}}, false);
  test::World w = b.build();
  w.topo.env_a = {1};
  w.topo.env_b = {2};
  w.topo.env_c = {3};
  w.topo.env_element = {1};
  return w;
}

struct Query {
  std::vector<std::int32_t> near, far;
};

Query query(const test::World& w, const CollisionGrid& g, std::int32_t v) {
  Query q;
  const Vec3f p{w.state.x[v], w.state.y[v], w.state.t[v]};
  near_triangles(g, w.topo, p, w.topo.element[v], q.near);
  far_triangles(g, w.topo, p, w.topo.element[v], q.far);
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
  const test::World w = vertex_and_triangle(0.53125f);  // centroid one cell above in t
  const CollisionGrid g = build_collision_grid(w.topo, w.state, p);
  const Query q = query(w, g, 0);
  REQUIRE(q.near.size() == 1);
  REQUIRE(q.far.empty());
  const RepulsionResult r = repulsion_force(w.topo, w.state, p, g, 0, q.near, q.far, false);
  // u = x − (0.5, 0.5, 0.53125) = (0, 0, −0.03125): F = 10 · (0, 0, −1) / (1 + 0.03125²).
  CHECK(r.force.x == 0.0f);
  CHECK(r.force.y == 0.0f);
  CHECK(r.force.t == Approx(-10.0 / (1.0 + 0.0009765625)).epsilon(1e-6));
  CHECK(r.closest == 0.03125f);

  const RepulsionResult inside = repulsion_force(w.topo, w.state, p, g, 0, q.near, q.far, true);
  CHECK((inside.force.x == 0.0f && inside.force.y == 0.0f && inside.force.t == 0.0f));
  CHECK(inside.closest == 0.03125f);  // growth and the stop test still see the distance
}

TEST_CASE("repulsion: Eq. 1 from the centroid of a far triangle") {
  const Params p = test::paper_params();
  const test::World w = vertex_and_triangle(0.59375f);  // centroid two cells above in t
  const CollisionGrid g = build_collision_grid(w.topo, w.state, p);
  const Query q = query(w, g, 0);
  REQUIRE(q.near.empty());
  REQUIRE(q.far.size() == 1);
  const RepulsionResult r = repulsion_force(w.topo, w.state, p, g, 0, q.near, q.far, false);
  const double ux = 0.5 - g.cx[0], uy = 0.5 - g.cy[0], ut = 0.5 - g.ct[0];
  const double d2 = ux * ux + uy * uy + ut * ut, s = 10.0 / std::sqrt(d2) / (1.0 + d2);
  CHECK(r.force.x == Approx(ux * s).epsilon(1e-5));
  CHECK(r.force.y == Approx(uy * s).epsilon(1e-5));
  CHECK(r.force.t == Approx(ut * s).epsilon(1e-5));
  CHECK(std::isinf(r.closest));  // far centroids are not closest points
}

TEST_CASE("repulsion: interior vertices get none") {
  const Params p = test::paper_params();
  test::World w = vertex_and_triangle(0.53125f);
  w.topo.flags[0] = 0;
  const CollisionGrid g = build_collision_grid(w.topo, w.state, p);
  const Query q = query(w, g, 0);
  const RepulsionResult r = repulsion_force(w.topo, w.state, p, g, 0, q.near, q.far, false);
  CHECK((r.force.x == 0.0f && r.force.y == 0.0f && r.force.t == 0.0f));
  CHECK(std::isinf(r.closest));
}

TEST_CASE("overlap: found inside a second element even when a third element's triangle is nearer") {
  const Params p = test::paper_params();
  WorldBuilder b;
  const auto times = times26();
  b.add_element(test::square_tube(0.49f, 0.5f, 0.01f, times));  // A: vertex 12·4 + 1 is (0.5, 0.49)
  b.add_element(test::square_tube(0.5f, 0.5f, 0.03f, times));     // B: contains it, boundary 0.02 away
  b.add_element(test::square_tube(0.525f, 0.49f, 0.01f, times));  // C: outside, 0.015 away
  const test::World w = b.build();
  const std::int32_t v = 12 * 4 + 1;
  REQUIRE(w.state.x[v] == 0.5f);
  REQUIRE(w.state.y[v] == 0.49f);
  const CollisionGrid g = build_collision_grid(w.topo, w.state, p);
  const Query q = query(w, g, v);

  // The nearest closest point belongs to C, so a nearest-element-only test would miss B.
  float best = 1e9f;
  std::int32_t best_element = -1;
  for (const std::int32_t tri : q.near) {
    const auto pt = [&](std::int32_t i) { return Vec3f{w.state.x[i], w.state.y[i], w.state.t[i]}; };
    const Vec3f c = closest_point_on_triangle(pt(v), pt(w.topo.env_a[tri]), pt(w.topo.env_b[tri]), pt(w.topo.env_c[tri]));
    const float d = std::hypot(c.x - 0.5f, c.y - 0.49f, c.t - w.state.t[v]);
    if (d < best) best = d, best_element = w.topo.env_element[tri];
  }
  REQUIRE(best_element == 2);
  REQUIRE(std::any_of(q.near.begin(), q.near.end(), [&](std::int32_t tri) { return w.topo.env_element[tri] == 1; }));
  CHECK(inside_other_element(w.topo, w.state, v, q.near));

  WorldBuilder without_b;
  without_b.add_element(test::square_tube(0.49f, 0.5f, 0.01f, times));
  without_b.add_element(test::square_tube(0.525f, 0.49f, 0.01f, times));
  const test::World w2 = without_b.build();
  const CollisionGrid g2 = build_collision_grid(w2.topo, w2.state, p);
  CHECK_FALSE(inside_other_element(w2.topo, w2.state, v, query(w2, g2, v).near));
}

TEST_CASE("overlap: the other element's boundary is interpolated linearly between its slices") {
  const Params p = test::paper_params();
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
    const test::World w = b.build();
    const CollisionGrid g = build_collision_grid(w.topo, w.state, p);
    const Query q = query(w, g, 0);
    REQUIRE(!q.near.empty());
    CHECK(inside_other_element(w.topo, w.state, 0, q.near) == inside);
  }
}

TEST_CASE("overlap: never inside one's own element, and interior vertices are not tested") {
  const Params p = test::paper_params();
  WorldBuilder b;
  b.add_element(test::square_tube(0.5f, 0.5f, 0.06f, times26()));
  test::World w = b.build();
  const CollisionGrid g = build_collision_grid(w.topo, w.state, p);
  const std::int32_t v = 12 * 4;
  std::vector<std::int32_t> all(w.topo.envelope_count());
  for (std::int32_t i = 0; i < w.topo.envelope_count(); ++i) all[i] = i;
  CHECK_FALSE(inside_other_element(w.topo, w.state, v, all));
  CHECK(query(w, g, v).near.empty());
}
