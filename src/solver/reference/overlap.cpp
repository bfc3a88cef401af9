// Overlap test and force, paper Eq. 3 (§5): a boundary vertex that penetrates another element is pushed
// out, and its slice stops growing (§5.3). The paper finds penetrations through the collision grid's
// near block; that misses a vertex more than one cell deep and an edge that crosses another element's
// outline with neither end inside (thin parts: tails, legs). Here every boundary vertex is tested against
// every other element whose boundary polygon, on its curve at the vertex's t (include/animpak/curve.hpp), can reach it (a
// box test first), whatever the depth, and its boundary edge is tested for crossings on the same walk;
// so are interval_points times inside the slice intervals on either side of it.
// Which elements the box test can accept comes from a broadphase rebuilt every step (OverlapGrid,
// docs/architecture.md, "The overlap test"): an (x, y, t) cell grid over the slice pairs' boxes, so a
// query tries only the elements listed in the cells its edge's box meets, in increasing element order
// as a walk over every element would; the results are the same bits, at a cost per vertex that does
// not grow with the element count.
// The force adds to Eq. 3 a pull towards the other element's outline that grows with depth
// (docs/parameters.md, "Overlaps").
#include <algorithm>
#include <cmath>

#include "../counting_sort.hpp"
#include "animpak/reference/overlap.hpp"
#include "animpak/reference/segments.hpp"

