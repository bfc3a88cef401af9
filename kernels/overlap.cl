/* Overlap test and force, paper Eq. 3 (src/solver/reference/overlap.cpp): every boundary vertex, and
 * points of the slice intervals next to it (ForceParams.interval_points), against every other
 * element's boundary polygon on its curve at their t (curve.cl), at any depth, with the boundary edge tested for
 * crossings on the same walk; the force adds a pull along the way out of the other element. The
 * elements tried are the broadphase's candidates (OverlapGridInfo, built on the host by
 * reference::build_overlap_grid or on the device by overlap_grid.cl; docs/architecture.md, "The
 * overlap test"): the merged lists of the
 * cells the query edge's box meets, in increasing element order, exactly as
 * reference::overlap_candidates. */

/* std::min / std::max spelled out, so NaN compares exactly as in the reference. */
float ap_min(float a, float b) { return b < a ? b : a; }
float ap_max(float a, float b) { return a < b ? b : a; }

/** What the overlap test reads of the curve between slices (the reference's state positions and
 * CurveTangents): every vertex's position, its tangent (curve_tangents) and its Bézier handles towards
 * the next slice (hp*) and the one before (hq*), which slice_boxes keeps. */
typedef struct {
  __global const float* x;
  __global const float* y;
  __global const float* mx;
  __global const float* my;
  __global const float* hpx;
  __global const float* hpy;
  __global const float* hqx;
  __global const float* hqy;
} CurveArrays;

/** Vertex k's position on its curve at weights b between the slices whose first vertices are lo and hi
 * (reference curve_point in overlap.cpp), with the Bézier handles slice_boxes computed: hp* at lo's
 * vertex towards hi, hq* at hi's towards lo (curve_value's p and q, the same operands). */
AP_INLINE void curve_point(const CurveArrays curve, int lo, int hi, int k, const CurveBasis b, float* px, float* py) {
  /* The handles only on the spline (slice_boxes writes them only there). */
  const float p_x = b.spline ? curve.hpx[lo + k] : 0.0f, q_x = b.spline ? curve.hqx[hi + k] : 0.0f;
  const float p_y = b.spline ? curve.hpy[lo + k] : 0.0f, q_y = b.spline ? curve.hqy[hi + k] : 0.0f;
  *px = curve_value_handles(curve.x[lo + k], curve.x[hi + k], curve.mx[lo + k], curve.mx[hi + k], b, p_x, q_x);
  *py = curve_value_handles(curve.y[lo + k], curve.y[hi + k], curve.my[lo + k], curve.my[hi + k], b, p_y, q_y);
}

/** Edge i → i + 1 (wrapping at `edges`) of the boundary polygon on the curve at weights b between the
 * slices whose first vertices are lo and hi (reference overlap_edge). */
void overlap_edge(const CurveArrays curve,
                  int lo,
                  int hi,
                  int i,
                  int edges,
                  const CurveBasis b,
                  float* ax,
                  float* ay,
                  float* bx,
                  float* by) {
  const int j = i + 1 == edges ? 0 : i + 1;
  curve_point(curve, lo, hi, i, b, ax, ay);
  curve_point(curve, lo, hi, j, b, bx, by);
}

#ifdef AP_LANES
/** curve_point for vertices k … k + AP_LANES − 1, one per lane. */
AP_INLINE void
curve_point_lanes(const CurveArrays curve, int lo, int hi, int k, const CurveBasis b, ap_floatv* px, ap_floatv* py) {
  *px =
      curve_value_lanes(ap_vloadf(0, curve.x + lo + k), ap_vloadf(0, curve.x + hi + k), ap_vloadf(0, curve.mx + lo + k),
                        ap_vloadf(0, curve.mx + hi + k), b, curve.hpx + lo + k, curve.hqx + hi + k);
  *py =
      curve_value_lanes(ap_vloadf(0, curve.y + lo + k), ap_vloadf(0, curve.y + hi + k), ap_vloadf(0, curve.my + lo + k),
                        ap_vloadf(0, curve.my + hi + k), b, curve.hpy + lo + k, curve.hqy + hi + k);
}

#endif

