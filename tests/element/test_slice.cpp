// §3.1 Fig. 2b–c: sampling, constrained Delaunay triangulation, shear and negative-space edges.
#include <algorithm>
#include <catch2/catch.hpp>

#include "animpak/error.hpp"
#include "element/mesh_checks.hpp"

using namespace animpak;
using namespace animpak::test;

namespace {

// A slice made by hand: only boundary samples, no interior ones. No edge of `ring` is longer than the
// spacing and each corner is farther than the tolerance from its neighbours' chord, so the samples are
// exactly the corners, in order from ring[0].
SliceMesh boundary_only(const std::vector<Vec2>& ring) {
  Params params;
  params.element.interior_spacing = 10.0;  // larger than the shape: no interior sample survives
  Outline outline;
  outline.ring = ring;
  params.element.boundary_spacing = perimeter(ring);
  const SliceMesh mesh = build_slice(outline, params, 1);
  REQUIRE(mesh.vertices == ring);
  return mesh;
}

}  // namespace

TEST_CASE("build_slice makes a valid disc on synthetic shapes", "[element][slice]") {
  // Finer than the defaults so that even the thin bar gets interior samples to check.
  Params params;
  params.element.boundary_spacing = 0.1;
  params.element.interior_spacing = 0.08;
  for (const ArtShape& art : {square_art(), l_art(), bar_art(), frame_art(), two_blobs_art()}) {
    INFO(art.source);
    const Built b = build(art, params);
    check_slice(b.outline, b.mesh, params);
    CHECK(b.mesh.vertices.size() > static_cast<std::size_t>(b.mesh.boundary_count));
  }
}

TEST_CASE("a square split into two triangles has exactly one shear edge", "[element][slice]") {
  const SliceMesh m = boundary_only({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  REQUIRE(m.vertices.size() == 4);
  CHECK(m.triangles.size() == 2);
  CHECK(m.edges.size() == 5);
  REQUIRE(m.shear_edges.size() == 1);
  // The shear edge is the diagonal the triangulation did not take.
  const bool took_02 = std::count(m.edges.begin(), m.edges.end(), Edge{0, 2}) == 1;
  CHECK(m.shear_edges[0] == (took_02 ? Edge{1, 3} : Edge{0, 2}));
  CHECK(m.negative_space_edges.empty());
}

TEST_CASE("negative-space edges span concavities only", "[element][slice]") {
  // Convex: none.
  CHECK(boundary_only({{0, 0}, {2, 0}, {3, 1}, {2, 2}, {0, 2}}).negative_space_edges.empty());
  // An L: the notch's hull edge between (1, 2) and (2, 1) bridges the concavity.
  const SliceMesh l = boundary_only({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  REQUIRE(l.vertices.size() == 6);
  REQUIRE(l.negative_space_edges.size() == 1);
  CHECK(l.negative_space_edges[0] == Edge{2, 4});
  // The default L element: at least one, all outside (checked in check_slice).
  const Built b = build(l_art());
  CHECK_FALSE(b.mesh.negative_space_edges.empty());
  CHECK(build(square_art()).mesh.negative_space_edges.empty());
}

TEST_CASE("build_slice is deterministic for a seed", "[element][slice]") {
  const Built a = build(l_art(), {}, 7), b = build(l_art(), {}, 7);
  REQUIRE(a.mesh.vertices.size() == b.mesh.vertices.size());
  for (std::size_t i = 0; i < a.mesh.vertices.size(); ++i) CHECK(a.mesh.vertices[i] == b.mesh.vertices[i]);
  CHECK(a.mesh.triangles == b.mesh.triangles);
  CHECK(a.mesh.edges == b.mesh.edges);
  CHECK(a.mesh.shear_edges == b.mesh.shear_edges);
  CHECK(a.mesh.negative_space_edges == b.mesh.negative_space_edges);
  const Built c = build(l_art(), {}, 8);
  CHECK_FALSE(std::equal(a.mesh.vertices.begin() + a.mesh.boundary_count, a.mesh.vertices.end(),
                         c.mesh.vertices.begin() + c.mesh.boundary_count, c.mesh.vertices.end()));
}

TEST_CASE("build_slice rejects a degenerate outline", "[element][slice]") {
  Outline flat;
  flat.ring = {{0, 0}, {1, 0}, {2, 0}};
  flat.source = "flat.svg";
  CHECK_THROWS_WITH(build_slice(flat, {}, 1), Catch::Contains("flat.svg"));
  CHECK(build(l_art()).outline.source == "l.svg");
}