namespace animpak::reference {

namespace {

// Slices are stacked along t; a slice's t is its first vertex's t (simultaneity keeps the slice's
// vertices at one t after every step).
float slice_t(const Topology& topo, const SimState& state, std::int32_t s) { return state.t[topo.slice_begin[s]]; }

}  // namespace

void slice_boxes(const Topology& topo, const SimState& state, const CurveTangents& tangents, SliceBoxes& out) {
  const std::int32_t slices = topo.slice_count();
  out.x0.assign(slices, 0.0f);
  out.y0.assign(slices, 0.0f);
  out.x1.assign(slices, 0.0f);
  out.y1.assign(slices, 0.0f);
  out.t.assign(slices, 0.0f);
  const bool spline = tangents.mode == curve_spline;
  for (std::int32_t s = 0; s < slices; ++s) {
    out.t[s] = slice_t(topo, state, s);
    const std::int32_t lo = topo.slice_begin[s], count = topo.slice_boundary[s];
    if (count == 0) continue;
    float x0 = state.x[lo], x1 = x0, y0 = state.y[lo], y1 = y0;
    for (std::int32_t v = lo + 1; v < lo + count; ++v) {
      x0 = state.x[v] < x0 ? state.x[v] : x0;
      x1 = state.x[v] > x1 ? state.x[v] : x1;
      y0 = state.y[v] < y0 ? state.y[v] : y0;
      y1 = state.y[v] > y1 ? state.y[v] : y1;
    }
    if (spline) {
      // The handles towards the slice before and after within the element: the steps as the overlap
      // test's curve_basis takes them (t of the upper slice minus t of the lower).
      const std::int32_t e = topo.slice_element[s];
      for (const std::int32_t q : {s - 1, s + 1}) {
        if (q < topo.element_slice_begin[e] || q >= topo.element_slice_begin[e + 1]) continue;
        const float h = q > s ? slice_t(topo, state, q) - out.t[s] : -(out.t[s] - slice_t(topo, state, q));
        for (std::int32_t v = lo; v < lo + count; ++v) {
          const float hx = curve_handle(state.x[v], tangents.x[v], h), hy = curve_handle(state.y[v], tangents.y[v], h);
          x0 = hx < x0 ? hx : x0;
          x1 = hx > x1 ? hx : x1;
          y0 = hy < y0 ? hy : y0;
          y1 = hy > y1 ? hy : y1;
        }
      }
    }
    out.x0[s] = x0, out.y0[s] = y0, out.x1[s] = x1, out.y1[s] = y1;
  }
}

namespace {

// A pair's box: the union of its two slices' boxes (exactly what overlap_point tests) and its t range.
struct PairBox {
  float x0, y0, x1, y1, t0, t1;
};

PairBox pair_box(const SliceBoxes& boxes, std::int32_t s) {
  return {std::min(boxes.x0[s], boxes.x0[s + 1]), std::min(boxes.y0[s], boxes.y0[s + 1]),
          std::max(boxes.x1[s], boxes.x1[s + 1]), std::max(boxes.y1[s], boxes.y1[s + 1]),
          std::min(boxes.t[s], boxes.t[s + 1]),   std::max(boxes.t[s], boxes.t[s + 1])};
}

// The grid's cells per axis are capped so that a far-flung world does not make the cell table larger
// than the pair lists it indexes.
constexpr std::int32_t overlap_grid_max_axis = 1024;

}  // namespace

void build_overlap_grid(const Topology& topo, const SliceBoxes& boxes, OverlapGrid& grid) {
  grid.nx = grid.ny = grid.nt = 0;
  grid.cell_start.assign(1, 0);
  grid.elements.clear();
  // The pairs of every element with two slices or more, named by their lower slice: increasing slice
  // order is increasing element order.
  std::vector<std::int32_t> pairs, owner;
  for (std::int32_t e = 0; e < topo.element_count(); ++e)
    for (std::int32_t s = topo.element_slice_begin[e]; s + 1 < topo.element_slice_begin[e + 1]; ++s) {
      pairs.push_back(s);
      owner.push_back(e);
    }
  if (pairs.empty()) return;
  // The grid spans the pairs' boxes; its cell is their mean extent, so a box meets a few cells. A box
  // that is not finite (a blown-up state) leaves the grid without cells: every query then tries every
  // element, as the box test, which a NaN never fails, would (and an infinite span could not be cut
  // into cells: the doubling below would never end).
  PairBox all = pair_box(boxes, pairs.front());
  double w = 0.0, h = 0.0, d = 0.0;
  for (const std::int32_t s : pairs) {
    const PairBox b = pair_box(boxes, s);
    if (!std::isfinite(b.x0) || !std::isfinite(b.y0) || !std::isfinite(b.x1) || !std::isfinite(b.y1) ||
        !std::isfinite(b.t0) || !std::isfinite(b.t1))
      return;
    all = {std::min(all.x0, b.x0), std::min(all.y0, b.y0), std::max(all.x1, b.x1),
           std::max(all.y1, b.y1), std::min(all.t0, b.t0), std::max(all.t1, b.t1)};
    w += static_cast<double>(b.x1) - b.x0;
    h += static_cast<double>(b.y1) - b.y0;
    d += static_cast<double>(b.t1) - b.t0;
  }
  const double count = static_cast<double>(pairs.size());
  const double span_x = static_cast<double>(all.x1) - all.x0, span_y = static_cast<double>(all.y1) - all.y0,
               span_t = static_cast<double>(all.t1) - all.t0;
  double cell = std::max(w, h) / count, cell_t = d / count;
  if (!(cell > 0.0)) cell = std::max({span_x, span_y, 1.0});
  if (!(cell_t > 0.0)) cell_t = std::max(span_t, 1.0);
  const auto axis = [](double span, double edge) {
    return static_cast<std::int32_t>(std::min<double>(overlap_grid_max_axis, std::floor(span / edge) + 1.0));
  };
  // Never more cells than a few per pair: a sparse world gets coarser cells.
  while (static_cast<double>(axis(span_x, cell)) * axis(span_y, cell) * axis(span_t, cell_t) > 8.0 * count + 64.0)
    cell *= 2.0, cell_t *= 2.0;
  grid.x0 = all.x0, grid.y0 = all.y0, grid.t0 = all.t0;
  grid.cell = static_cast<float>(cell), grid.cell_t = static_cast<float>(cell_t);
  grid.nx = axis(span_x, cell), grid.ny = axis(span_y, cell), grid.nt = axis(span_t, cell_t);

  // Every pair in every cell its box meets, pairs in increasing order; the stable sort keeps that
  // order within a cell, and a cell lists an element once, though several of its pairs may meet it.
  std::vector<std::int32_t> entry_cell, entry_element;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const PairBox b = pair_box(boxes, pairs[i]);
    const std::int32_t ix0 = grid_axis_cell(b.x0 - grid.x0, grid.cell, grid.nx),
                       ix1 = grid_axis_cell(b.x1 - grid.x0, grid.cell, grid.nx);
    const std::int32_t iy0 = grid_axis_cell(b.y0 - grid.y0, grid.cell, grid.ny),
                       iy1 = grid_axis_cell(b.y1 - grid.y0, grid.cell, grid.ny);
    const std::int32_t it0 = grid_axis_cell(b.t0 - grid.t0, grid.cell_t, grid.nt),
                       it1 = grid_axis_cell(b.t1 - grid.t0, grid.cell_t, grid.nt);
    const std::int32_t e = owner[i];
    for (std::int32_t it = it0; it <= it1; ++it)
      for (std::int32_t iy = iy0; iy <= iy1; ++iy)
        for (std::int32_t ix = ix0; ix <= ix1; ++ix) {
          entry_cell.push_back((it * grid.ny + iy) * grid.nx + ix);
          entry_element.push_back(e);
        }
  }
  const std::int32_t cells = grid.nx * grid.ny * grid.nt;
  std::vector<std::int32_t> start, order;
  counting_sort(entry_cell, cells, start, order);
  // Within a cell an element's entries are adjacent: keep the first.
  grid.cell_start.assign(static_cast<std::size_t>(cells) + 1, 0);
  grid.elements.reserve(order.size());
  for (std::int32_t c = 0; c < cells; ++c) {
    for (std::int32_t i = start[c]; i < start[c + 1]; ++i) {
      const std::int32_t e = entry_element[order[i]];
      if (i == start[c] || e != grid.elements.back()) grid.elements.push_back(e);
    }
    grid.cell_start[c + 1] = static_cast<std::int32_t>(grid.elements.size());
  }
}

