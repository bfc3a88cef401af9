#include <catch2/catch.hpp>

#include <cmath>

#include "animpak/animation.hpp"
#include "animpak/error.hpp"
#include "element/slice_fixtures.hpp"

using namespace animpak;
using animpak::testing::grid_border;
using animpak::testing::grid_slice;
using animpak::testing::max_distance;

namespace {

Vec2 rigid(Vec2 p, double angle, Vec2 shift) {
  const double c = std::cos(angle), s = std::sin(angle);
  return Vec2{c * p.x - s * p.y, s * p.x + c * p.y} + shift;
}

}  // namespace

TEST_CASE("ArapSolver: a rigidly moved handle set moves every vertex rigidly") {
  const SliceMesh mesh = grid_slice(7, 5, 0.1, {0.2, 0.3});
  // Handles on the border only: the interior has to find the rotation by itself.
  const std::vector<int> handles = grid_border(7, 5);
  const ArapSolver solver(mesh, handles);
  const double angle = 0.7;
  const Vec2 shift{0.15, -0.05};
  std::vector<Vec2> targets;
  for (int v : handles) targets.push_back(rigid(mesh.vertices[v], angle, shift));
  const std::vector<Vec2> p = solver.solve(targets, mesh.vertices, 200);
  std::vector<Vec2> expected;
  for (Vec2 r : mesh.vertices) expected.push_back(rigid(r, angle, shift));
  CHECK(max_distance(p, expected) < 1e-6);
  CHECK(solver.energy(p) < 1e-10);
  CHECK(solver.energy(mesh.vertices) < 1e-20);
}

TEST_CASE("ArapSolver: a non-rigid handle move lowers the energy, iteration after iteration") {
  const SliceMesh mesh = grid_slice(9, 4, 0.1);
  // Pin the left column, drag the right column down: a bend.
  std::vector<int> handles;
  std::vector<Vec2> targets;
  for (int j = 0; j < 4; ++j) {
    handles.push_back(j * 9);
    targets.push_back(mesh.vertices[j * 9]);
    handles.push_back(j * 9 + 8);
    targets.push_back(mesh.vertices[j * 9 + 8] + Vec2{-0.1, 0.4});
  }
  const ArapSolver solver(mesh, handles);
  std::vector<Vec2> initial = mesh.vertices;
  for (std::size_t k = 0; k < handles.size(); ++k) initial[handles[k]] = targets[k];
  double previous = solver.energy(initial);
  CHECK(previous > 1e-3);
  for (int iterations : {1, 2, 5, 20, 80}) {
    const std::vector<Vec2> p = solver.solve(targets, initial, iterations);
    const double e = solver.energy(p);
    INFO("iterations " << iterations << ": " << e << " after " << previous);
    CHECK(e <= previous * (1 + 1e-12));
    previous = e;
    for (std::size_t k = 0; k < handles.size(); ++k) CHECK(p[handles[k]] == targets[k]);
  }
  CHECK(previous < 0.5 * solver.energy(initial));
}

TEST_CASE("ArapSolver: factor once, solve many: results do not depend on earlier solves") {
  const SliceMesh mesh = grid_slice(6, 6, 0.1);
  const std::vector<int> handles{0, 5, 30, 35, 14};
  const ArapSolver reused(mesh, handles);
  std::vector<Vec2> last;
  for (int round = 0; round < 5; ++round) {
    std::vector<Vec2> targets;
    for (std::size_t k = 0; k < handles.size(); ++k)
      targets.push_back(mesh.vertices[handles[k]] + Vec2{0.02 * round * (k % 2 ? 1 : -1), 0.03 * round});
    last = reused.solve(targets, mesh.vertices, 15);
    if (round == 2) {
      const ArapSolver fresh(mesh, handles);
      CHECK(max_distance(last, fresh.solve(targets, mesh.vertices, 15)) == 0.0);
    }
  }
  ArapSolver moved = ArapSolver(mesh, handles);
  std::vector<Vec2> targets;
  for (std::size_t k = 0; k < handles.size(); ++k)
    targets.push_back(mesh.vertices[handles[k]] + Vec2{0.08 * (k % 2 ? 1 : -1), 0.12});
  CHECK(max_distance(last, moved.solve(targets, mesh.vertices, 15)) == 0.0);
}

TEST_CASE("ArapSolver: no handles, duplicates and unpinned pieces are InputError") {
  const SliceMesh mesh = grid_slice(4, 4, 0.1);
  CHECK_THROWS_AS(ArapSolver(mesh, {}), InputError);
  CHECK_THROWS_WITH(ArapSolver(mesh, {3, 7, 3}), Catch::Contains("vertex 3"));
  CHECK_THROWS_AS(ArapSolver(mesh, {16}), InputError);
  // Two grids side by side, a handle on only one of them.
  SliceMesh two = mesh;
  const SliceMesh other = grid_slice(4, 4, 0.1, {1.0, 0.0});
  for (Vec2 p : other.vertices) two.vertices.push_back(p);
  for (Triangle t : other.triangles) two.triangles.push_back({t[0] + 16, t[1] + 16, t[2] + 16});
  for (Edge e : other.edges) two.edges.push_back({e[0] + 16, e[1] + 16});
  CHECK_THROWS_WITH(ArapSolver(two, {0}), Catch::Contains("not connected to any handle"));
  CHECK_NOTHROW(ArapSolver(two, {0, 16}));
  const ArapSolver solver(mesh, {0});
  CHECK_THROWS_AS(solver.solve({}, mesh.vertices), InputError);
}
