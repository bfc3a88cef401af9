// Closed-form cases for Eq. 2, 4, 5, 6 and the target spring on two or three vertices.
#include <catch2/catch.hpp>

#include <cmath>

#include "tiny_worlds.hpp"

using namespace animpak;
using namespace animpak::reference;
using animpak::test::WorldBuilder;

namespace {

// Two vertices of one element, one spring of class c and rest length `rest` between them.
test::TinyWorld spring_pair(test::Ring ring, SpringClass c, float rest) {
  WorldBuilder b;
  b.add_element({{ring, 0.5f}}, false);
  b.add_spring(0, 1, c, rest);
  return b.build();
}

}  // namespace

TEST_CASE("springs: Eq. 2, one stretched spring pulls both ends together with k (|u| - l)^2") {
  const Params p = test::paper_params();
  // |u| = 0.625, l = 0.5: stretch 0.125, k = 10 → 10 · 0.015625 = 0.15625, all exact in float.
  const test::TinyWorld w = spring_pair({{0.25f, 0.5f}, {0.875f, 0.5f}}, SpringClass::edge, 0.5f);
  const Vec3f fa = spring_force(w.topo, w.state, step_params(p), 0),
              fb = spring_force(w.topo, w.state, step_params(p), 1);
  CHECK(fa.x == 0.15625f);
  CHECK(fa.y == 0.0f);
  CHECK(fa.t == 0.0f);
  CHECK(fb.x == -0.15625f);
}

TEST_CASE("springs: a spring stretched by 0.1 with k = 10 gives 0.1 along the edge") {
  const Params p = test::paper_params();
  const test::TinyWorld w = spring_pair({{0.2f, 0.3f}, {0.2f, 0.9f}}, SpringClass::shear, 0.5f);
  const Vec3f fa = spring_force(w.topo, w.state, step_params(p), 0);
  CHECK(fa.x == 0.0f);
  CHECK(fa.y == Approx(0.1f).margin(1e-6));
}

TEST_CASE("springs: a compressed spring pushes the ends apart") {
  const Params p = test::paper_params();
  const test::TinyWorld w = spring_pair({{0.25f, 0.5f}, {0.875f, 0.5f}}, SpringClass::edge, 0.75f);
  CHECK(spring_force(w.topo, w.state, step_params(p), 0).x == -0.15625f);
  CHECK(spring_force(w.topo, w.state, step_params(p), 1).x == 0.15625f);
}

TEST_CASE("springs: each class uses its own stiffness") {
  const Params p = test::paper_params();
  const std::pair<SpringClass, double> classes[] = {{SpringClass::edge, p.forces.k_edge},
                                                    {SpringClass::shear, p.forces.k_shear},
                                                    {SpringClass::negative_space, p.forces.k_negative_space},
                                                    {SpringClass::time, p.forces.k_time},
                                                    {SpringClass::target, p.forces.k_target}};
  for (const auto& [c, k] : classes) {
    INFO(static_cast<int>(c));
    const test::TinyWorld w = spring_pair({{0.25f, 0.5f}, {0.875f, 0.5f}}, c, 0.5f);
    CHECK(spring_force(w.topo, w.state, step_params(p), 0).x == Approx(k * 0.015625).epsilon(1e-6));
  }
}

TEST_CASE("springs: a spring at rest or with coincident ends gives no force") {
  const Params p = test::paper_params();
  const test::TinyWorld rest = spring_pair({{0.25f, 0.5f}, {0.75f, 0.5f}}, SpringClass::edge, 0.5f);
  CHECK(spring_force(rest.topo, rest.state, step_params(p), 0).x == 0.0f);
  const test::TinyWorld w = spring_pair({{0.5f, 0.5f}, {0.5f, 0.5f}}, SpringClass::edge, 0.5f);
  const Vec3f f = spring_force(w.topo, w.state, step_params(p), 0);
  CHECK((f.x == 0.0f && f.y == 0.0f && f.t == 0.0f));
}