/** Box of every slice's boundary polygon and the slice's t (the broadphase's input); one work-item per
 * slice. On the spline (mode AP_CURVE_SPLINE) it also holds each boundary vertex's Bézier handles towards
 * its element's neighbouring slices, so that two slices' boxes hold the curve between them (reference
 * slice_boxes), and keeps them for the overlap test's curve points (curve_point): the handle that way is
 * curve_value's p (towards the next slice) or q (towards the one before), the same operands. */
__kernel void slice_boxes(
    const WorldInfo world,
    __global const int* slice_topology, /* input: slice_begin, slice_boundary, slice_element, ... */
    __global const float* positions,    /* input: x, y, t per vertex */
    __global float* curve_planes,       /* input: tangents (curve_tangents); output on the spline: handles */
    const int mode,                     /* input: ForceParams.motion_curve */
    __global float* slice_geometry) {   /* output: the boxes and their t per slice */
  __global const int* slice_begin = slice_topology + AP_SLICES_BEGIN * world.slice_stride;
  __global const int* slice_boundary = slice_topology + AP_SLICES_BOUNDARY * world.slice_stride;
  __global const int* slice_element = slice_topology + AP_SLICES_ELEMENT * world.slice_stride;
  __global const int* element_slice_begin = slice_topology + AP_SLICES_ELEMENT_BEGIN * world.slice_stride;
  __global const float* x = positions + AP_X * world.vertex_stride;
  __global const float* y = positions + AP_Y * world.vertex_stride;
  __global const float* t = positions + AP_T * world.vertex_stride;
  /* The handles go towards the next slice (p) and the one before (q), per boundary vertex. */
  __global const float* tangent_x = curve_planes + AP_CURVE_TANGENT_X * world.vertex_stride;
  __global const float* tangent_y = curve_planes + AP_CURVE_TANGENT_Y * world.vertex_stride;
  __global float* handle_px = curve_planes + AP_CURVE_HANDLE_PX * world.vertex_stride;
  __global float* handle_py = curve_planes + AP_CURVE_HANDLE_PY * world.vertex_stride;
  __global float* handle_qx = curve_planes + AP_CURVE_HANDLE_QX * world.vertex_stride;
  __global float* handle_qy = curve_planes + AP_CURVE_HANDLE_QY * world.vertex_stride;
  __global float* box_x0 = slice_geometry + AP_GEOM_X0 * world.slice_stride;
  __global float* box_y0 = slice_geometry + AP_GEOM_Y0 * world.slice_stride;
  __global float* box_x1 = slice_geometry + AP_GEOM_X1 * world.slice_stride;
  __global float* box_y1 = slice_geometry + AP_GEOM_Y1 * world.slice_stride;
  __global float* box_t = slice_geometry + AP_GEOM_T * world.slice_stride;
  const int s = get_global_id(0);
  if (s >= world.slices) return;
  const int lo = slice_begin[s], count = slice_boundary[s];
  box_t[s] = t[lo];
  float x0 = 0.0f, y0 = 0.0f, x1 = 0.0f, y1 = 0.0f;
  if (count > 0) {
    x0 = x[lo], x1 = x0, y0 = y[lo], y1 = y0;
    for (int v = lo + 1; v < lo + count; ++v) {
      x0 = x[v] < x0 ? x[v] : x0;
      x1 = x[v] > x1 ? x[v] : x1;
      y0 = y[v] < y0 ? y[v] : y0;
      y1 = y[v] > y1 ? y[v] : y1;
    }
    if (mode == AP_CURVE_SPLINE) {
      const int e = slice_element[s];
      for (int side = 0; side < 2; ++side) {
        const int q = side == 0 ? s - 1 : s + 1;
        if (q < element_slice_begin[e] || q >= element_slice_begin[e + 1]) continue;
        const float h = q > s ? t[slice_begin[q]] - t[lo] : -(t[lo] - t[slice_begin[q]]);
        for (int v = lo; v < lo + count; ++v) {
          const float hx = curve_handle(x[v], tangent_x[v], h), hy = curve_handle(y[v], tangent_y[v], h);
          if (side == 0)
            handle_qx[v] = hx, handle_qy[v] = hy;
          else
            handle_px[v] = hx, handle_py[v] = hy;
          x0 = hx < x0 ? hx : x0;
          x1 = hx > x1 ? hx : x1;
          y0 = hy < y0 ? hy : y0;
          y1 = hy > y1 ? hy : y1;
        }
      }
    }
  }
  box_x0[s] = x0, box_y0[s] = y0, box_x1[s] = x1, box_y1[s] = y1;
}

