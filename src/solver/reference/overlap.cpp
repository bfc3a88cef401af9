// Overlap test and force, paper Eq. 3 (§5): a boundary vertex that penetrates another element is pushed
// out, and its slice stops growing (§5.3). The paper finds penetrations through the collision grid's
// near block; that misses a vertex more than one cell deep and an edge that crosses another element's
// outline with neither end inside (thin parts: tails, legs). Here every boundary vertex is tested against
// every other element whose boundary polygon, interpolated linearly at the vertex's t, can reach it (a
// box test first), whatever the depth, and its boundary edge is tested for crossings on the same walk;
// so are the middles of the slice intervals on either side of it.
// The force adds to Eq. 3 a pull towards the other element's outline that grows with depth
// (docs/parameters.md, "Overlaps").
#include <algorithm>

#include "animpak/reference.hpp"

namespace animpak::reference {

namespace {

// Slices are stacked along t; a slice's t is its first vertex's t (simultaneity keeps the slice's
// vertices at one t after every step).
float slice_t(const Topology& topo, const SimState& state, std::int32_t s) { return state.t[topo.slice_begin[s]]; }

float orient(float ax, float ay, float bx, float by, float cx, float cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

bool opposite(float a, float b) { return (a > 0.0f && b < 0.0f) || (a < 0.0f && b > 0.0f); }

}  // namespace

void slice_boxes(const Topology& topo, const SimState& state, SliceBoxes& out) {
  const std::int32_t slices = topo.slice_count();
  out.x0.assign(slices, 0.0f);
  out.y0.assign(slices, 0.0f);
  out.x1.assign(slices, 0.0f);
  out.y1.assign(slices, 0.0f);
  for (std::int32_t s = 0; s < slices; ++s) {
    const std::int32_t lo = topo.slice_begin[s], count = topo.slice_boundary[s];
    if (count == 0) continue;
    float x0 = state.x[lo], x1 = x0, y0 = state.y[lo], y1 = y0;
    for (std::int32_t v = lo + 1; v < lo + count; ++v) {
      x0 = state.x[v] < x0 ? state.x[v] : x0;
      x1 = state.x[v] > x1 ? state.x[v] : x1;
      y0 = state.y[v] < y0 ? state.y[v] : y0;
      y1 = state.y[v] > y1 ? state.y[v] : y1;
    }
    out.x0[s] = x0, out.y0[s] = y0, out.x1[s] = x1, out.y1[s] = y1;
  }
}

namespace {

// What one query point found: a point p at time pt, with its boundary edge p → n.
struct PointOverlap {
  bool overlap = false, inside = false;
  bool yield = false;          // one of the elements overlapped is no larger (g) than own_g
  float near2 = 0.0f;          // when inside: squared distance to the nearest way out
  float qx = 0.0f, qy = 0.0f;  // that way out, a point of the other element's outline
};

// The query point against every element but `own`, each one's slice pair around pt searched from slice
// index `start` of that element.
PointOverlap point_overlap(const Topology& topo, const SimState& state, const SliceBoxes& boxes, std::int32_t own,
                           float own_g, std::int32_t start, float px, float py, float pt, float nx, float ny) {
  PointOverlap r;
  const float ex0 = std::min(px, nx), ex1 = std::max(px, nx), ey0 = std::min(py, ny), ey1 = std::max(py, ny);
  for (std::int32_t e = 0; e < topo.element_count(); ++e) {
    if (e == own) continue;
    const std::int32_t first = topo.element_slice_begin[e], count = topo.element_slice_begin[e + 1] - first;
    if (count < 2) continue;
    // The pair of e's slices around pt: start at the query's own slice index (slices stay near their
    // rest times), then walk down or up.
    std::int32_t k = std::min(start, count - 2);
    while (k > 0 && pt < slice_t(topo, state, first + k)) --k;
    while (k < count - 2 && pt > slice_t(topo, state, first + k + 1)) ++k;
    const std::int32_t s = first + k;
    const float t0 = slice_t(topo, state, s), t1 = slice_t(topo, state, s + 1);
    if (!(std::min(t0, t1) <= pt && pt <= std::max(t0, t1))) continue;
    // The interpolated polygon lies in the union of the two slices' boxes.
    const float bx0 = std::min(boxes.x0[s], boxes.x0[s + 1]), bx1 = std::max(boxes.x1[s], boxes.x1[s + 1]);
    const float by0 = std::min(boxes.y0[s], boxes.y0[s + 1]), by1 = std::max(boxes.y1[s], boxes.y1[s + 1]);
    if (ex1 < bx0 || ex0 > bx1 || ey1 < by0 || ey0 > by1) continue;

    // Equal slice times (a flat pair) take the lower slice's polygon.
    const float w = t1 != t0 ? (pt - t0) / (t1 - t0) : 0.0f;
    const std::int32_t lo = topo.slice_begin[s], hi = topo.slice_begin[s + 1];
    const std::int32_t edges = topo.slice_boundary[s];
    bool inside = false, crosses = false;
    float near2 = std::numeric_limits<float>::infinity(), qx = px, qy = py;
    for (std::int32_t i = 0; i < edges; ++i) {
      const std::int32_t j = i + 1 == edges ? 0 : i + 1;
      const float ax = state.x[lo + i] + (state.x[hi + i] - state.x[lo + i]) * w;
      const float ay = state.y[lo + i] + (state.y[hi + i] - state.y[lo + i]) * w;
      const float bx = state.x[lo + j] + (state.x[hi + j] - state.x[lo + j]) * w;
      const float by = state.y[lo + j] + (state.y[hi + j] - state.y[lo + j]) * w;
      if (ray_crosses_segment(px, py, ax, ay, bx, by)) inside = !inside;
      // A proper crossing of the query's boundary edge with this edge (touching does not count).
      if (opposite(orient(ax, ay, bx, by, px, py), orient(ax, ay, bx, by, nx, ny)) &&
          opposite(orient(px, py, nx, ny, ax, ay), orient(px, py, nx, ny, bx, by)))
        crosses = true;
      float cx, cy;
      const float d2 = closest_point_on_segment(px, py, ax, ay, bx, by, cx, cy);
      if (d2 < near2) near2 = d2, qx = cx, qy = cy;
    }
    if (crosses) r.overlap = true;
    // The larger of two overlapping slices yields (docs/parameters.md, "Growth"): e's g at pt, between
    // its two slices as its polygon is.
    if ((crosses || inside) && !(state.growth[s] + (state.growth[s + 1] - state.growth[s]) * w > own_g))
      r.yield = true;
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
void fold(const PointOverlap& found, float px, float py, OverlapResult& r, float& depth2) {
  r.overlap = r.overlap || found.overlap;
  r.yield = r.yield || found.yield;
  if (!found.inside || (r.inside && !(found.near2 > depth2))) return;
  r.inside = true;
  depth2 = found.near2;
  r.out_x = found.qx - px;
  r.out_y = found.qy - py;
}

}  // namespace

OverlapResult overlap_test(const Topology& topo, const SimState& state, const SliceBoxes& boxes, std::int32_t v) {
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
  fold(point_overlap(topo, state, boxes, own, own_g, own_index, state.x[v], state.y[v], state.t[v], state.x[next],
                     state.y[next]),
       state.x[v], state.y[v], r, depth2);
  // Between slices (the paper's §6 and §8: overlaps can hide there): the middles of the two slice
  // intervals next to v, the point and its edge interpolated halfway to the same vertices of the
  // neighbouring slice, are tested like v.
  for (const std::int32_t step : {1, -1}) {
    if (own_index + step < 0 || own_index + step >= own_slices) continue;
    const std::int32_t w = v + step * per_slice, wn = next + step * per_slice;
    const float mx = (state.x[v] + state.x[w]) * 0.5f, my = (state.y[v] + state.y[w]) * 0.5f;
    const float mt = (state.t[v] + state.t[w]) * 0.5f;
    const float nx = (state.x[next] + state.x[wn]) * 0.5f, ny = (state.y[next] + state.y[wn]) * 0.5f;
    fold(point_overlap(topo, state, boxes, own, own_g, step > 0 ? own_index : own_index - 1, mx, my, mt, nx, ny), mx, my, r,
         depth2);
  }
  return r;
}

Vec3f overlap_force(const Topology& topo, const SimState& state, const Params& params, std::int32_t v,
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
  const float k_ovr = static_cast<float>(params.k_overlap);
  Vec3f f{k_ovr * sum.x, k_ovr * sum.y, k_ovr * sum.t};
  if (overlap.inside) {
    const float k_depth = static_cast<float>(params.k_overlap_depth);
    f.x = f.x + k_depth * overlap.out_x;
    f.y = f.y + k_depth * overlap.out_y;
  }
  return f;
}

}  // namespace animpak::reference