TEST_CASE("springs: a time spring acts along t, summed over the CSR slots") {
  const Params p = test::paper_params();
  WorldBuilder b;
  b.add_element({{{{0.5f, 0.5f}}, 0.25f}, {{{0.5f, 0.5f}}, 0.5f}, {{{0.5f, 0.5f}}, 0.75f}}, false);
  b.add_spring(0, 1, SpringClass::time, 0.125f);  // stretched by 0.125: pulls vertex 1 down in t
  b.add_spring(1, 2, SpringClass::time, 0.5f);    // compressed by 0.25: pushes vertex 1 down in t
  const test::TinyWorld w = b.build();
  const Vec3f f = spring_force(w.topo, w.state, step_params(p), 1);
  CHECK(f.t == Approx(-0.01 * 0.015625 - 0.01 * 0.0625).epsilon(1e-6));
  CHECK(f.x == 0.0f);
}

TEST_CASE("target: a zero-length Eq. 2 spring from the anchor to its target point") {
  const Params p = test::paper_params();
  WorldBuilder b;
  b.add_element({{{{0.5f, 0.5f}, {0.6f, 0.5f}}, 0.5f}}, false);
  b.add_target(0, 0.5f, 0.75f, 0.5f);
  const test::TinyWorld w = b.build();
  const Vec3f f = target_force(w.topo, w.state, step_params(p), 0);
  CHECK(f.x == 0.0f);
  CHECK(f.y == 0.625f);  // 10 · 0.25²
  CHECK(f.t == 0.0f);
  const Vec3f none = target_force(w.topo, w.state, step_params(p), 1);
  CHECK((none.x == 0.0f && none.y == 0.0f && none.t == 0.0f));
}

TEST_CASE("temporal: Eq. 6 pulls a vertex back to its slice's rest time") {
  const Params p = test::paper_params();
  WorldBuilder b;
  b.add_element({{{{0.5f, 0.5f}}, 0.5f}}, false);
  test::TinyWorld w = b.build();
  w.state.t[0] = 0.625f;
  const Vec3f f = temporal_force(w.topo, w.state, step_params(p), 0);
  CHECK(f.t == -0.125f);
  CHECK((f.x == 0.0f && f.y == 0.0f));
}

TEST_CASE("boundary: Eq. 4 on a unit-square container") {
  Params p = test::paper_params();
  p.forces.wall_repulsion = 0.0;  // Eq. 4 alone; the wall's repulsion inside is the next case
  WorldBuilder b;
  b.add_element({{{{0.5f, 0.5f}, {1.25f, 0.5f}, {-0.5f, -0.25f}, {1.0f, 0.5f}}, 0.5f}}, false);
  const test::TinyWorld w = b.build();
  const Vec3f inside = boundary_force(w.topo, w.state, step_params(p), 0);
  CHECK((inside.x == 0.0f && inside.y == 0.0f && inside.t == 0.0f));
  const Vec3f right = boundary_force(w.topo, w.state, step_params(p), 1);  // closest point (1, 0.5)
  CHECK(right.x == -1.25f);
  CHECK(right.y == 0.0f);
  const Vec3f corner = boundary_force(w.topo, w.state, step_params(p), 2);  // closest point (0, 0)
  CHECK(corner.x == 2.5f);
  CHECK(corner.y == 1.25f);
  CHECK(corner.t == 0.0f);
  const Vec3f on_edge = boundary_force(w.topo, w.state, step_params(p), 3);
  CHECK((on_edge.x == 0.0f && on_edge.y == 0.0f));
}

TEST_CASE("boundary: the wall repels a boundary vertex inside the container like Eq. 1, interior vertices not") {
  Params p = test::paper_params();  // k_rpl 10, ε 1
  p.forces.wall_repulsion = 10.0;   // the point wall alone (0.5.0's default), not the mirror image
  p.forces.wall_mirror = 0.0;
  p.forces.wall_range = 0.2;  // both vertices below are within reach
  WorldBuilder b;
  b.set_container({test::square(0.5f, 0.5f, 0.5f), test::square(0.5f, 0.5f, 0.125f)});
  b.add_element({{{{0.25f, 0.5f}, {0.5f, 0.9f}}, 0.5f}}, false);
  test::TinyWorld w = b.build();
  // Vertex 0: nearest wall the hole's edge x = 0.375, u = (−0.125, 0): 100 · (−1, 0) / (1 + 0.125²).
  const Vec3f f0 = boundary_force(w.topo, w.state, step_params(p), 0);
  CHECK(f0.x == Approx(-100.0 / (1.0 + 0.015625)).epsilon(1e-6));
  CHECK(f0.y == 0.0f);
  // Vertex 1: the outline's y = 1, u = (0, −0.1).
  const Vec3f f1 = boundary_force(w.topo, w.state, step_params(p), 1);
  CHECK(f1.x == 0.0f);
  CHECK(f1.y == Approx(-100.0 / (1.0 + 0.01)).epsilon(1e-6));
  w.topo.flags[1] = 0;  // an interior vertex feels nothing inside
  const Vec3f interior = boundary_force(w.topo, w.state, step_params(p), 1);
  CHECK((interior.x == 0.0f && interior.y == 0.0f && interior.t == 0.0f));
}

