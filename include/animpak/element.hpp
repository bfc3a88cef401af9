// Spacetime elements (paper §3): art normalized to the unit square, offset outline, one triangulated
// slice with its edge classes and art binding, and the extrusion over n_s slices with time edges and
// envelope triangles. Vertex data is flat (structure of arrays); springs are a per-vertex CSR adjacency.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "animpak/geometry.hpp"
#include "animpak/io.hpp"
#include "animpak/params.hpp"
#include "animpak/spring_class.hpp"

namespace animpak {

/// Maps art coordinates onto the unit square: unit = (art - art_origin) * scale + unit_origin.
/// The art's bounding box is scaled uniformly so its longer side is 1 and centred in [0, 1]².
struct ArtFrame {
  Vec2 art_origin;
  Vec2 unit_origin;
  double scale = 1.0;
  Vec2 to_unit(Vec2 p) const { return (p - art_origin) * scale + unit_origin; }
  Vec2 to_art(Vec2 p) const { return (p - unit_origin) * (1.0 / scale) + art_origin; }
};

/// The art in unit-square coordinates, and the frame that took it there.
struct NormalizedArt {
  ArtShape art;
  ArtFrame frame;
};

/// Throws InputError (naming the art file) when the art has no drawable point or a zero-size box.
NormalizedArt normalize_art(const ArtShape& art);

/// Everything `art` paints, fills and strokes at their width, as one region: outer rings counter-clockwise
/// (positive signed area), holes clockwise, in the art's own coordinates.
std::vector<std::vector<Vec2>> painted_region(const ArtShape& art);

/// One of the disjoint pieces the art's offset outline comes in before they are bridged
/// (docs/parameters.md, "Bridging detached art").
struct OutlinePiece {
  double share = 0.0;      ///< of the area the art paints (fills, and strokes at their width)
  std::vector<int> paths;  ///< indices into the art's paths of those that paint in it (one may paint in several)
  bool dropped = false;    ///< farther than the largest closing bridges: outside the outline, its art still drawn
};

/// The element's outer outline: union of all paths, offset by `offset`, its pieces bridged into one.
struct Outline {
  std::vector<Vec2> ring;          ///< simple polygon, counter-clockwise in y-up terms, no repeat
  std::vector<std::string> notes;  ///< e.g. "dropped 2 pieces smaller than the largest"
  std::string source;              ///< the art file, named in build_slice's errors
  /// Every disjoint piece, largest first (the one the others are bridged to), when there are several;
  /// empty when the art is one piece.
  std::vector<OutlinePiece> pieces;
  double bridge_radius = 0.0;  ///< the closing that bridged pieces; 0 when none was needed or none reached
};
Outline element_outline(const NormalizedArt& art, double offset);

/// The region one art path paints when drawn with `points` (indexed like path.polylines) and
/// `stroke_width`: its fill under its fill rule, every closed subpath counting as filled (SVG fills open
/// subpaths too when the path has a fill), united with its stroke band (round joins and caps), the
/// band's arcs within `tolerance` of true circles. Disjoint rings under the non-zero rule, outer
/// rings counter-clockwise in y-up terms and holes clockwise, on a 1e-9 grid. element_outline offsets
/// the union of these; docs/quality.md measures frames with it.
std::vector<std::vector<Vec2>> painted_region(const ArtPath& path, const std::vector<std::vector<Vec2>>& points,
                                              double stroke_width, double tolerance);

/// Whether two segments of `line` that are not neighbours cross (the closing segment counts when it is
/// closed); false with fewer than four points.
bool crosses_itself(const Polyline& line);

using Edge = std::array<int, 2>;      ///< vertex ids, first < second
using Triangle = std::array<int, 3>;  ///< vertex ids, counter-clockwise in y-up terms

/// Where one art point sits in the slice: a triangle and barycentric coordinates (may be negative for
/// points outside every triangle, which bind to the nearest one by extrapolation).
struct BoundPoint {
  int triangle = 0;
  std::array<double, 3> weights{};
};

/// Bindings of every point of every polyline, indexed like ArtShape::paths[p].polylines[q].points[k].
struct ArtBinding {
  std::vector<std::vector<std::vector<BoundPoint>>> points;
};

/// One undeformed slice (paper Fig. 2c). Vertices [0, boundary_count) are the boundary samples in
/// polygon order; the rest are interior samples.
struct SliceMesh {
  std::vector<Vec2> vertices;
  int boundary_count = 0;
  std::vector<Triangle> triangles;
  std::vector<Edge> edges;                 ///< triangulation edges, unique
  std::vector<Edge> shear_edges;           ///< A–D across every interior edge BC of triangles ABC, BCD
  std::vector<Edge> negative_space_edges;  ///< from triangulating the negative space in the convex hull
};

/// Samples the outline and triangulates it (constrained Delaunay, CGAL). Deterministic for a seed.
SliceMesh build_slice(const Outline& outline, const Params& params, std::uint64_t seed);

/// Binds every art point to the slice. Replaying on `mesh.vertices` reproduces the art within 1e-6.
ArtBinding bind_art(const ArtShape& unit_art, const SliceMesh& mesh);

/// Positions of the bound art points for one set of slice vertex positions.
std::vector<std::vector<std::vector<Vec2>>> replay_art(const ArtBinding& binding, const SliceMesh& mesh,
                                                       const std::vector<Vec2>& positions);

/// Springs as a per-vertex adjacency (each spring appears once at each of its two ends).
struct SpringCsr {
  std::vector<int> offsets;    ///< vertex v's springs are [offsets[v], offsets[v+1])
  std::vector<int> neighbors;  ///< the other end
  std::vector<double> rest;    ///< rest length
  std::vector<SpringClass> classes;
  /// Springs of one class, each counted once.
  std::size_t count(SpringClass c) const;
  /// Builds the adjacency from an undirected list; rest lengths from `x`, `y`.
  static SpringCsr from_edges(int vertex_count, const std::vector<Edge>& edges, const std::vector<SpringClass>& classes,
                              const std::vector<double>& x, const std::vector<double>& y);
};

/// A slice mesh extruded over n_s slices (paper §3.1). Vertex v of slice s has id s * P + v.
struct SpacetimeElement {
  std::string name;
  NormalizedArt art;
  ArtBinding binding;
  SliceMesh slice;  ///< undeformed slice topology and rest positions
  int slice_count = 0;
  std::vector<double> x, y, t;     ///< animated positions of every vertex, slice-major
  SpringCsr springs;               ///< edge, shear and negative-space springs on every slice, plus time springs
  std::vector<Triangle> envelope;  ///< two time edges and one boundary edge each; vertex ids
  std::vector<std::string> notes;  ///< what building it changed, e.g. the outline's dropped pieces
  std::vector<OutlinePiece> outline_pieces;  ///< Outline::pieces
  double bridge_radius = 0.0;                ///< Outline::bridge_radius
  /// slice_advice of its script (include/animpak/animation.hpp): about the fewest slices that keep the curve
  /// between slices within 1 % of its size of the script (0: it barely moves), and the largest distance
  /// at slice_count, as a share of its size.
  int slices_needed = 0;
  double motion_error = 0.0;

  int vertices_per_slice() const { return static_cast<int>(slice.vertices.size()); }
  int vertex_count() const { return slice_count * vertices_per_slice(); }
  int id(int s, int v) const { return s * vertices_per_slice() + v; }
  Vec2 position(int s, int v) const { return {x[id(s, v)], y[id(s, v)]}; }
};

/// Stacks `per_slice[s]` (positions of every slice vertex at slice s, s = 0..n_s-1, at t = s/(n_s-1))
/// and adds time edges AC, AD, BC and envelope triangles between consecutive slice boundaries.
SpacetimeElement extrude(std::string name, NormalizedArt art, ArtBinding binding, SliceMesh slice,
                         const std::vector<std::vector<Vec2>>& per_slice);

}  // namespace animpak