void overlap_candidates(const OverlapGrid& grid, std::int32_t elements, float ex0, float ex1, float ey0, float ey1,
                        float pt, std::vector<std::int32_t>& out) {
  out.clear();
  // The cells the query's box meets, at pt's cell in t: a pair whose box passes the box test around pt
  // is listed in one of them (the cell of a point in both boxes; the cell of a coordinate never
  // decreases as the coordinate grows, and clamping keeps that).
  bool every =
      grid.nx == 0 || std::isnan(ex0) || std::isnan(ex1) || std::isnan(ey0) || std::isnan(ey1) || std::isnan(pt);
  std::int32_t begin[4], end[4], lists = 0;
  if (!every) {
    const std::int32_t ix0 = grid_axis_cell(ex0 - grid.x0, grid.cell, grid.nx),
                       ix1 = grid_axis_cell(ex1 - grid.x0, grid.cell, grid.nx);
    const std::int32_t iy0 = grid_axis_cell(ey0 - grid.y0, grid.cell, grid.ny),
                       iy1 = grid_axis_cell(ey1 - grid.y0, grid.cell, grid.ny);
    const std::int32_t it = grid_axis_cell(pt - grid.t0, grid.cell_t, grid.nt);
    // An edge longer than a cell (rare: the cell is a mean box's extent) tries every element.
    every = (ix1 - ix0 + 1) * (iy1 - iy0 + 1) > 4;
    for (std::int32_t iy = iy0; !every && iy <= iy1; ++iy)
      for (std::int32_t ix = ix0; ix <= ix1; ++ix, ++lists) {
        const std::int32_t c = (it * grid.ny + iy) * grid.nx + ix;
        begin[lists] = grid.cell_start[c];
        end[lists] = grid.cell_start[c + 1];
      }
  }
  if (every) {
    for (std::int32_t e = 0; e < elements; ++e) out.push_back(e);
    return;
  }
  // Merge the cells' increasing lists: the smallest element above the last one taken, until none is left.
  for (std::int32_t last = -1;;) {
    std::int32_t next = elements;
    for (std::int32_t l = 0; l < lists; ++l) {
      while (begin[l] < end[l] && grid.elements[begin[l]] <= last) ++begin[l];
      if (begin[l] < end[l] && grid.elements[begin[l]] < next) next = grid.elements[begin[l]];
    }
    if (next == elements) return;
    out.push_back(next);
    last = next;
  }
}

