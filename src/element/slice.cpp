// Paper §3.1, Fig. 2b–c: one slice. Samples on the offset outline (evenly spaced, refined at tips), Poisson-disk samples
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
double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// The outline parametrized by arc length from ring[0]: arc[i] is the arc length at ring[i].
struct ArcRing {
  const std::vector<Vec2>& ring;
  std::vector<double> arc;
  double length = 0.0;

  explicit ArcRing(const std::vector<Vec2>& r) : ring(r) {
    arc.reserve(ring.size());
    for (std::size_t i = 0; i < ring.size(); ++i) {
      arc.push_back(length);
      length += norm(ring[(i + 1) % ring.size()] - ring[i]);
    }
  }

  Vec2 at(double s) const {
    const std::size_t i = static_cast<std::size_t>(std::upper_bound(arc.begin(), arc.end(), s) - arc.begin()) - 1;
    const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
    const double len = norm(b - a);
    return len > 0.0 ? a + (b - a) * ((s - arc[i]) / len) : a;
  }
};

// docs/parameters.md "Sampling the outline": the boundary samples, as arc lengths in [0, length). The
// paper's evenly spaced samples cut the round caps that the offset puts on the art's tips; here the
// outline is simplified as by Douglas–Peucker (every outline point within `tolerance` of its chord), and
// a chord longer than `spacing` is cut into equal arcs, so straight runs keep the paper's even spacing.
// The span from ring[0] to the outline point farthest from it and the span back start the subdivision.
std::vector<double> boundary_samples(const ArcRing& outline, double spacing, double tolerance) {
  const std::vector<Vec2>& ring = outline.ring;
  std::size_t far = 0;
  for (std::size_t i = 1; i < ring.size(); ++i)
    if (norm(ring[i] - ring[0]) > norm(ring[far] - ring[0])) far = i;
  // Spans still to settle; the last is the next along the outline, so samples come out in order.
  std::vector<std::pair<double, double>> spans{{outline.arc[far], outline.length}, {0.0, outline.arc[far]}};
  std::vector<double> samples;
  while (!spans.empty()) {
    const auto [a, b] = spans.back();
    spans.pop_back();
    const Vec2 p = outline.at(a), q = outline.at(b);
    // The outline point strictly inside the span farthest from the chord, if farther than the tolerance.
    double worst = tolerance, split = a;
    const auto first = std::upper_bound(outline.arc.begin(), outline.arc.end(), a);
    const auto last = std::lower_bound(outline.arc.begin(), outline.arc.end(), b);
    for (auto it = first; it < last; ++it) {
      const double d = segment_distance(ring[static_cast<std::size_t>(it - outline.arc.begin())], p, q);
      if (d > worst) worst = d, split = *it;
    }
    if (split > a) {
      spans.push_back({split, b});
      spans.push_back({a, split});
      continue;
    }
    // Equal arcs no longer than `spacing`, so no chord is either.
    const int parts = static_cast<int>(std::ceil((b - a) / spacing));
    if (norm(q - p) > spacing && parts > 1) {
      for (int k = parts; k-- > 0;)
        spans.push_back({a + (b - a) * k / parts, k + 1 == parts ? b : a + (b - a) * (k + 1) / parts});
      continue;
    }
    samples.push_back(a);
  }
  return samples;
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

Edge make_edge(int a, int b) { return a < b ? Edge{a, b} : Edge{b, a}; }

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
  if (!(params.element.boundary_spacing > 0.0) || !(params.element.interior_spacing > 0.0))
    throw InputError(name + ": boundary_spacing and interior_spacing must be positive");
  if (!(params.element.boundary_tolerance > 0.0)) throw InputError(name + ": boundary_tolerance must be positive");
  const ArcRing arc_ring(outline.ring);
  double spacing = params.element.boundary_spacing, tolerance = params.element.boundary_tolerance;
  // A sampling can still cut across a neck narrower than the tolerance and make the boundary polygon
  // cross itself; refine until it is simple (a few rounds at most for any outline offset by Δs).
  for (int attempt = 0; attempt < 12; ++attempt) {
    SliceMesh mesh;
    for (double s : boundary_samples(arc_ring, spacing, tolerance)) mesh.vertices.push_back(arc_ring.at(s));
    mesh.boundary_count = static_cast<int>(mesh.vertices.size());
    const std::vector<Vec2> interior = interior_samples(mesh.vertices, params.element.interior_spacing, seed);
    mesh.vertices.insert(mesh.vertices.end(), interior.begin(), interior.end());
    if (mesh.boundary_count >= 3 && triangulate(mesh)) return mesh;
    spacing *= 0.8;
    tolerance *= 0.5;
  }
  throw InputError(name + ": could not triangulate the element's outline (" + std::to_string(n) +
                   " points, perimeter " + std::to_string(arc_ring.length) + "); it may be degenerate");
}

}  // namespace animpak
