// Eq. 7 assembled per vertex: the total is the documented left-to-right sum of the components, each
// component is what its own function gives, and the overlap test switches repulsion for overlap.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "animpak/compare.hpp"
#include "tiny_worlds.hpp"

using namespace animpak;
using namespace animpak::reference;
using animpak::test::WorldBuilder;

namespace {

std::vector<float> step_times26() {
  std::vector<float> t;
  for (int k = 0; k <= 25; ++k) t.push_back(static_cast<float>(k) / 25.0f);
  return t;
}

// Element 0 spans x, y in [0.35, 0.45] × [0.45, 0.55]; element 1 is a square of half-size h1 about
// (x1, 0.5). Positions are jittered by up to 0.004; element 0 has a target point.
test::TinyWorld two_tubes(float x1, float h1, std::uint32_t seed) {
  WorldBuilder b;
  b.add_element(test::square_tube(0.4f, 0.5f, 0.05f, step_times26()));
  b.add_element(test::square_tube(x1, 0.5f, h1, step_times26()));
  b.add_target(13 * 4 + 2, 0.45f, 0.55f, 0.5f);
  test::TinyWorld w = b.build();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> jitter(-0.004f, 0.004f);
  for (std::int32_t v = 0; v < w.topo.vertex_count(); ++v) {
    w.state.x[v] += jitter(rng);
    w.state.y[v] += jitter(rng);
    w.state.t[v] += jitter(rng);
  }
  return w;
}

bool same(Vec3f a, Vec3f b) { return a.x == b.x && a.y == b.y && a.t == b.t; }

}  // namespace

TEST_CASE("step_forces: the total is Eq. 7 summed in order, each part from its own function") {
  const Params p = test::paper_params();
  const test::TinyWorld w = two_tubes(0.52f, 0.05f, 5);  // 0.02 apart
  const CollisionGrid g = build_collision_grid(w.topo, w.state, p);
  ForceBreakdown parts;
  const StepForces f = step_forces(w.topo, w.state, step_params(p), g, &parts);
  const StepForces again = step_forces(w.topo, w.state, step_params(p), g, nullptr);
  std::vector<float> cx, cy;
  slice_centroids(w.topo, w.state, cx, cy);
  std::vector<std::int32_t> near, far;
  int with_neighbour = 0;
  for (std::int32_t v = 0; v < w.topo.vertex_count(); ++v) {
    INFO("vertex " << v);
    const Vec3f r = parts.repulsion.at(v), e = parts.springs.at(v), tg = parts.target.at(v), b = parts.boundary.at(v),
                o = parts.overlap.at(v), to = parts.torsion.at(v);
    // Eq. 7 left to right over breakdown_forces, the order of AP_FORCE_TERMS.
    Vec3f sum = (parts.*breakdown_forces[0].field).at(v);
    for (std::size_t c = 1; c < breakdown_forces.size(); ++c) {
      const Vec3f part = (parts.*breakdown_forces[c].field).at(v);
      sum = {sum.x + part.x, sum.y + part.y, sum.t + part.t};
    }
    CHECK(same(f.total.at(v), sum));
    CHECK(same(f.total.at(v), again.total.at(v)));

    const Vec3f q{w.state.x[v], w.state.y[v], w.state.t[v]};
    repulsion_near_slots(g, q, w.topo.element[v], near);
    repulsion_far_slots(g, q, w.topo.element[v], far);
    CHECK((f.contact[v] & contact_overlap) == 0);
    const RepulsionResult rr = repulsion_force(w.topo, w.state, step_params(p), g, v, near, far, false);
    CHECK(same(r, rr.force));
    // The slice gap counts the container's wall as a neighbour.
    const ContainerQuery wall = container_query(w.topo.container, q.x, q.y, true);
    const float d = std::sqrt(wall.distance2);
    const float expected = std::min(d + d, rr.closest);  // the wall's mirror image is twice as far; no overlap
    CHECK(f.closest[v] == expected);
    CHECK(same(e, spring_force(w.topo, w.state, step_params(p), v)));
    CHECK(same(tg, target_force(w.topo, w.state, step_params(p), v)));
    const Vec3f point = boundary_force(w.topo, w.state, step_params(p), v),
                mirror = wall_mirror_force(w.topo, w.state, step_params(p), g, v, wall);
    CHECK(same(b, Vec3f{point.x + mirror.x, point.y + mirror.y, point.t + mirror.t}));
    CHECK(same(o, Vec3f{}));
    CHECK(same(to, torsion_force(w.topo, w.state, step_params(p), v, cx[w.topo.slice[v]], cy[w.topo.slice[v]])));
#define AP_CHECK_LOCAL_FORCE(name, ...) CHECK(same(parts.name.at(v), name##_force(w.topo, w.state, step_params(p), v)));
    AP_LOCAL_FORCES(AP_CHECK_LOCAL_FORCE)
#undef AP_CHECK_LOCAL_FORCE
    if (f.closest[v] < 0.04f) ++with_neighbour;
  }
  CHECK(with_neighbour > 26);  // the facing sides see each other
  CHECK(parts.target.at(13 * 4 + 2).y != 0.0f);
}

TEST_CASE("step_forces: a vertex inside another element gets overlap instead of repulsion") {
  const Params p = test::paper_params();
  // Element 1 spans [0.40, 0.54] × [0.43, 0.57]: element 0's two right corners are 0.02 inside it.
  const test::TinyWorld w = two_tubes(0.47f, 0.07f, 6);
  const CollisionGrid g = build_collision_grid(w.topo, w.state, p);
  ForceBreakdown parts;
  const StepForces f = step_forces(w.topo, w.state, step_params(p), g, &parts);
  int inside = 0;
  for (std::int32_t v = 0; v < w.topo.vertex_count(); ++v) {
    INFO("vertex " << v);
    if ((f.contact[v] & contact_overlap) == 0) {
      CHECK(same(parts.overlap.at(v), Vec3f{}));
      continue;
    }
    ++inside;
    CHECK(same(parts.repulsion.at(v), Vec3f{}));
    SliceBoxes boxes;
    slice_boxes(w.topo, w.state, test::tangents(w), boxes);
    OverlapGrid grid;
    build_overlap_grid(w.topo, boxes, grid);
    CHECK(same(parts.overlap.at(v), overlap_force(w.topo, w.state, step_params(p), v,
                                                  overlap_test(w.topo, w.state, boxes, grid, test::tangents(w), v,
                                                               p.forces.interval_points))));
    CHECK(f.closest[v] == 0.0f);  // an overlapping vertex touches
  }
  // Element 0's right corners (vertices 1, 2 of each slice) on every inner slice; at t = 0 and 1 the
  // jitter may put a corner just outside element 1's t range, where it is not inside.
  // Both elements are at g = 1, so the overlap is with an element no larger: it yields.
  for (std::int32_t s = 1; s < 25; ++s) {
    CHECK(f.contact[s * 4 + 1] == (contact_overlap | contact_inside | contact_yield | contact_block));
    CHECK(f.contact[s * 4 + 2] == (contact_overlap | contact_inside | contact_yield | contact_block));
  }
  CHECK(inside >= 2 * 24);
}
