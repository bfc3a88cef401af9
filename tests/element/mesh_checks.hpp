// Validity of one slice (§3.1, Fig. 2b–c), shared by the synthetic and the real-shape tests.
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <set>

#include "element/fixtures.hpp"

namespace animpak::test {

/// docs/parameters.md "Sampling the outline": the boundary samples lie on the outline in its order (one
/// turn), no boundary edge is longer than boundary_spacing, and the polygon they make stays within
/// boundary_tolerance of the outline both ways.
inline void check_boundary_sampling(const Outline& outline, const SliceMesh& mesh, const Params& params) {
  const int b = mesh.boundary_count;
  const std::vector<Vec2> boundary(mesh.vertices.begin(), mesh.vertices.begin() + b);
  const auto& ring = outline.ring;
  const double length = perimeter(ring);
  // Walk the outline from sample 0 (where the walk starts) and record the arc length of each sample met.
  double arc = 0.0, last = -1.0;
  int next = 0;
  for (std::size_t i = 0; i < ring.size() && next < b; ++i) {
    const Vec2 a = ring[i], c = ring[(i + 1) % ring.size()];
    const double len = norm(c - a);
    while (next < b) {
      const Vec2 s = mesh.vertices[next];
      const double along = dot(s - a, c - a) / std::max(len, 1e-300);
      if (std::fabs(cross(c - a, s - a)) / std::max(len, 1e-300) > 1e-9 || along < -1e-9 || along > len + 1e-9) break;
      CHECK(arc + along > last);
      last = arc + along;
      ++next;
    }
    arc += len;
  }
  CHECK(next == b);
  CHECK(last < length);
  double longest = 0.0, deviation = 0.0;
  for (int i = 0; i < b; ++i) {
    const Vec2 p = boundary[i], q = boundary[(i + 1) % b];
    longest = std::max(longest, norm(q - p));
    // Points along the edge, against the outline.
    for (int k = 1; k < 16; ++k) deviation = std::max(deviation, ring_distance(ring, p + (q - p) * (k / 16.0)));
  }
  // Every outline point against the polygon; between two outline points the distance to a segment is
  // convex, so the vertices bound it.
  for (Vec2 p : ring) deviation = std::max(deviation, ring_distance(boundary, p));
  INFO("boundary vertices " << b << ", longest edge " << longest << ", deviation " << deviation);
  CHECK(longest <= params.element.boundary_spacing * (1.0 + 1e-12));
  CHECK(deviation <= params.element.boundary_tolerance + 1e-12);
}

inline void check_slice(const Outline& outline, const SliceMesh& mesh, const Params& params) {
  const int v_count = static_cast<int>(mesh.vertices.size());
  const int b = mesh.boundary_count;
  REQUIRE(b >= 3);
  REQUIRE(b <= v_count);
  std::set<Edge> edges(mesh.edges.begin(), mesh.edges.end());
  CHECK(edges.size() == mesh.edges.size());
  std::set<int> used;
  for (const Triangle& t : mesh.triangles) {
    const Vec2 p = mesh.vertices[t[0]], q = mesh.vertices[t[1]], r = mesh.vertices[t[2]];
    CHECK(0.5 * cross(q - p, r - p) > 1e-12);  // counter-clockwise and not degenerate
    for (int k = 0; k < 3; ++k) {
      used.insert(t[k]);
      const int a = std::min(t[k], t[(k + 1) % 3]), c = std::max(t[k], t[(k + 1) % 3]);
      CHECK(edges.count({a, c}) == 1);
    }
  }
  CHECK(static_cast<int>(used.size()) == v_count);  // every sample, boundary ones included, is a vertex
  for (int i = 0; i < b; ++i) CHECK(edges.count({std::min(i, (i + 1) % b), std::max(i, (i + 1) % b)}) == 1);
  // A disc: V − E + F = 1.
  CHECK(v_count - static_cast<int>(mesh.edges.size()) + static_cast<int>(mesh.triangles.size()) == 1);
  std::vector<Vec2> boundary(mesh.vertices.begin(), mesh.vertices.begin() + b);
  CHECK(signed_area(boundary) > 0.0);
  for (int i = b; i < v_count; ++i) {
    CHECK(ring_contains(outline.ring, mesh.vertices[i]));
    CHECK(ring_contains(boundary, mesh.vertices[i]));
  }
  check_boundary_sampling(outline, mesh, params);
  // Shear and negative-space edges are new edges, unique.
  std::set<Edge> extra;
  for (const Edge& e : mesh.shear_edges) CHECK(edges.count(e) == 0);
  for (const Edge& e : mesh.negative_space_edges) CHECK(edges.count(e) == 0);
  extra.insert(mesh.shear_edges.begin(), mesh.shear_edges.end());
  CHECK(extra.size() == mesh.shear_edges.size());
  std::set<Edge> neg(mesh.negative_space_edges.begin(), mesh.negative_space_edges.end());
  CHECK(neg.size() == mesh.negative_space_edges.size());
  // Negative-space edges join boundary samples and run outside the outline (midpoint outside, no crossing).
  for (const Edge& e : mesh.negative_space_edges) {
    CHECK(e[0] < b);
    CHECK(e[1] < b);
    const Vec2 a = mesh.vertices[e[0]], c = mesh.vertices[e[1]];
    CHECK_FALSE(ring_contains(boundary, (a + c) * 0.5));
    for (int i = 0; i < b; ++i) {
      const int j = (i + 1) % b;
      if (i == e[0] || i == e[1] || j == e[0] || j == e[1]) continue;
      const Vec2 p = mesh.vertices[i], q = mesh.vertices[j];
      const bool crosses = (cross(c - a, p - a) > 0) != (cross(c - a, q - a) > 0) &&
                           (cross(q - p, a - p) > 0) != (cross(q - p, c - p) > 0);
      CHECK_FALSE(crosses);
    }
  }
}

}  // namespace animpak::test
