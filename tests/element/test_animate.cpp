#include <catch2/catch.hpp>

#include <cmath>

#include "animpak/animation.hpp"
#include "animpak/error.hpp"
#include "element/slice_fixtures.hpp"

using namespace animpak;
using animpak::testing::grid_slice;
using animpak::testing::max_distance;

namespace {

// A 5 × 5 grid filling [0.3, 0.7]², its square outline, and the identity frame.
SliceMesh square() { return grid_slice(5, 5, 0.1, {0.3, 0.3}); }
Outline square_outline() { return Outline{{{0.3, 0.7}, {0.7, 0.7}, {0.7, 0.3}, {0.3, 0.3}}, {}, {}, {}, 0.0}; }
const ArtFrame identity{};

double mesh_area(const SliceMesh& mesh, const std::vector<Vec2>& p) {
  double a = 0.0;
  for (const Triangle& t : mesh.triangles) a += 0.5 * cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]);
  return a;
}

Vec2 mean(const std::vector<Vec2>& p) {
  Vec2 m;
  for (Vec2 q : p) m = m + q;
  return m * (1.0 / static_cast<double>(p.size()));
}

}  // namespace

TEST_CASE("animate_slices: no animation keeps every slice at rest") {
  const SliceMesh mesh = square();
  const auto slices = animate_slices(mesh, square_outline(), identity, AnimationSpec{}, 4);
  REQUIRE(slices.size() == 4);
  for (const auto& s : slices) CHECK(max_distance(s, mesh.vertices) == 0.0);
  CHECK_THROWS_AS(animate_slices(mesh, square_outline(), identity, AnimationSpec{}, 1), InputError);
}

TEST_CASE("animate_slices: rotate turns clockwise on screen about the outline's centroid") {
  const SliceMesh mesh = square();
  AnimationSpec spec;
  spec.preset = AnimationPreset::rotate;
  spec.turns = 1.0;
  const auto slices = animate_slices(mesh, square_outline(), identity, spec, 5);
  // t = 0.25: a quarter turn. The top-left corner (y down) goes to the top-right corner.
  CHECK(slices[1][0].x == Approx(0.7).margin(1e-12));
  CHECK(slices[1][0].y == Approx(0.3).margin(1e-12));
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Vec2 d = mesh.vertices[v] - Vec2{0.5, 0.5};
    CHECK(norm(slices[1][v] - (Vec2{0.5, 0.5} + Vec2{-d.y, d.x})) < 1e-12);
  }
  CHECK(max_distance(slices[4], slices[0]) <= 1e-9);
  spec.turns = 0.5;
  CHECK_THROWS_WITH(animate_slices(mesh, square_outline(), identity, spec, 5), Catch::Contains("animation.turns"));
  spec.loop = false;
  CHECK_NOTHROW(animate_slices(mesh, square_outline(), identity, spec, 5));
}

TEST_CASE("animate_slices: pulse scales the area by (1 + amplitude)² at its peak") {
  const SliceMesh mesh = square();
  AnimationSpec spec;
  spec.preset = AnimationPreset::pulse;
  spec.amplitude = 0.2;
  const auto slices = animate_slices(mesh, square_outline(), identity, spec, 9);
  const double rest = mesh_area(mesh, mesh.vertices);
  CHECK(mesh_area(mesh, slices[2]) / rest == Approx(1.44).epsilon(1e-12));  // t = 0.25
  CHECK(mesh_area(mesh, slices[6]) / rest == Approx(0.64).epsilon(1e-12));  // t = 0.75
  CHECK(norm(mean(slices[2]) - Vec2{0.5, 0.5}) < 1e-12);
  CHECK(max_distance(slices[8], slices[0]) <= 1e-9);
  spec.amplitude = 1.5;
  CHECK_THROWS_AS(animate_slices(mesh, square_outline(), identity, spec, 9), InputError);
}