/** The candidate after e: e + 1, or the smallest listed element above e; `elements` when none is left. */
AP_INLINE int overlap_next_candidate(int e,
                                     int elements,
                                     bool every,
                                     int lists,
                                     int* begin,
                                     const int* end,
                                     __global const int* grid_elements) {
  if (every) return e + 1 < elements ? e + 1 : elements;
  int next = elements;
  for (int l = 0; l < lists; ++l) {
    while (begin[l] < end[l] && grid_elements[begin[l]] <= e) ++begin[l];
    if (begin[l] < end[l] && grid_elements[begin[l]] < next) next = grid_elements[begin[l]];
  }
  return next;
}

/** The search of overlap_slice_pair: from slice index `start` of an element whose `count` (≥ 2)
 * slices begin at global slice `first`, down while pt is before the slice, then up while it is after
 * the next one. The index found never decreases as pt grows (NaN times included: a comparison with
 * NaN stops either walk whatever pt is), so points whose times lie between two that find the same
 * index find it too. */
AP_INLINE int overlap_pair_search(int first, int count, int start, float pt, __global const float* slice_t) {
  int k = start < count - 2 ? start : count - 2;
  while (k > 0 && pt < slice_t[first + k]) --k;
  while (k < count - 2 && pt > slice_t[first + k + 1]) ++k;
  return k;
}

/** Element e's slice pair around pt, searched from slice index `start` (slices stay near their rest
 * times), whose boxes meet the query box: its lower global slice, with *w the weight of pt between the
 * two (0 for a flat pair); -1 when pt is outside the pair or the boxes miss (reference
 * overlap_slice_pair). The slice times come from slice_boxes' copy (slice_t[s] = t of the slice's
 * first vertex, the same values, one load fewer each). */
AP_INLINE int overlap_slice_pair(int e,
                                 int start,
                                 float pt,
                                 float ex0,
                                 float ex1,
                                 float ey0,
                                 float ey1,
                                 __global const int* element_slice_begin,
                                 __global const float* slice_t,
                                 __global const float* box_x0,
                                 __global const float* box_y0,
                                 __global const float* box_x1,
                                 __global const float* box_y1,
                                 float* w) {
  const int first = element_slice_begin[e], count = element_slice_begin[e + 1] - first;
  if (count < 2) return -1;
  const int s = first + overlap_pair_search(first, count, start, pt, slice_t);
  const float t0 = slice_t[s], t1 = slice_t[s + 1];
  if (!(ap_min(t0, t1) <= pt && pt <= ap_max(t0, t1))) return -1;
  const float bx0 = ap_min(box_x0[s], box_x0[s + 1]), bx1 = ap_max(box_x1[s], box_x1[s + 1]);
  const float by0 = ap_min(box_y0[s], box_y0[s + 1]), by1 = ap_max(box_y1[s], box_y1[s + 1]);
  if (ex1 < bx0 || ex0 > bx1 || ey1 < by0 || ey0 > by1) return -1;
  *w = t1 != t0 ? (pt - t0) / (t1 - t0) : 0.0f;
  return s;
}

/** The polygon of the slices whose first vertices are lo and hi, on the curve at weights b, edge by edge: the
 * even-odd test of (px, py) into *inside, and into *crosses whether the query edge p → n properly crosses
 * one of its edges, tried until one is found and only where the two edges' boxes meet (reference
 * overlap_polygon_walk). */
