// Paper §3.1, Fig. 2d–e: n_s copies of the slice at t = (i-1)/(n_s-1), stitched by time edges AC, AD,
// BC between corresponding boundary edges AB and CD of consecutive slices; the boundary edges and the
// time edges AC, BC form the envelope triangle mesh. Everything is ordered slice-major, then as in the
// slice's own lists, so solver backends see the same spring and triangle order.
#include <string>

#include "animpak/element.hpp"
#include "animpak/error.hpp"

namespace animpak {

SpacetimeElement extrude(std::string name, NormalizedArt art, ArtBinding binding, SliceMesh slice,
                         const std::vector<std::vector<Vec2>>& per_slice) {
  const int slices = static_cast<int>(per_slice.size());
  const int per = static_cast<int>(slice.vertices.size());
  const int b_count = slice.boundary_count;
  const std::string where = name + " (" + art.art.source.string() + ")";
  if (slices < 2) throw InputError(where + ": an element needs at least two slices, got " + std::to_string(slices));
  if (b_count < 3 || b_count > per)
    throw InputError(where + ": the slice has " + std::to_string(b_count) + " boundary vertices of " +
                     std::to_string(per));
  for (int s = 0; s < slices; ++s)
    if (static_cast<int>(per_slice[s].size()) != per)
      throw InputError(where + ": slice " + std::to_string(s) + " has " + std::to_string(per_slice[s].size()) +
                       " positions, the slice mesh has " + std::to_string(per) + " vertices");

  SpacetimeElement e;
  e.name = std::move(name);
  e.art = std::move(art);
  e.binding = std::move(binding);
  e.slice = std::move(slice);
  e.slice_count = slices;
  const std::size_t total = static_cast<std::size_t>(slices) * per;
  e.x.reserve(total);
  e.y.reserve(total);
  e.t.reserve(total);
  for (int s = 0; s < slices; ++s) {
    // §3.1: slice s_i sits at time (i-1)/(n_s-1); computed from the index so the ends are exactly 0 and 1.
    const double t = static_cast<double>(s) / (slices - 1);
    for (const Vec2 p : per_slice[s]) {
      e.x.push_back(p.x);
      e.y.push_back(p.y);
      e.t.push_back(t);
    }
  }

  const SliceMesh& m = e.slice;
  std::vector<Edge> edges;
  std::vector<SpringClass> classes;
  const std::size_t slice_springs = m.edges.size() + m.shear_edges.size() + m.negative_space_edges.size();
  edges.reserve(slices * slice_springs + 3 * static_cast<std::size_t>(b_count) * (slices - 1));
  auto add = [&](int a, int b, SpringClass c) {
    edges.push_back(a < b ? Edge{a, b} : Edge{b, a});
    classes.push_back(c);
  };
  e.envelope.reserve(2 * static_cast<std::size_t>(b_count) * (slices - 1));
  for (int s = 0; s < slices; ++s) {
    for (const Edge& d : m.edges) add(e.id(s, d[0]), e.id(s, d[1]), SpringClass::edge);
    for (const Edge& d : m.shear_edges) add(e.id(s, d[0]), e.id(s, d[1]), SpringClass::shear);
    for (const Edge& d : m.negative_space_edges) add(e.id(s, d[0]), e.id(s, d[1]), SpringClass::negative_space);
    if (s + 1 == slices) continue;
    for (int b = 0; b < b_count; ++b) {
      const int next = (b + 1) % b_count;
      // AB = (b, b+1) on slice s, CD the same edge on slice s+1.
      const int a = e.id(s, b), bb = e.id(s, next), c = e.id(s + 1, b), d = e.id(s + 1, next);
      add(a, c, SpringClass::time);
      add(a, d, SpringClass::time);
      add(bb, c, SpringClass::time);
      // Fig. 2e: the envelope's triangles are a boundary edge plus two time edges (AC, BC and BD, the
      // next boundary vertex's AC).
      e.envelope.push_back({a, bb, c});
      e.envelope.push_back({bb, d, c});
    }
  }
  e.springs = SpringCsr::from_edges(static_cast<int>(total), edges, classes, e.x, e.y);
  return e;
}

}  // namespace animpak
