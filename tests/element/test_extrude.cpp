// §3.1 Fig. 2d–e: extrusion over n_s slices, time edges and the envelope.
#include <catch2/catch.hpp>
#include <cstdio>
#include <map>
#include <set>

#include "animpak/error.hpp"
#include "element/fixtures.hpp"

using namespace animpak;
using namespace animpak::test;

namespace {

SpacetimeElement extrude_static(const Built& b, int slices) {
  const std::vector<std::vector<Vec2>> per_slice(static_cast<std::size_t>(slices), b.mesh.vertices);
  ArtBinding binding = bind_art(b.art.art, b.mesh);
  return extrude("L", b.art, binding, b.mesh, per_slice);
}

// Every spring as (min id, max id) -> class, from the CSR (each spring is stored at both ends).
std::map<Edge, SpringClass> springs_of(const SpacetimeElement& e) {
  std::map<Edge, SpringClass> out;
  for (int v = 0; v < e.vertex_count(); ++v)
    for (int k = e.springs.offsets[v]; k < e.springs.offsets[v + 1]; ++k) {
      const int w = e.springs.neighbors[k];
      out[{std::min(v, w), std::max(v, w)}] = e.springs.classes[k];
    }
  return out;
}

}  // namespace

TEST_CASE("extrusion counts follow the formulas in n_s", "[element][extrude]") {
  const Built b = build(l_art());
  const SliceMesh& m = b.mesh;
  const std::size_t p = m.vertices.size(), bc = static_cast<std::size_t>(m.boundary_count);
  for (int n : {2, 3, 10, 100}) {
    INFO("n_s = " << n);
    const SpacetimeElement e = extrude_static(b, n);
    const std::size_t ns = static_cast<std::size_t>(n);
    CHECK(static_cast<std::size_t>(e.vertex_count()) == ns * p);
    CHECK(e.x.size() == ns * p);
    CHECK(e.t.size() == ns * p);
    CHECK(e.springs.count(SpringClass::edge) == ns * m.edges.size());
    CHECK(e.springs.count(SpringClass::shear) == ns * m.shear_edges.size());
    CHECK(e.springs.count(SpringClass::negative_space) == ns * m.negative_space_edges.size());
    CHECK(e.springs.count(SpringClass::time) == 3 * bc * (ns - 1));
    CHECK(e.springs.count(SpringClass::target) == 0);
    CHECK(e.envelope.size() == 2 * bc * (ns - 1));
    // Each spring once: the unique pairs equal the total count.
    const auto springs = springs_of(e);
    CHECK(springs.size() == e.springs.neighbors.size() / 2);
    for (int s = 0; s < n; ++s)
      for (std::size_t v = 0; v < p; ++v) {
        const int id = e.id(s, static_cast<int>(v));
        CHECK(e.t[id] == static_cast<double>(s) / (n - 1));
        CHECK(e.x[id] == m.vertices[v].x);
        CHECK(e.y[id] == m.vertices[v].y);
      }
    CHECK(e.t.front() == 0.0);
    CHECK(e.t.back() == 1.0);
  }
}

TEST_CASE("time edges and envelope triangles stitch consecutive boundaries", "[element][extrude]") {
  const Built b = build(l_art());
  const int n = 4;
  const SpacetimeElement e = extrude_static(b, n);
  const int p = e.vertices_per_slice(), bc = e.slice.boundary_count;
  const auto springs = springs_of(e);
  auto slice_of = [&](int id) { return id / p; };
  auto local = [&](int id) { return id % p; };
  // Time springs join boundary vertex b of slice s to b or b+1 of slice s+1, or b+1 of s to b of s+1.
  for (const auto& [edge, cls] : springs) {
    if (cls != SpringClass::time) {
      CHECK(slice_of(edge[0]) == slice_of(edge[1]));
      continue;
    }
    REQUIRE(slice_of(edge[1]) == slice_of(edge[0]) + 1);
    const int lo = local(edge[0]), hi = local(edge[1]);
    CHECK(lo < bc);
    CHECK(hi < bc);
    CHECK((lo == hi || hi == (lo + 1) % bc || lo == (hi + 1) % bc));
  }
  std::map<Edge, int> uses;  // time edge -> envelope triangles using it, per gap
  for (const Triangle& tri : e.envelope) {
    int boundary_edges = 0, time_edges = 0;
    for (int k = 0; k < 3; ++k) {
      const Edge d{std::min(tri[k], tri[(k + 1) % 3]), std::max(tri[k], tri[(k + 1) % 3])};
      REQUIRE(springs.count(d) == 1);
      const SpringClass cls = springs.at(d);
      if (cls == SpringClass::time) {
        ++time_edges;
        ++uses[d];
      } else {
        const int u = local(d[0]), w = local(d[1]);
        CHECK(cls == SpringClass::edge);
        CHECK(slice_of(d[0]) == slice_of(d[1]));
        CHECK(((w == u + 1) || (u == 0 && w == bc - 1)));
        ++boundary_edges;
      }
    }
    CHECK(boundary_edges == 1);
    CHECK(time_edges == 2);
  }
  // Each gap's envelope is a closed band: its 2B time edges (AC and BC) are each in exactly two triangles.
  CHECK(uses.size() == static_cast<std::size_t>(2 * bc * (n - 1)));
  for (const auto& [edge, count] : uses) CHECK(count == 2);
  // Spring order is slice-major: the first springs are slice 0's edges, in the slice's order.
  CHECK(e.springs.neighbors[e.springs.offsets[0]] == e.slice.edges[0][1]);
}

TEST_CASE("extrude is deterministic and rejects mismatched slices", "[element][extrude]") {
  const Built b = build(l_art());
  const SpacetimeElement e1 = extrude_static(b, 5), e2 = extrude_static(b, 5);
  CHECK(e1.springs.neighbors == e2.springs.neighbors);
  CHECK(e1.springs.offsets == e2.springs.offsets);
  CHECK(e1.envelope == e2.envelope);
  std::vector<std::vector<Vec2>> bad(3, b.mesh.vertices);
  bad[1].pop_back();
  CHECK_THROWS_AS(extrude("L", b.art, {}, b.mesh, bad), InputError);
  CHECK_THROWS_AS(extrude("L", b.art, {}, b.mesh, {b.mesh.vertices}), InputError);
}

// Not run by default: `test_element "[.counts]"` prints one real element's sizes at n_s = 100.
TEST_CASE("print the spacetime sizes of the bird at n_s = 100", "[.counts]") {
  const Built b = build(load_path_file(shape_path("bird")));
  const SpacetimeElement e = extrude_static(b, 100);
  std::printf(
      "bird, n_s = 100: %d vertices, springs edge %zu shear %zu negative_space %zu time %zu, "
      "%zu envelope triangles, %.2f springs per vertex (each counted once)\n",
      e.vertex_count(), e.springs.count(SpringClass::edge), e.springs.count(SpringClass::shear),
      e.springs.count(SpringClass::negative_space), e.springs.count(SpringClass::time), e.envelope.size(),
      0.5 * static_cast<double>(e.springs.neighbors.size()) / e.vertex_count());
}