AP_INLINE void overlap_polygon_walk(const CurveArrays curve,
                                    int lo,
                                    int hi,
                                    int edges,
                                    const CurveBasis b,
                                    float px,
                                    float py,
                                    float nx,
                                    float ny,
                                    float ex0,
                                    float ex1,
                                    float ey0,
                                    float ey1,
                                    bool* inside_out,
                                    bool* crosses_out) {
  bool inside = false, crosses = false;
  int i = 0;
#ifdef AP_LANES
  /* Built for a CPU: AP_LANES edges at a time while the last one's end does not wrap to vertex 0.
   * Each lane does the scalar test's float operations; the parity and the crossing are a count and
   * an any over the lanes, so the order does not matter (docs/architecture.md, "The near block in
   * lanes"). */
  for (; i + AP_LANES < edges; i += AP_LANES) {
    ap_floatv ax, ay, bx, by;
    curve_point_lanes(curve, lo, hi, i, b, &ax, &ay);
    curve_point_lanes(curve, lo, hi, i + 1, b, &bx, &by);
    inside = inside != ((ap_lane_count(ray_crosses_segments(px, py, ax, ay, bx, by)) & 1) != 0);
    if (!crosses) crosses = any(edges_cross_properly(px, py, nx, ny, ex0, ex1, ey0, ey1, ax, ay, bx, by));
  }
  /* The rest in one more round when the polygon has AP_LANES edges or more: its last AP_LANES edges, the
   * lanes already walked masked out. Each edge's end is the next lane's start, the last edge's end
   * vertex 0 (its curve point in one lane's operations), so nothing past the polygon is read. */
  if (i < edges && edges >= AP_LANES) {
    const int base = edges - AP_LANES;
    ap_floatv ax, ay;
    curve_point_lanes(curve, lo, hi, base, b, &ax, &ay);
    float first_x, first_y;
    curve_point(curve, lo, hi, 0, b, &first_x, &first_y);
    const ap_uintv next = ap_lane_index() + 1u; /* lane AP_LANES: the second operand's lane 0 */
    const ap_floatv bx = shuffle2(ax, (ap_floatv)(first_x), next), by = shuffle2(ay, (ap_floatv)(first_y), next);
    const ap_intv fresh = ap_lane_index_int() + base >= i;
    inside = inside != ((ap_lane_count(fresh && ray_crosses_segments(px, py, ax, ay, bx, by)) & 1) != 0);
    if (!crosses) crosses = any(fresh && edges_cross_properly(px, py, nx, ny, ex0, ex1, ey0, ey1, ax, ay, bx, by));
    i = edges;
  }
#endif
  /* Each edge's end is the next one's start: one curve point per vertex (the same value either way). */
  float ax = 0.0f, ay = 0.0f;
  if (i < edges) curve_point(curve, lo, hi, i, b, &ax, &ay);
  for (; i < edges; ++i) {
    float bx, by;
    curve_point(curve, lo, hi, i + 1 == edges ? 0 : i + 1, b, &bx, &by);
    if (ray_crosses_segment(px, py, ax, ay, bx, by)) inside = !inside;
    if (!crosses && ap_max(ax, bx) >= ex0 && ap_min(ax, bx) <= ex1 && ap_max(ay, by) >= ey0 && ap_min(ay, by) <= ey1 &&
        segments_cross_properly(px, py, nx, ny, ax, ay, bx, by))
      crosses = true;
    ax = bx, ay = by;
  }
  *inside_out = inside;
  *crosses_out = crosses;
}

/** The way out of a point inside the polygon on the curve: its nearest outline point (*qx, *qy), the
 * first edge reaching the minimum winning; returns the squared distance (reference overlap_way_out). */
float overlap_way_out(const CurveArrays curve,
                      int lo,
                      int hi,
                      int edges,
                      const CurveBasis b,
                      float px,
                      float py,
                      float* qx,
                      float* qy) {
  float near2 = INFINITY;
  *qx = px;
  *qy = py;
  for (int i = 0; i < edges; ++i) {
    float ax, ay, bx, by, cx, cy;
    overlap_edge(curve, lo, hi, i, edges, b, &ax, &ay, &bx, &by);
    const float d2 = closest_point_on_segment(px, py, ax, ay, bx, by, &cx, &cy);
    if (d2 < near2) near2 = d2, *qx = cx, *qy = cy;
  }
  return near2;
}

/* At most this many query points share one candidate walk (overlap_points), and at most this many
 * cells' lists make up its candidates (overlap_span_lists). */
#define AP_OVERLAP_BATCH 8
#define AP_SPAN_LISTS 8

/** What one query point found so far (reference PointOverlap). */
typedef struct {
  uchar overlap, inside, yield, block;
  float near2, qx, qy;
} OverlapFound;