TEST_CASE("boundary: the wall repels only within wall_range, so a wall across the container pushes nothing") {
  Params p = test::paper_params();
  p.forces.wall_repulsion = 10.0;  // the point wall
  p.forces.wall_mirror = 0.0;
  WorldBuilder b;
  b.set_container({test::square(0.5f, 0.5f, 0.5f), test::square(0.5f, 0.5f, 0.125f)});
  b.add_element({{{{0.25f, 0.5f}, {0.5f, 0.9f}}, 0.5f}}, false);
  test::TinyWorld w = b.build();
  // Vertex 0 is 0.125 from the hole's edge, vertex 1 0.1 from the outline.
  p.forces.wall_range = 0.11;
  const Vec3f far0 = boundary_force(w.topo, w.state, step_params(p), 0);
  CHECK((far0.x == 0.0f && far0.y == 0.0f));
  const Vec3f near1 = boundary_force(w.topo, w.state, step_params(p), 1);
  CHECK(near1.y == Approx(-100.0 / (1.0 + 0.01)).epsilon(1e-6));
  p.forces.wall_range = 0.09;
  const Vec3f far1 = boundary_force(w.topo, w.state, step_params(p), 1);
  CHECK((far1.x == 0.0f && far1.y == 0.0f));
}

TEST_CASE("boundary: the wall's mirror image pushes a vertex as the element reflected in the wall would") {
  // A: the container's left wall at x = 0.48 (twelve cells of 0.04, so the reflection maps grid cells onto
  // grid cells) and an element 0.01 from it. B: no wall there, and the element's reflection in x = 0.48 as
  // a second element. The mirror force on a vertex in A is the repulsion the reflection exerts in B, up
  // to the order of the sums' terms.
  Params p;
  p.forces.wall_mirror = 1.0;
  p.forces.wall_repulsion = 0.0;
  const test::Ring ring = {{0.49f, 0.40f}, {0.55f, 0.41f}, {0.54f, 0.47f}, {0.50f, 0.46f}};
  test::Ring reflected;
  for (const auto& q : ring) reflected.push_back({0.96f - q[0], q[1]});
  const std::vector<float> times = {0.3f, 0.5f, 0.7f};
  const auto tube = [&](const test::Ring& r) {
    std::vector<test::TinySlice> slices;
    for (const float t : times) slices.push_back({r, t});
    return slices;
  };
  WorldBuilder a;
  a.set_container({{{0.48f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.48f, 1.0f}}});
  a.add_element(tube(ring));
  const test::TinyWorld wa = a.build();
  WorldBuilder b;
  b.add_element(tube(ring));
  b.add_element(tube(reflected));
  const test::TinyWorld wb = b.build();
  const CollisionGrid ga = build_collision_grid(wa.topo, wa.state, p);
  const CollisionGrid gb = build_collision_grid(wb.topo, wb.state, p);
  int pushed = 0;
  for (std::int32_t v = 0; v < wa.topo.vertex_count(); ++v) {
    INFO("vertex " << v);
    const ContainerQuery wall = container_query(wa.topo.container, wa.state.x[v], wa.state.y[v], true);
    const Vec3f m = wall_mirror_force(wa.topo, wa.state, step_params(p), ga, v, wall);
    std::vector<std::int32_t> near, far;
    const Vec3f q{wb.state.x[v], wb.state.y[v], wb.state.t[v]};
    repulsion_near_slots(gb, q, 0, near);
    repulsion_far_slots(gb, q, 0, far);
    const Vec3f r = repulsion_force(wb.topo, wb.state, step_params(p), gb, v, near, far, false).force;
    CHECK(m.x == Approx(r.x).epsilon(1e-4).margin(1e-12));
    CHECK(m.y == Approx(r.y).epsilon(1e-4).margin(1e-12));
    CHECK(m.t == Approx(r.t).epsilon(1e-4).margin(1e-12));
    pushed += m.x > 0.0f;  // away from the wall
  }
  CHECK(pushed >= 3);  // the vertices near the wall on every slice
  // Added to the wall's force in the step, and off with wall_mirror 0.
  const ContainerQuery wall = container_query(wa.topo.container, wa.state.x[4], wa.state.y[4], true);
  const StepForces with = step_forces(wa.topo, wa.state, step_params(p), ga, nullptr);
  p.forces.wall_mirror = 0.0;
  CHECK(wall_mirror_force(wa.topo, wa.state, step_params(p), ga, 4, wall).x == 0.0f);
  const StepForces without = step_forces(wa.topo, wa.state, step_params(p), ga, nullptr);
  CHECK(with.total.x[4] > without.total.x[4]);
}