TEST_CASE("animate_slices: swim bends the body with a wave that loops, the head steadier than the tail") {
  // A long strip, 1.0 × 0.15, head at the left (the pivot marks it).
  const SliceMesh mesh = grid_slice(21, 4, 0.05, {0.0, 0.4});
  const Outline outline{{{0.0, 0.55}, {1.0, 0.55}, {1.0, 0.4}, {0.0, 0.4}}, {}, {}};
  AnimationSpec spec;
  spec.preset = AnimationPreset::swim;
  spec.amplitude = 0.15;
  spec.pivot = Vec2{0.1, 0.475};
  const int n = 24;
  const auto slices = animate_slices(mesh, outline, identity, spec, n);
  CHECK(max_distance(slices[n - 1], slices[0]) <= 1e-9);
  // The wrap is as smooth as any other step: slice n-2 is as close to slice 0 as slice 1 is.
  CHECK(max_distance(slices[n - 2], slices[0]) < 2.0 * max_distance(slices[1], slices[0]) + 1e-9);
  double head = 0.0, tail = 0.0, worst_stretch = 0.0, worst_midline = 0.0;
  for (const auto& s : slices) {
    for (int j = 0; j < 4; ++j) {
      head = std::max(head, norm(s[j * 21] - mesh.vertices[j * 21]));
      tail = std::max(tail, norm(s[j * 21 + 20] - mesh.vertices[j * 21 + 20]));
    }
    for (const Edge& e : mesh.edges) {
      const double rest = norm(mesh.vertices[e[0]] - mesh.vertices[e[1]]);
      worst_stretch = std::max(worst_stretch, std::fabs(norm(s[e[0]] - s[e[1]]) / rest - 1.0));
    }
    // The two long sides shorten and lengthen against each other; their mean (the mid-line) keeps its
    // length, as a bent body's centre line does.
    double sides = 0.0;
    for (int i = 0; i < 20; ++i) sides += norm(s[i + 1] - s[i]) + norm(s[63 + i + 1] - s[63 + i]);
    worst_midline = std::max(worst_midline, std::fabs(0.5 * sides - 1.0));
  }
  INFO("head " << head << " tail " << tail << " worst relative edge change " << worst_stretch
               << " worst mid-line change " << worst_midline);
  CHECK(tail > 0.08);  // it really swims: the tail swings by a good part of amplitude · length
  CHECK(head < 0.25 * tail);
  // Bending, not stretching or shearing: the mid-line keeps its length, and single edges change only by
  // what curvature does to the sides of a body 0.15 thick (the inner side of the tail's sharpest bend
  // shortens by about curvature · half-width).
  CHECK(worst_midline < 0.03);
  CHECK(worst_stretch < 0.35);
  // With the pivot at the other end, the other end is the head.
  spec.pivot = Vec2{0.9, 0.475};
  const auto flipped = animate_slices(mesh, outline, identity, spec, n);
  double left = 0.0;
  for (const auto& s : flipped) left = std::max(left, norm(s[0] - mesh.vertices[0]));
  CHECK(left > 0.08);
}

TEST_CASE("animate_slices: keyed translation moves the centroid along the spline, in art units") {
  const SliceMesh mesh = square();
  AnimationSpec spec;
  spec.keys = {{0.0, {0.0, 0.0}}, {0.4, {20.0, 10.0}}, {0.7, {-10.0, 5.0}}};
  const ArtFrame frame{{100.0, 100.0}, {0.0, 0.0}, 0.01};  // art units are a hundredth of the unit square
  const int n = 11;
  const auto slices = animate_slices(mesh, square_outline(), frame, spec, n);
  const Spline x({0.0, 0.4, 0.7}, {0.0, 20.0, -10.0}, true), y({0.0, 0.4, 0.7}, {0.0, 10.0, 5.0}, true);
  for (int s = 0; s < n; ++s) {
    const double t = s / (n - 1.0);
    const Vec2 expected = mean(mesh.vertices) + Vec2{x(t), y(t)} * 0.01;
    CHECK(norm(mean(slices[s]) - expected) < 1e-12);
  }
  CHECK(norm(mean(slices[4]) - Vec2{0.7, 0.6}) < 1e-12);  // the key at t = 0.4: (20, 10) art units
  spec.keys.push_back({1.0, {5.0, 0.0}});
  CHECK_THROWS_WITH(animate_slices(mesh, square_outline(), frame, spec, n), Catch::Contains("animation.keys[3]"));
}

TEST_CASE("animate_slices: a handle vertex lands exactly on its key position at key times") {
  const SliceMesh mesh = square();
  // Art frame: art = unit * 200 + (50, 50), so handle points and keys are in art units.
  const ArtFrame frame{{50.0, 50.0}, {0.0, 0.0}, 1.0 / 200.0};
  auto art = [&](Vec2 unit) { return unit * 200.0 + Vec2{50.0, 50.0}; };
  AnimationSpec spec;
  HandleSpec pinned{art({0.3, 0.3}) + Vec2{1.0, -2.0}, {{0.0, art({0.3, 0.3})}}};         // near vertex 0
  HandleSpec dragged{art({0.7, 0.7}), {{0.0, art({0.7, 0.7})}, {0.5, art({0.8, 0.9})}}};  // vertex 24
  spec.handles = {pinned, dragged};
  const int n = 5;
  const auto slices = animate_slices(mesh, square_outline(), frame, spec, n);
  CHECK(norm(slices[0][24] - Vec2{0.7, 0.7}) < 1e-12);
  CHECK(norm(slices[2][24] - Vec2{0.8, 0.9}) < 1e-12);
  for (const auto& s : slices) CHECK(norm(s[0] - Vec2{0.3, 0.3}) < 1e-12);
  CHECK(norm(slices[2][12] - Vec2{0.5, 0.5}) > 0.01);  // the middle follows the drag
  CHECK(max_distance(slices[n - 1], slices[0]) <= 1e-9);

  spec.handles.push_back(HandleSpec{art({0.71, 0.69}), {{0.0, art({0.7, 0.7})}}});
  CHECK_THROWS_WITH(animate_slices(mesh, square_outline(), frame, spec, n),
                    Catch::Contains("animation.handles[2]") && Catch::Contains("animation.handles[1]"));
  spec.handles = {HandleSpec{art({0.5, 0.5}), {}}};
  CHECK_THROWS_WITH(animate_slices(mesh, square_outline(), frame, spec, n), Catch::Contains("handles[0].keys"));
}