/** One query point (px, py) at time pt with its boundary edge to (nx, ny), its edge's box ex0…ey1,
 * against element e's slice pair around pt searched from slice index `start`, folded into *r in the
 * reference overlap_point's order: any crossing or inside is an overlap; e blocks unless it is
 * secondary and `own` primary, and then yields when it is no larger (g at pt) than own_g or `own` is
 * secondary while e is primary; of the elements it is inside, the nearest way out, the first reaching
 * it winning. */
AP_INLINE void overlap_point_element(int e,
                                     bool own_secondary,
                                     float own_g,
                                     int start,
                                     float px,
                                     float py,
                                     float pt,
                                     float nx,
                                     float ny,
                                     float ex0,
                                     float ex1,
                                     float ey0,
                                     float ey1,
                                     __global const int* element_slice_begin,
                                     __global const int* slice_begin,
                                     __global const int* slice_boundary,
                                     __global const float* box_x0,
                                     __global const float* box_y0,
                                     __global const float* box_x1,
                                     __global const float* box_y1,
                                     __global const float* slice_t,
                                     const CurveArrays curve,
                                     int mode,
                                     __global const float* growth,
                                     __global const int* element_secondary,
                                     OverlapFound* r) {
  float w;
  const int s = overlap_slice_pair(e, start, pt, ex0, ex1, ey0, ey1, element_slice_begin, slice_t, box_x0, box_y0,
                                   box_x1, box_y1, &w);
  if (s < 0) return;
  const int lo = slice_begin[s], hi = slice_begin[s + 1], edges = slice_boundary[s];
  const CurveBasis b = curve_basis(w, slice_t[s + 1] - slice_t[s], mode);
  bool inside, crosses;
  overlap_polygon_walk(curve, lo, hi, edges, b, px, py, nx, ny, ex0, ex1, ey0, ey1, &inside, &crosses);
  /* Only a point inside needs its way out: a second walk, since most elements tried are near and not
   * entered. */
  float cqx = px, cqy = py;
  const float near2 = inside ? overlap_way_out(curve, lo, hi, edges, b, px, py, &cqx, &cqy) : INFINITY;
  if (crosses) r->overlap = 1;
  const bool other_secondary = element_secondary[e] != 0;
  if ((crosses || inside) && !(other_secondary && !own_secondary)) {
    r->block = 1;
    if ((own_secondary && !other_secondary) || !(growth[s] + (growth[s + 1] - growth[s]) * w > own_g)) r->yield = 1;
  }
  if (inside && (!r->inside || near2 < r->near2)) {
    r->overlap = 1;
    r->inside = 1;
    r->near2 = near2;
    r->qx = cqx;
    r->qy = cqy;
  }
}

/** The broadphase lists of the cells a query box meets over the times t0 … t1: up to
 * AP_SPAN_LISTS lists in begin/end, or *every (no grid, a NaN, a box over more than 2 x 2 cells,
 * more cells than lists) for every element. Every element whose slice-pair box meets the query box
 * somewhere in t0 … t1 is listed (the cell of each coordinate never decreases as it grows). */
AP_INLINE int overlap_span_lists(const OverlapGridInfo grid,
                                 __global const int* grid_start,
                                 float ex0,
                                 float ex1,
                                 float ey0,
                                 float ey1,
                                 float t0,
                                 float t1,
                                 int* begin,
                                 int* end,
                                 bool* every) {
  *every = grid.nx == 0 || isnan(ex0) || isnan(ex1) || isnan(ey0) || isnan(ey1) || isnan(t0) || isnan(t1);
  int lists = 0;
  if (*every) return 0;
  const int ix0 = grid_axis_cell(ex0 - grid.x0, grid.cell, grid.nx);
  const int ix1 = grid_axis_cell(ex1 - grid.x0, grid.cell, grid.nx);
  const int iy0 = grid_axis_cell(ey0 - grid.y0, grid.cell, grid.ny);
  const int iy1 = grid_axis_cell(ey1 - grid.y0, grid.cell, grid.ny);
  const int it0 = grid_axis_cell(t0 - grid.t0, grid.cell_t, grid.nt);
  const int it1 = grid_axis_cell(t1 - grid.t0, grid.cell_t, grid.nt);
  const int xy = (ix1 - ix0 + 1) * (iy1 - iy0 + 1);
  *every = xy > 4 || xy * (it1 - it0 + 1) > AP_SPAN_LISTS;
  for (int it = it0; !*every && it <= it1; ++it)
    for (int iy = iy0; iy <= iy1; ++iy)
      for (int ix = ix0; ix <= ix1; ++ix, ++lists) {
        const int c = (it * grid.ny + iy) * grid.nx + ix;
        begin[lists] = grid_start[c];
        end[lists] = grid_start[c + 1];
      }
  return lists;
}