TEST_CASE("boundary: a vertex inside a hole is pulled to the hole's ring") {
  Params p = test::paper_params();
  p.forces.wall_repulsion = 0.0;
  WorldBuilder b;
  b.set_container({test::square(0.5f, 0.5f, 0.5f), test::square(0.5f, 0.5f, 0.125f)});
  b.add_element({{{{0.5f, 0.5625f}, {0.25f, 0.5f}}, 0.5f}}, false);
  const test::TinyWorld w = b.build();
  const Vec3f in_hole = boundary_force(w.topo, w.state, step_params(p), 0);  // nearest hole edge y = 0.625
  CHECK(in_hole.x == 0.0f);
  CHECK(in_hole.y == 0.3125f);
  const Vec3f between = boundary_force(w.topo, w.state, step_params(p), 1);
  CHECK((between.x == 0.0f && between.y == 0.0f));
}

TEST_CASE("torsion: Eq. 5 turns a slice rotated by +5 or -5 degrees back, with magnitude k_tor") {
  const Params p = test::paper_params();
  const double pi = 3.14159265358979323846;
  for (const double degrees : {5.0, -5.0}) {
    INFO(degrees);
    WorldBuilder b;
    b.add_element({{test::square(0.5f, 0.5f, 0.125f), 0.5f}}, false);
    test::TinyWorld w = b.build();
    const double a = degrees * pi / 180.0;
    for (int v = 0; v < 4; ++v) {
      const double ux = w.state.x[v] - 0.5, uy = w.state.y[v] - 0.5;
      w.state.x[v] = static_cast<float>(0.5 + std::cos(a) * ux - std::sin(a) * uy);
      w.state.y[v] = static_cast<float>(0.5 + std::sin(a) * ux + std::cos(a) * uy);
    }
    std::vector<float> cx, cy;
    slice_centroids(w.topo, w.state, cx, cy);
    CHECK(cx[0] == Approx(0.5f).margin(1e-6));
    // Vertex 1 rests at (0.625, 0.375): direction −45° in the stored (y-down) coordinates.
    const double now = (-45.0 + degrees) * pi / 180.0;
    const double sign = degrees > 0 ? -1.0 : 1.0;  // always back towards −45°
    const Vec3f f = torsion_force(w.topo, w.state, step_params(p), 1, cx[0], cy[0]);
    CHECK(f.x == Approx(sign * 0.1 * -std::sin(now)).margin(1e-6));
    CHECK(f.y == Approx(sign * 0.1 * std::cos(now)).margin(1e-6));
    CHECK(f.t == 0.0f);
    for (int v = 0; v < 4; ++v) {
      const Vec3f g = torsion_force(w.topo, w.state, step_params(p), v, cx[0], cy[0]);
      const double ux = w.state.x[v] - cx[0], uy = w.state.y[v] - cy[0];
      CHECK(std::hypot(g.x, g.y) == Approx(0.1).epsilon(1e-5));
      CHECK((-uy * g.x + ux * g.y) * degrees < 0.0);  // opposes the rotation
    }
  }
}

