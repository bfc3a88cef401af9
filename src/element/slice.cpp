// Paper §3.1, Fig. 2b–c: one slice. Evenly spaced samples on the offset outline, Poisson-disk samples
// inside, a constrained Delaunay triangulation (CGAL; the only translation unit that includes it, because
// it compiles slowly), then the shear edges and the negative-space edges that brace the slice.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <string>

#include "animpak/element.hpp"
#include "animpak/error.hpp"

namespace animpak {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;  // sample index
using FaceInfo = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;      // nesting level
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel, FaceInfo>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// Constraints never cross in a simple polygon; if they do, CGAL throws instead of inventing a vertex.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::No_constraint_intersection_tag>;

// Interior samples keep this fraction of the interior spacing away from the boundary polygon, so no
// interior point sits close to a boundary edge and makes a sliver triangle.
constexpr double boundary_clearance = 0.6;
// Bridson's candidates per active sample.
constexpr int bridson_tries = 30;
// Smallest triangle area accepted (unit-square units²).
constexpr double min_triangle_area = 1e-12;

// Portable uniform double in [0, 1): the top 53 bits of the generator (std distributions differ between
// standard libraries, so they would break determinism across platforms).
double uniform(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

// `count` points evenly spaced by arc length around `ring`, whose perimeter is `length`.
std::vector<Vec2> resample(const std::vector<Vec2>& ring, double length, int count) {
  const std::size_t n = ring.size();
  std::vector<Vec2> out;
  out.reserve(static_cast<std::size_t>(count));
  std::size_t seg = 0;
  double seg_start = 0.0;  // arc length at ring[seg]
  for (int k = 0; k < count; ++k) {
    const double s = length * k / count;
    while (seg + 1 < n && seg_start + norm(ring[seg + 1] - ring[seg]) <= s) {
      seg_start += norm(ring[seg + 1] - ring[seg]);
      ++seg;
    }
    const Vec2 a = ring[seg], b = ring[(seg + 1) % n];
    const double len = norm(b - a);
    out.push_back(len > 0.0 ? a + (b - a) * ((s - seg_start) / len) : a);
  }
  return out;
}

// Bridson Poisson-disk sampling over the boundary's box; samples are then kept only when inside the
// boundary polygon and clear of it.
std::vector<Vec2> interior_samples(const std::vector<Vec2>& boundary, double spacing, std::uint64_t seed) {
  Box box;
  for (Vec2 p : boundary) box.add(p);
  const double cell = spacing / std::sqrt(2.0);
  const int nx = static_cast<int>(std::ceil(box.width() / cell)) + 1;
  const int ny = static_cast<int>(std::ceil(box.height() / cell)) + 1;
  std::vector<int> grid(static_cast<std::size_t>(nx) * ny, -1);
  std::vector<Vec2> points;
  std::vector<std::size_t> active;
  std::mt19937_64 rng(seed);
  auto cell_of = [&](Vec2 p) {
    return std::pair{std::clamp(static_cast<int>((p.x - box.min.x) / cell), 0, nx - 1),
                     std::clamp(static_cast<int>((p.y - box.min.y) / cell), 0, ny - 1)};
  };
  auto accept = [&](Vec2 p) {
    if (p.x < box.min.x || p.x > box.max.x || p.y < box.min.y || p.y > box.max.y) return false;
    const auto [cx, cy] = cell_of(p);
    for (int gy = std::max(0, cy - 2); gy <= std::min(ny - 1, cy + 2); ++gy)
      for (int gx = std::max(0, cx - 2); gx <= std::min(nx - 1, cx + 2); ++gx) {
        const int q = grid[static_cast<std::size_t>(gy) * nx + gx];
        if (q >= 0 && norm(points[q] - p) < spacing) return false;
      }
    grid[static_cast<std::size_t>(cy) * nx + cx] = static_cast<int>(points.size());
    active.push_back(points.size());
    points.push_back(p);
    return true;
  };
  accept({box.min.x + uniform(rng) * box.width(), box.min.y + uniform(rng) * box.height()});
  while (!active.empty()) {
    const std::size_t slot = static_cast<std::size_t>(rng() % active.size());
    const Vec2 centre = points[active[slot]];
    bool found = false;
    for (int k = 0; k < bridson_tries && !found; ++k) {
      const double angle = 2.0 * std::numbers::pi * uniform(rng);
      const double radius = spacing * (1.0 + uniform(rng));
      found = accept(centre + Vec2{std::cos(angle), std::sin(angle)} * radius);
    }
    if (!found) {
      active[slot] = active.back();
      active.pop_back();
    }
  }
  std::vector<Vec2> kept;
  for (Vec2 p : points)
    if (ring_contains(boundary, p) && ring_distance(boundary, p) > boundary_clearance * spacing) kept.push_back(p);
  return kept;
}

// Nesting level of every face: 0 for the unbounded side, +1 across each constrained edge. With one simple
// constrained polygon, level 1 is the slice's domain and finite level-0 faces fill the negative space of
// the convex hull.
void mark_nesting(Cdt& cdt) {
  for (Cdt::Face_handle f : cdt.all_face_handles()) f->info() = -1;
  std::vector<Cdt::Face_handle> frontier{cdt.infinite_face()};
  for (int level = 0; !frontier.empty(); ++level) {
    std::vector<Cdt::Face_handle> next;
    while (!frontier.empty()) {
      const Cdt::Face_handle f = frontier.back();
      frontier.pop_back();
      if (f->info() != -1) continue;
      f->info() = level;
      for (int i = 0; i < 3; ++i) {
        const Cdt::Face_handle g = f->neighbor(i);
        if (g->info() != -1) continue;
        (cdt.is_constrained(Cdt::Edge(f, i)) ? next : frontier).push_back(g);
      }
    }
    frontier = std::move(next);
  }
}

Edge make_edge(int a, int b) {
  return a < b ? Edge{a, b} : Edge{b, a};
}

// Triangle with its smallest vertex first, cyclic order (and so orientation) kept.
Triangle canonical(Triangle t) {
  while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
  return t;
}

// Triangulates boundary + interior samples; false when the boundary polygon is not simple at this
// sampling (a constraint crosses another or runs through a vertex).
bool triangulate(SliceMesh& mesh) {
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles;
  const int count = static_cast<int>(mesh.vertices.size());
  for (int i = 0; i < count; ++i) {
    handles.push_back(cdt.insert(Kernel::Point_2(mesh.vertices[i].x, mesh.vertices[i].y)));
    handles.back()->info() = i;
  }
  if (static_cast<int>(cdt.number_of_vertices()) != count) return false;
  const int b = mesh.boundary_count;
  try {
    for (int i = 0; i < b; ++i) cdt.insert_constraint(handles[i], handles[(i + 1) % b]);
  } catch (const std::exception&) {
    return false;
  }
  if (static_cast<int>(cdt.number_of_vertices()) != count) return false;
  for (int i = 0; i < b; ++i)
    if (!cdt.is_edge(handles[i], handles[(i + 1) % b])) return false;
  mark_nesting(cdt);

  std::vector<Triangle> outside;
  for (Cdt::Face_handle f : cdt.finite_face_handles()) {
    const Triangle t = canonical({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
    if (f->info() % 2 == 1)
      mesh.triangles.push_back(t);
    else if (f->info() == 0)
      outside.push_back(t);
    else
      return false;  // a nested level means the polygon wound around twice: not simple
  }
  std::sort(mesh.triangles.begin(), mesh.triangles.end());
  for (const Triangle& t : mesh.triangles) {
    const Vec2 p = mesh.vertices[t[0]], q = mesh.vertices[t[1]], r = mesh.vertices[t[2]];
    if (0.5 * cross(q - p, r - p) <= min_triangle_area) return false;
  }

  std::map<Edge, std::vector<int>> opposite;  // edge -> the vertices opposite it in its triangles
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) opposite[make_edge(t[k], t[(k + 1) % 3])].push_back(t[(k + 2) % 3]);
  std::set<Edge> edges;
  for (const auto& [e, opp] : opposite) edges.insert(e);
  mesh.edges.assign(edges.begin(), edges.end());

  // §3.1: "if two triangles ABC and BCD share edge BC, then we add a shear edge connecting A and D".
  std::set<Edge> shear;
  for (const auto& [e, opp] : opposite)
    if (opp.size() == 2 && !edges.count(make_edge(opp[0], opp[1]))) shear.insert(make_edge(opp[0], opp[1]));
  mesh.shear_edges.assign(shear.begin(), shear.end());

  // §3.1: "we triangulate the negative space inside the convex hull"; the constrained Delaunay
  // triangulation restricted to the hull minus the outline is exactly that triangulation, since every
  // interior sample is hidden from it behind the constrained boundary.
  std::set<Edge> negative;
  for (const Triangle& t : outside)
    for (int k = 0; k < 3; ++k) {
      const Edge e = make_edge(t[k], t[(k + 1) % 3]);
      if (!edges.count(e)) negative.insert(e);
    }
  mesh.negative_space_edges.assign(negative.begin(), negative.end());
  return true;
}

}  // namespace

SliceMesh build_slice(const Outline& outline, const Params& params, std::uint64_t seed) {
  const std::size_t n = outline.ring.size();
  const std::string name = outline.source.empty() ? std::string("<outline>") : outline.source;
  if (n < 3 || !(std::fabs(signed_area(outline.ring)) > 0.0))
    throw InputError(name + ": the element's outline has fewer than three points or no area");
  if (!(params.boundary_spacing > 0.0) || !(params.interior_spacing > 0.0))
    throw InputError(name + ": boundary_spacing and interior_spacing must be positive");
  const double length = perimeter(outline.ring);
  // §3.1 "evenly-spaced samples around the outer boundary": the count is rounded so the spacing along
  // the outline is exactly perimeter / count.
  int count = std::max(3, static_cast<int>(std::lround(length / params.boundary_spacing)));
  // A coarse sampling can cut across a narrow neck and make the boundary polygon cross itself; refine
  // until it is simple (a few rounds at most for any outline offset by Δs).
  for (int attempt = 0; attempt < 12; ++attempt) {
    SliceMesh mesh;
    mesh.vertices = resample(outline.ring, length, count);
    mesh.boundary_count = count;
    const std::vector<Vec2> interior = interior_samples(mesh.vertices, params.interior_spacing, seed);
    mesh.vertices.insert(mesh.vertices.end(), interior.begin(), interior.end());
    if (triangulate(mesh)) return mesh;
    count = count + std::max(1, count / 4);
  }
  throw InputError(name + ": could not triangulate the element's outline (" + std::to_string(n) +
                   " points, perimeter " + std::to_string(length) + "); it may be degenerate");
}

}  // namespace animpak