/** Folds one query point's findings into v's (reference overlap_fold): the deepest point inside gives the way out. */
void overlap_fold(const OverlapFound found,
                  float px,
                  float py,
                  uchar* bits,
                  float* depth2,
                  float* out_x,
                  float* out_y) {
  if (found.overlap) *bits |= AP_CONTACT_OVERLAP;
  if (found.yield) *bits |= AP_CONTACT_YIELD;
  if (found.block) *bits |= AP_CONTACT_BLOCK;
  if (!found.inside || ((*bits & AP_CONTACT_INSIDE) != 0 && !(found.near2 > *depth2))) return;
  *bits |= AP_CONTACT_INSIDE;
  *depth2 = found.near2;
  *out_x = found.qx - px;
  *out_y = found.qy - py;
}

/** `count` (≤ AP_OVERLAP_BATCH) query points of one boundary vertex, each with its edge to (nx, ny),
 * its time pt and its pair search's start, against every element but `own` (reference overlap_point
 * for each), folded in order into v's bits (overlap_fold). The points share one walk over the
 * broadphase's candidates for the union of their edges' boxes over their times: an element is tried
 * for a point only if it passes that point's own box test, and every such element is among the
 * shared candidates, so each point finds what its own walk would, element by element in the same
 * increasing order. */
void overlap_points(int count,
                    const float* px,
                    const float* py,
                    const float* pt,
                    const float* nx,
                    const float* ny,
                    const int* start,
                    int own,
                    float own_g,
                    int elements,
                    __global const int* element_slice_begin,
                    __global const int* slice_begin,
                    __global const int* slice_boundary,
                    __global const float* box_x0,
                    __global const float* box_y0,
                    __global const float* box_x1,
                    __global const float* box_y1,
                    __global const float* slice_t,
                    const CurveArrays curve,
                    int mode,
                    __global const float* growth,
                    __global const int* element_secondary,
                    const OverlapGridInfo grid,
                    __global const int* grid_start,
                    __global const int* grid_elements,
                    uchar* bits,
                    float* depth2,
                    float* out_x,
                    float* out_y) {
  const bool own_secondary = element_secondary[own] != 0;
  float ex0[AP_OVERLAP_BATCH], ex1[AP_OVERLAP_BATCH], ey0[AP_OVERLAP_BATCH], ey1[AP_OVERLAP_BATCH];
  OverlapFound found[AP_OVERLAP_BATCH];
  /* The union of the edges' boxes and times; NaN anywhere makes it NaN (every element is tried). */
  float ux0 = INFINITY, ux1 = -INFINITY, uy0 = INFINITY, uy1 = -INFINITY, ut0 = INFINITY, ut1 = -INFINITY;
  bool nan = false;
  for (int j = 0; j < count; ++j) {
    ex0[j] = ap_min(px[j], nx[j]), ex1[j] = ap_max(px[j], nx[j]);
    ey0[j] = ap_min(py[j], ny[j]), ey1[j] = ap_max(py[j], ny[j]);
    nan = nan || isnan(ex0[j]) || isnan(ex1[j]) || isnan(ey0[j]) || isnan(ey1[j]) || isnan(pt[j]);
    ux0 = fmin(ux0, ex0[j]), ux1 = fmax(ux1, ex1[j]), uy0 = fmin(uy0, ey0[j]), uy1 = fmax(uy1, ey1[j]);
    ut0 = fmin(ut0, pt[j]), ut1 = fmax(ut1, pt[j]);
    found[j].overlap = found[j].inside = found[j].yield = found[j].block = 0;
    found[j].near2 = 0.0f, found[j].qx = 0.0f, found[j].qy = 0.0f;
  }
  if (nan) ux0 = NAN;
  bool one_start = true;
  for (int j = 1; j < count; ++j) one_start = one_start && start[j] == start[0];
  int begin[AP_SPAN_LISTS], end[AP_SPAN_LISTS];
  bool every;
  const int lists = overlap_span_lists(grid, grid_start, ux0, ux1, uy0, uy1, ut0, ut1, begin, end, &every);
  for (int e = overlap_next_candidate(-1, elements, every, lists, begin, end, grid_elements); e < elements;
       e = overlap_next_candidate(e, elements, every, lists, begin, end, grid_elements)) {
    if (e == own) continue;
    /* When every point's pair search ends on one pair (it does at the earliest and the latest time),
     * the union of the edges' boxes missing that pair's box means each point's box test fails. */
    if (one_start && !nan) {
      const int first = element_slice_begin[e], slices = element_slice_begin[e + 1] - first;
      if (slices < 2) continue;
      const int k = overlap_pair_search(first, slices, start[0], ut0, slice_t);
      if (k == overlap_pair_search(first, slices, start[0], ut1, slice_t)) {
        const int s = first + k;
        const float bx0 = ap_min(box_x0[s], box_x0[s + 1]), bx1 = ap_max(box_x1[s], box_x1[s + 1]);
        const float by0 = ap_min(box_y0[s], box_y0[s + 1]), by1 = ap_max(box_y1[s], box_y1[s + 1]);
        if (ux1 < bx0 || ux0 > bx1 || uy1 < by0 || uy0 > by1) continue;
      }
    }
    for (int j = 0; j < count; ++j)
      overlap_point_element(e, own_secondary, own_g, start[j], px[j], py[j], pt[j], nx[j], ny[j], ex0[j], ex1[j],
                            ey0[j], ey1[j], element_slice_begin, slice_begin, slice_boundary, box_x0, box_y0, box_x1,
                            box_y1, slice_t, curve, mode, growth, element_secondary, &found[j]);
  }
  for (int j = 0; j < count; ++j) overlap_fold(found[j], px[j], py[j], bits, depth2, out_x, out_y);
}