TEST_CASE("torsion: no force at the rest orientation") {
  const Params p = test::paper_params();
  WorldBuilder b;
  b.add_element({{test::square(0.5f, 0.5f, 0.125f), 0.5f}}, false);
  const test::TinyWorld w = b.build();
  std::vector<float> cx, cy;
  slice_centroids(w.topo, w.state, cx, cy);
  for (int v = 0; v < 4; ++v) {
    const Vec3f f = torsion_force(w.topo, w.state, step_params(p), v, cx[0], cy[0]);
    CHECK((f.x == 0.0f && f.y == 0.0f && f.t == 0.0f));
  }
}

TEST_CASE("torsion: a keyed slice holding its target angle turns back with k_target_angle, others with k_tor") {
  Params p = test::paper_params();
  p.forces.k_target_angle = 2.0;
  const double pi = 3.14159265358979323846;
  // Two slices of a triangle rotated by +10° about their centroids; slice 0 is a guided target's slice
  // with an angle (vertex_hold_angle), slice 1 an ordinary one.
  const test::Ring tri = {{0.6f, 0.5f}, {0.4f, 0.4f}, {0.4f, 0.6f}};
  WorldBuilder b;
  b.add_element({{tri, 0.0f}, {tri, 1.0f}}, false);
  test::TinyWorld w = b.build();
  for (int v = 0; v < 3; ++v) w.topo.flags[v] |= vertex_hold_angle;
  const double a = 10.0 * pi / 180.0;
  const double c = (0.6 + 0.4 + 0.4) / 3.0;  // centroid (c, 0.5)
  for (int v = 0; v < 6; ++v) {
    const double ux = w.state.x[v] - c, uy = w.state.y[v] - 0.5;
    w.state.x[v] = static_cast<float>(c + std::cos(a) * ux - std::sin(a) * uy);
    w.state.y[v] = static_cast<float>(0.5 + std::sin(a) * ux + std::cos(a) * uy);
  }
  std::vector<float> cx, cy;
  slice_centroids(w.topo, w.state, cx, cy);
  // Vertex 0 rests at direction 0° and now points at +10°: the force is k u⊥ backwards, closed form
  // k · (sin 10°, −cos 10°).
  const Vec3f held = torsion_force(w.topo, w.state, step_params(p), 0, cx[0], cy[0]);
  CHECK(held.x == Approx(2.0 * std::sin(a)).margin(1e-5));
  CHECK(held.y == Approx(-2.0 * std::cos(a)).margin(1e-5));
  const Vec3f free = torsion_force(w.topo, w.state, step_params(p), 3, cx[1], cy[1]);
  CHECK(free.x == Approx(0.1 * std::sin(a)).margin(1e-6));
  CHECK(free.y == Approx(-0.1 * std::cos(a)).margin(1e-6));
  for (int v = 0; v < 6; ++v) {
    const int s = v / 3;
    const Vec3f f = torsion_force(w.topo, w.state, step_params(p), v, cx[s], cy[s]);
    const double ux = w.state.x[v] - cx[s], uy = w.state.y[v] - cy[s];
    CHECK(std::hypot(f.x, f.y) == Approx(s == 0 ? 2.0 : 0.1).epsilon(1e-5));
    CHECK((-uy * f.x + ux * f.y) < 0.0);  // turns back against the +10°
  }
}