namespace {

// Vertex k's position on its curve at weights b between the slices whose first vertices are lo and hi.
void curve_point(const SimState& state, const CurveTangents& m, std::int32_t lo, std::int32_t hi, std::int32_t k,
                 const CurveBasis<float>& b, float& x, float& y) {
  x = curve_value(state.x[lo + k], state.x[hi + k], m.x[lo + k], m.x[hi + k], b);
  y = curve_value(state.y[lo + k], state.y[hi + k], m.y[lo + k], m.y[hi + k], b);
}

// Edge i → i + 1 (wrapping at `edges`) of the boundary polygon on the curve at weights b between the
// slices whose first vertices are lo and hi.
void overlap_edge(const SimState& state, const CurveTangents& m, std::int32_t lo, std::int32_t hi, std::int32_t i,
                  std::int32_t edges, const CurveBasis<float>& b, float& ax, float& ay, float& bx, float& by) {
  const std::int32_t j = i + 1 == edges ? 0 : i + 1;
  curve_point(state, m, lo, hi, i, b, ax, ay);
  curve_point(state, m, lo, hi, j, b, bx, by);
}

// What one query point found: a point p at time pt, with its boundary edge p → n.
struct PointOverlap {
  bool overlap = false, inside = false;
  bool yield = false;          // one of the elements overlapped is no larger (g) than own_g
  bool block = false;          // one of the elements overlapped does not give way to own
  float near2 = 0.0f;          // when inside: squared distance to the nearest way out
  float qx = 0.0f, qy = 0.0f;  // that way out, a point of the other element's outline
};

// Element e's slice pair around pt, searched from slice index `start` (slices stay near their rest times),
// whose boxes meet the query box: its lower global slice, with w the weight of pt between the two (0 for
// a flat pair, which takes the lower slice's polygon); -1 when pt is outside the pair or the boxes miss.
std::int32_t overlap_slice_pair(const Topology& topo, const SimState& state, const SliceBoxes& boxes, std::int32_t e,
                                std::int32_t start, float pt, float ex0, float ex1, float ey0, float ey1, float& w) {
  const std::int32_t first = topo.element_slice_begin[e], count = topo.element_slice_begin[e + 1] - first;
  if (count < 2) return -1;
  std::int32_t k = std::min(start, count - 2);
  while (k > 0 && pt < slice_t(topo, state, first + k)) --k;
  while (k < count - 2 && pt > slice_t(topo, state, first + k + 1)) ++k;
  const std::int32_t s = first + k;
  const float t0 = slice_t(topo, state, s), t1 = slice_t(topo, state, s + 1);
  if (!(std::min(t0, t1) <= pt && pt <= std::max(t0, t1))) return -1;
  // The interpolated polygon lies in the union of the two slices' boxes.
  const float bx0 = std::min(boxes.x0[s], boxes.x0[s + 1]), bx1 = std::max(boxes.x1[s], boxes.x1[s + 1]);
  const float by0 = std::min(boxes.y0[s], boxes.y0[s + 1]), by1 = std::max(boxes.y1[s], boxes.y1[s + 1]);
  if (ex1 < bx0 || ex0 > bx1 || ey1 < by0 || ey0 > by1) return -1;
  w = t1 != t0 ? (pt - t0) / (t1 - t0) : 0.0f;
  return s;
}

// The polygon at weights b between the slices whose first vertices are lo and hi, edge by edge: the
// even-odd test of p, and whether the query edge p → n properly crosses one of its edges (touching does
// not count), tried only until one is found and only where the two edges' boxes meet (disjoint boxes
// cannot cross).
void overlap_polygon_walk(const SimState& state, const CurveTangents& m, std::int32_t lo, std::int32_t hi,
                          std::int32_t edges, const CurveBasis<float>& b, float px, float py, float nx, float ny,
                          float ex0, float ex1, float ey0, float ey1, bool& inside, bool& crosses) {
  inside = false;
  crosses = false;
  for (std::int32_t i = 0; i < edges; ++i) {
    float ax, ay, bx, by;
    overlap_edge(state, m, lo, hi, i, edges, b, ax, ay, bx, by);
    if (ray_crosses_segment(px, py, ax, ay, bx, by)) inside = !inside;
    if (!crosses && std::max(ax, bx) >= ex0 && std::min(ax, bx) <= ex1 && std::max(ay, by) >= ey0 &&
        std::min(ay, by) <= ey1 && segments_cross_properly(px, py, nx, ny, ax, ay, bx, by))
      crosses = true;
  }
}

// The way out of a point inside that polygon: its nearest outline point (qx, qy), the first edge reaching
// the minimum winning; returns the squared distance.
float overlap_way_out(const SimState& state, const CurveTangents& m, std::int32_t lo, std::int32_t hi,
                      std::int32_t edges, const CurveBasis<float>& b, float px, float py, float& qx, float& qy) {
  float near2 = std::numeric_limits<float>::infinity();
  qx = px;
  qy = py;
  for (std::int32_t i = 0; i < edges; ++i) {
    float ax, ay, bx, by, cx, cy;
    overlap_edge(state, m, lo, hi, i, edges, b, ax, ay, bx, by);
    const float d2 = closest_point_on_segment(px, py, ax, ay, bx, by, cx, cy);
    if (d2 < near2) near2 = d2, qx = cx, qy = cy;
  }
  return near2;
}

// The query point against every element but `own` that the broadphase lists, in increasing order, each
// one's slice pair around pt searched from slice index `start` of that element.
PointOverlap overlap_point(const Topology& topo, const SimState& state, const SliceBoxes& boxes,
                           const OverlapGrid& grid, const CurveTangents& m, std::int32_t own, float own_g,
                           std::int32_t start, float px, float py, float pt, float nx, float ny) {
  PointOverlap r;
  const bool own_secondary = topo.secondary(own);
  const float ex0 = std::min(px, nx), ex1 = std::max(px, nx), ey0 = std::min(py, ny), ey1 = std::max(py, ny);
  // Reused across calls: three queries per boundary vertex.
  thread_local std::vector<std::int32_t> candidates;
  overlap_candidates(grid, topo.element_count(), ex0, ex1, ey0, ey1, pt, candidates);
  for (const std::int32_t e : candidates) {
    if (e == own) continue;
    float w;
    const std::int32_t s = overlap_slice_pair(topo, state, boxes, e, start, pt, ex0, ex1, ey0, ey1, w);
    if (s < 0) continue;
    const std::int32_t lo = topo.slice_begin[s], hi = topo.slice_begin[s + 1], edges = topo.slice_boundary[s];
    const CurveBasis<float> b = curve_basis(w, state.t[hi] - state.t[lo], m.mode);
    bool inside, crosses;
    overlap_polygon_walk(state, m, lo, hi, edges, b, px, py, nx, ny, ex0, ex1, ey0, ey1, inside, crosses);
    // Only a point inside needs its way out: a second walk, since most elements tried are near and not
    // entered.
    float qx = px, qy = py;
    const float near2 =
        inside ? overlap_way_out(state, m, lo, hi, edges, b, px, py, qx, qy) : std::numeric_limits<float>::infinity();
    if (crosses) r.overlap = true;
    // The larger of two overlapping slices yields (docs/parameters.md, "Growth"): e's g at pt, straight
    // between its two slices. A secondary element gives way to a primary one whatever their
    // sizes ("Secondary elements"): it blocks and yields to it, never the other way round.
    const bool other_secondary = topo.secondary(e);
    if ((crosses || inside) && !(other_secondary && !own_secondary)) {
      r.block = true;
      if ((own_secondary && !other_secondary) ||
          !(state.growth[s] + (state.growth[s + 1] - state.growth[s]) * w > own_g))
        r.yield = true;
    }
    // Inside several elements: the nearest way out, the first element reaching it wins.
    if (inside && (!r.inside || near2 < r.near2)) {
      r.overlap = r.inside = true;
      r.near2 = near2;
      r.qx = qx;
      r.qy = qy;
    }
  }
  return r;
}

// Folds one query point's finding into v's result: any overlap counts; of the points inside another
// element the deepest gives the way out, the first reaching it winning.
void overlap_fold(const PointOverlap& found, float px, float py, OverlapResult& r, float& depth2) {
  r.overlap = r.overlap || found.overlap;
  r.yield = r.yield || found.yield;
  r.block = r.block || found.block;
  if (!found.inside || (r.inside && !(found.near2 > depth2))) return;
  r.inside = true;
  depth2 = found.near2;
  r.out_x = found.qx - px;
  r.out_y = found.qy - py;
}

}  // namespace