/** The overlap test of boundary vertex v (reference overlap_test): v, then the interval_points times
 * of each slice interval next to v that lie in the half nearer to v, in that order, in batches of up
 * to AP_OVERLAP_BATCH points (overlap_points). Returns AP_CONTACT_OVERLAP, plus AP_CONTACT_INSIDE with
 * the way out (*out_x, *out_y) of the deepest point inside another element. */
uchar overlap_test(int v,
                   int interval_points,
                   int elements,
                   __global const int* element,
                   __global const int* slice,
                   __global const int* element_slice_begin,
                   __global const int* slice_begin,
                   __global const int* slice_boundary,
                   __global const float* box_x0,
                   __global const float* box_y0,
                   __global const float* box_x1,
                   __global const float* box_y1,
                   __global const float* slice_t,
                   __global const float* t,
                   const CurveArrays curve,
                   int mode,
                   __global const float* growth,
                   __global const int* element_secondary,
                   const OverlapGridInfo grid,
                   __global const int* grid_start,
                   __global const int* grid_elements,
                   float* out_x,
                   float* out_y) {
  const int own = element[v], own_slice = slice[v];
  const int own_lo = slice_begin[own_slice], own_count = slice_boundary[own_slice];
  const int next = own_lo + (v - own_lo + 1 == own_count ? 0 : v - own_lo + 1);
  const int own_index = own_slice - element_slice_begin[own];
  const int own_slices = element_slice_begin[own + 1] - element_slice_begin[own];
  const int per_slice = slice_begin[own_slice + 1] - own_lo;
  uchar bits = 0;
  float depth2 = 0.0f;
  *out_x = 0.0f;
  *out_y = 0.0f;
  const float own_g = growth[own_slice];
  float px[AP_OVERLAP_BATCH], py[AP_OVERLAP_BATCH], pt[AP_OVERLAP_BATCH], nx[AP_OVERLAP_BATCH], ny[AP_OVERLAP_BATCH];
  int start[AP_OVERLAP_BATCH];
  /* v itself first, sharing a batch with the points after it. */
  px[0] = curve.x[v], py[0] = curve.y[v], pt[0] = t[v], nx[0] = curve.x[next], ny[0] = curve.y[next];
  start[0] = own_index;
  int count = 1;
  const float denominator = (float)(interval_points + 1);
  for (int side = 0; side < 2; ++side) {
    const int step = side == 0 ? 1 : -1;
    if (own_index + step < 0 || own_index + step >= own_slices) continue;
    const int w = v + step * per_slice;
    /* The interval's lower and upper slices, and v's side of it. */
    const int lo = step > 0 ? own_lo : own_lo - per_slice, hi = lo + per_slice;
    const int k = v - own_lo, kn = next - own_lo;
    const float h = t[hi] - t[lo];
    for (int j = 1; 2 * j <= interval_points + 1; ++j) {
      if (count == AP_OVERLAP_BATCH) {
        overlap_points(count, px, py, pt, nx, ny, start, own, own_g, elements, element_slice_begin, slice_begin,
                       slice_boundary, box_x0, box_y0, box_x1, box_y1, slice_t, curve, mode, growth, element_secondary,
                       grid, grid_start, grid_elements, &bits, &depth2, out_x, out_y);
        count = 0;
      }
      const float f = (float)j / denominator;
      pt[count] = t[v] + (t[w] - t[v]) * f;
      const CurveBasis b = curve_basis(step > 0 ? f : 1.0f - f, h, mode);
      curve_point(curve, lo, hi, k, b, &px[count], &py[count]);
      curve_point(curve, lo, hi, kn, b, &nx[count], &ny[count]);
      start[count] = step > 0 ? own_index : own_index - 1;
      ++count;
    }
    /* A side's points lie near v and each other: one batch each, v's with the first side's. */
    overlap_points(count, px, py, pt, nx, ny, start, own, own_g, elements, element_slice_begin, slice_begin,
                   slice_boundary, box_x0, box_y0, box_x1, box_y1, slice_t, curve, mode, growth, element_secondary,
                   grid, grid_start, grid_elements, &bits, &depth2, out_x, out_y);
    count = 0;
  }
  if (count > 0)
    overlap_points(count, px, py, pt, nx, ny, start, own, own_g, elements, element_slice_begin, slice_begin,
                   slice_boundary, box_x0, box_y0, box_x1, box_y1, slice_t, curve, mode, growth, element_secondary,
                   grid, grid_start, grid_elements, &bits, &depth2, out_x, out_y);
  return bits;
}