TEST_CASE("overlap force: Eq. 3 pulls a vertex towards its incident slice-triangle centroids") {
  const Params p = test::paper_params();
  WorldBuilder b;
  b.add_element({{test::square(0.5f, 0.5f, 0.5f), 0.5f}});  // fan (0,1,2), (0,2,3) over (0,0)..(1,1)
  const test::TinyWorld w = b.build();
  const OverlapResult crossing{true, false};  // an edge crossing only: Eq. 3 without the depth term
  const Vec3f f1 = overlap_force(w.topo, w.state, step_params(p), 1, crossing);  // only in (0,1,2): centroid (2/3, 1/3)
  CHECK(f1.x == Approx(-5.0 / 3.0).epsilon(1e-6));
  CHECK(f1.y == Approx(5.0 / 3.0).epsilon(1e-6));
  CHECK(f1.t == 0.0f);
  const Vec3f f0 = overlap_force(w.topo, w.state, step_params(p), 0, crossing);  // both: (2/3, 1/3) + (1/3, 2/3)
  CHECK(f0.x == Approx(5.0).epsilon(1e-6));
  CHECK(f0.y == Approx(5.0).epsilon(1e-6));
  const Vec3f none = overlap_force(w.topo, w.state, step_params(p), 0, OverlapResult{});  // no overlap, no force
  CHECK((none.x == 0.0f && none.y == 0.0f && none.t == 0.0f));
  // Inside another element: plus k_ovr_depth times the way out.
  const Vec3f d = overlap_force(w.topo, w.state, step_params(p), 0, OverlapResult{true, true, 0.25f, -0.5f});
  CHECK(d.x == Approx(5.0 + p.forces.k_overlap_depth * 0.25).epsilon(1e-6));
  CHECK(d.y == Approx(5.0 + p.forces.k_overlap_depth * -0.5).epsilon(1e-6));
}

TEST_CASE(
    "fold guard: a slice triangle folded over its opposite edge pushes the vertex back by k_fold times the "
    "height it misses, and nothing above fold_area of its rest area") {
  Params p = test::paper_params();
  p.forces.k_fold = 2.0;
  p.forces.fold_area = 0.5;
  WorldBuilder b;
  b.add_element({{test::square(0.5f, 0.5f, 0.5f), 0.5f}});  // fan (0,1,2), (0,2,3) over (0,0)..(1,1)
  test::TinyWorld w = b.build();
  for (std::int32_t v = 0; v < 4; ++v) {  // at rest: every triangle at its full area
    const Vec3f f = fold_force(w.topo, w.state, step_params(p), v);
    CHECK((f.x == 0.0f && f.y == 0.0f && f.t == 0.0f));
  }
  // Vertex 1, (1, 0), mirrored across the diagonal 0-2 to (0.2, 0.8): triangle (0,1,2) is folded over.
  w.state.x[1] = 0.2f;
  w.state.y[1] = 0.8f;
  const Vec3f f = fold_force(w.topo, w.state, step_params(p), 1);
  // Twice its signed area is -0.6 where fold_area asks for 0.5; the missing height is 1.1 / sqrt(2),
  // pushed along (1, -1) / sqrt(2), back over the diagonal.
  CHECK(f.x == Approx(2.0 * 0.55).epsilon(1e-5));
  CHECK(f.y == Approx(-2.0 * 0.55).epsilon(1e-5));
  CHECK(f.t == 0.0f);
  // Squeezed to 0.6 of its rest area it is above fold_area: no push; at 0.4, a push of the 0.1 missing.
  w.state.x[1] = 1.0f - 0.2f;
  w.state.y[1] = 0.2f;  // twice the area: 1 - 0.2 - 0.2 = 0.6
  const Vec3f above = fold_force(w.topo, w.state, step_params(p), 1);
  CHECK((above.x == 0.0f && above.y == 0.0f));
  w.state.x[1] = 0.7f;
  w.state.y[1] = 0.3f;  // 0.4
  const Vec3f below = fold_force(w.topo, w.state, step_params(p), 1);
  CHECK(below.x == Approx(2.0 * 0.05).epsilon(1e-4));
  CHECK(below.y == Approx(-2.0 * 0.05).epsilon(1e-4));
  // The rest area grows with g: at g = 2 the untouched square is a quarter of its grown rest area.
  w.state.x[1] = 1.0f;
  w.state.y[1] = 0.0f;
  w.state.growth[0] = 2.0f;
  const Vec3f grown = fold_force(w.topo, w.state, step_params(p), 1);
  CHECK(grown.x == Approx(2.0 * 0.5).epsilon(1e-5));  // deficit 0.5 * 4 - 1 = 1 over |grad|^2 = 2
  CHECK(grown.y == Approx(-2.0 * 0.5).epsilon(1e-5));
  // k_fold 0 turns it off.
  p.forces.k_fold = 0.0;
  const Vec3f off = fold_force(w.topo, w.state, step_params(p), 1);
  CHECK((off.x == 0.0f && off.y == 0.0f));
}