OverlapResult overlap_test(const Topology& topo, const SimState& state, const SliceBoxes& boxes,
                           const OverlapGrid& grid, const CurveTangents& tangents, std::int32_t v,
                           std::int32_t interval_points) {
  OverlapResult r;
  if ((topo.flags[v] & vertex_boundary) == 0) return r;
  const std::int32_t own = topo.element[v], own_slice = topo.slice[v];
  const std::int32_t own_lo = topo.slice_begin[own_slice], own_count = topo.slice_boundary[own_slice];
  const std::int32_t next = own_lo + (v - own_lo + 1 == own_count ? 0 : v - own_lo + 1);
  const std::int32_t own_index = own_slice - topo.element_slice_begin[own];
  const std::int32_t own_slices = topo.element_slice_begin[own + 1] - topo.element_slice_begin[own];
  const std::int32_t per_slice = topo.slice_begin[own_slice + 1] - own_lo;
  const float own_g = state.growth[own_slice];
  float depth2 = 0.0f;
  overlap_fold(overlap_point(topo, state, boxes, grid, tangents, own, own_g, own_index, state.x[v], state.y[v],
                             state.t[v], state.x[next], state.y[next]),
               state.x[v], state.y[v], r, depth2);
  // Between slices (the paper's §6 and §8: overlaps can hide there): interval_points evenly spaced
  // times inside each slice interval, at fractions j / (interval_points + 1) of it. v tests those of the
  // two intervals next to it that lie in the half nearer to v (the middle from both ends), the point and
  // its edge on their curves towards the same vertices of the neighbouring slice; the vertex at the other
  // end tests the other half. docs/parameters.md, "Between slices".
  const float denominator = static_cast<float>(interval_points + 1);
  for (const std::int32_t step : {1, -1}) {
    if (own_index + step < 0 || own_index + step >= own_slices) continue;
    const std::int32_t w = v + step * per_slice;
    // The interval's lower and upper slices, and v's side of it.
    const std::int32_t lo = step > 0 ? own_lo : own_lo - per_slice, hi = lo + per_slice;
    const std::int32_t k = v - own_lo, kn = next - own_lo;
    for (std::int32_t j = 1; 2 * j <= interval_points + 1; ++j) {
      const float f = static_cast<float>(j) / denominator;
      const float mt = state.t[v] + (state.t[w] - state.t[v]) * f;
      const CurveBasis<float> b = curve_basis(step > 0 ? f : 1.0f - f, state.t[hi] - state.t[lo], tangents.mode);
      float mx, my, nx, ny;
      curve_point(state, tangents, lo, hi, k, b, mx, my);
      curve_point(state, tangents, lo, hi, kn, b, nx, ny);
      overlap_fold(overlap_point(topo, state, boxes, grid, tangents, own, own_g, step > 0 ? own_index : own_index - 1,
                                 mx, my, mt, nx, ny),
                   mx, my, r, depth2);
    }
  }
  return r;
}