/** Eq. 3: k_ovr Σ (p_i − x) over centroids p_i of v's incident slice triangles, in list order, plus
 * k_ovr_depth times the way out (out_x, out_y) when inside another element (reference overlap_force). */
void overlap_force(const ForceParams p,
                   int v,
                   bool inside,
                   float out_x,
                   float out_y,
                   __global const int* tri_begin,
                   __global const int* tri_list,
                   __global const int* tri_a,
                   __global const int* tri_b,
                   __global const int* tri_c,
                   __global const float* x,
                   __global const float* y,
                   __global const float* t,
                   float* fx,
                   float* fy,
                   float* ft) {
  const float px = x[v], py = y[v], pt = t[v];
  float sx = 0.0f, sy = 0.0f, st = 0.0f;
  for (int k = tri_begin[v]; k < tri_begin[v + 1]; ++k) {
    const int i = tri_list[k];
    const int a = tri_a[i], b = tri_b[i], c = tri_c[i];
    const float cx = (x[a] + x[b] + x[c]) / 3.0f;
    const float cy = (y[a] + y[b] + y[c]) / 3.0f;
    const float ct = (t[a] + t[b] + t[c]) / 3.0f;
    sx = sx + (cx - px);
    sy = sy + (cy - py);
    st = st + (ct - pt);
  }
  const float k_ovr = p.k_overlap;
  float ox = k_ovr * sx, oy = k_ovr * sy;
  if (inside) {
    ox = ox + p.k_overlap_depth * out_x;
    oy = oy + p.k_overlap_depth * out_y;
  }
  *fx = ox;
  *fy = oy;
  *ft = k_ovr * st;
}