Vec3f overlap_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v,
                    const OverlapResult& overlap) {
  if (!overlap.overlap) return {};
  const float x = state.x[v], y = state.y[v], t = state.t[v];
  Vec3f sum;
  for (std::int32_t k = topo.tri_begin[v]; k < topo.tri_begin[v + 1]; ++k) {
    const std::int32_t i = topo.tri_list[k];
    const std::int32_t a = topo.tri_a[i], b = topo.tri_b[i], c = topo.tri_c[i];
    const float px = (state.x[a] + state.x[b] + state.x[c]) / 3.0f;
    const float py = (state.y[a] + state.y[b] + state.y[c]) / 3.0f;
    const float pt = (state.t[a] + state.t[b] + state.t[c]) / 3.0f;
    sum.x = sum.x + (px - x);
    sum.y = sum.y + (py - y);
    sum.t = sum.t + (pt - t);
  }
  const float k_ovr = params.k_overlap;
  Vec3f f{k_ovr * sum.x, k_ovr * sum.y, k_ovr * sum.t};
  if (overlap.inside) {
    const float k_depth = params.k_overlap_depth;
    f.x = f.x + k_depth * overlap.out_x;
    f.y = f.y + k_depth * overlap.out_y;
  }
  return f;
}

}  // namespace animpak::reference
