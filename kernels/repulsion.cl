/* Repulsion, paper Eq. 1 (src/solver/reference/repulsion.cpp): k_rpl Σ u/|u| · 1/(ε + |u|²) over the
 * exact closest points on the near envelope triangles of other elements, in four partial sums by grid
 * slot mod 4, then the centroids of the far ones (or their cells' aggregates, grid_runs), in the grid's
 * visiting order (cells by dz, dy, dx ascending, sorted order within a cell), and the overlap test of
 * Eq. 3 (overlap.cl). docs/architecture.md, "The twin rule", gives the order. */

/** Eq. 1's weight of one term, `count` times: 1/|u| · 1/(ε + |u|²) · count, for d2 = |u|² > 0. */
float repulsion_weight(float d2, float eps, float count) {
  const float inv_len = 1.0f / sqrt(d2);
  return inv_len * (1.0f / (eps + d2)) * count;
}

/** One term of Eq. 1, `count` times (a far-field run stands for count triangles; 1 is exact); a point
 * exactly at x has no direction and adds nothing. */
void repulsion_add_term(float ux, float uy, float ut, float eps, float count, float* sx, float* sy, float* st) {
  const float d2 = ux * ux + uy * uy + ut * ut;
  if (!(d2 > 0.0f)) return;
  const float w = repulsion_weight(d2, eps, count);
  *sx = *sx + ux * w;
  *sy = *sy + uy * w;
  *st = *st + ut * w;
}

/** One exact near term of Eq. 1, added to partial sum k mod 4 of (*ax, *ay, *at) (repulsion.cpp); the
 * other three partials get +0, which leaves them as they are (they start at +0 and never become −0). */
void repulsion_add_partial(int k, float ux, float uy, float ut, float eps, float4* ax, float4* ay, float4* at) {
  const float d2 = ux * ux + uy * uy + ut * ut;
  if (!(d2 > 0.0f)) return;
  const float w = repulsion_weight(d2, eps, 1.0f);
  const int4 mine = (int4)(0, 1, 2, 3) == (int4)(k & 3);
  *ax = *ax + select((float4)(0.0f), (float4)(ux * w), mine);
  *ay = *ay + select((float4)(0.0f), (float4)(uy * w), mine);
  *at = *at + select((float4)(0.0f), (float4)(ut * w), mine);
}

/** Exact terms of Eq. 1 for every near slot in [range.x, range.y) of triangles not owned by `own` (with
 * own_only, of those owned by `own`: the wall's mirror image, boundary.cl), each
 * added to partial sum (slot mod 4) of (*ax, *ay, *at), in slot order within each partial. Built for a
 * CPU, AP_LANES slots at a time (closest_point_on_triangles): the partials are turned so that lane j
 * holds partial (range.x + j) mod 4, and each group adds its lanes 0-3, 4-7, 8-11, 12-15 in that order
 * (slot order within every partial). Lanes of the own element, or with d2 = 0 (w inf, NaN), add +0
 * instead of being skipped. The same float operations as the one-slot loop, which takes the rest of the
 * range (all of it on a GPU), and as the reference. */
AP_INLINE void repulsion_near_slots(int2 range,
                                    int own,
                                    int own_only,
                                    float px,
                                    float py,
                                    float pt,
                                    float eps,
                                    __global const int* slot_element,
                                    __global const float* slot_vertices,
                                    int slots,
                                    float4* ax_sum,
                                    float4* ay_sum,
                                    float4* at_sum,
                                    float* closest2) {
  __global const float* ax = slot_vertices + AP_SLOT_AX * slots;
  __global const float* ay = slot_vertices + AP_SLOT_AY * slots;
  __global const float* at = slot_vertices + AP_SLOT_AT * slots;
  __global const float* bx = slot_vertices + AP_SLOT_BX * slots;
  __global const float* by = slot_vertices + AP_SLOT_BY * slots;
  __global const float* bt = slot_vertices + AP_SLOT_BT * slots;
  __global const float* cx = slot_vertices + AP_SLOT_CX * slots;
  __global const float* cy = slot_vertices + AP_SLOT_CY * slots;
  __global const float* ct = slot_vertices + AP_SLOT_CT * slots;
  float4 sum_x = *ax_sum, sum_y = *ay_sum, sum_t = *at_sum;
  float c2 = *closest2;
  int k = range.x;
#ifdef AP_LANES
  if (k < range.y) {
    const uint r = (uint)(k & 3);
    const uint4 turn = ((uint4)(0, 1, 2, 3) + r) & 3u, back = ((uint4)(4, 5, 6, 7) - r) & 3u;
    float4 lane_x = shuffle(sum_x, turn), lane_y = shuffle(sum_y, turn), lane_t = shuffle(sum_t, turn);
    for (; k < range.y; k += AP_LANES) {
      /* Lanes past the range's end read the next slots (the slot arrays end in AP_LANES spare slots) and
       * add +0. */
      const ap_intv past = ap_lane_index_int() >= (ap_intv)(range.y - k);
      const ap_intv own_lane = ap_vloadi(0, slot_element + k) == own;
      const ap_intv skip = (own_only != 0 ? ~own_lane : own_lane) | past;
      if (all(skip)) continue;
      ap_floatv qx, qy, qt;
      closest_point_on_triangles(px, py, pt, ap_vloadf(0, ax + k), ap_vloadf(0, ay + k), ap_vloadf(0, at + k),
                                 ap_vloadf(0, bx + k), ap_vloadf(0, by + k), ap_vloadf(0, bt + k), ap_vloadf(0, cx + k),
                                 ap_vloadf(0, cy + k), ap_vloadf(0, ct + k), &qx, &qy, &qt);
      const ap_floatv ux = px - qx, uy = py - qy, ut = pt - qt;
      const ap_floatv d2 = ux * ux + uy * uy + ut * ut;
      /* repulsion_weight with count 1, lane by lane. */
      const ap_floatv w = 1.0f / sqrt(d2) * (1.0f / (eps + d2)) * 1.0f;
      const ap_intv take = ~skip & (d2 > 0.0f);
      const ap_floatv zero = (ap_floatv)(0.0f);
      const ap_floatv wx = select(zero, ux * w, take), wy = select(zero, uy * w, take), wt = select(zero, ut * w, take);
      lane_x = lane_x + wx.s0123, lane_y = lane_y + wy.s0123, lane_t = lane_t + wt.s0123;
      lane_x = lane_x + wx.s4567, lane_y = lane_y + wy.s4567, lane_t = lane_t + wt.s4567;
      lane_x = lane_x + wx.s89ab, lane_y = lane_y + wy.s89ab, lane_t = lane_t + wt.s89ab;
      lane_x = lane_x + wx.scdef, lane_y = lane_y + wy.scdef, lane_t = lane_t + wt.scdef;
      /* The nearest distance is a minimum, exact in any order; NaN lanes are ignored as `d2 < c2` does. */
      const ap_floatv other_d2 = select(d2, (ap_floatv)(INFINITY), skip);
      const float8 m8 = fmin(other_d2.lo, other_d2.hi);
      const float4 m4 = fmin(m8.lo, m8.hi);
      c2 = fmin(c2, fmin(fmin(m4.x, m4.y), fmin(m4.z, m4.w)));
    }
    k = range.y;
    sum_x = shuffle(lane_x, back), sum_y = shuffle(lane_y, back), sum_t = shuffle(lane_t, back);
  }
#endif
  for (; k < range.y; ++k) {
    if ((slot_element[k] == own) != (own_only != 0)) continue;
    float qx, qy, qt;
    closest_point_on_triangle(px, py, pt, ax[k], ay[k], at[k], bx[k], by[k], bt[k], cx[k], cy[k], ct[k], &qx, &qy, &qt);
    const float ux = px - qx, uy = py - qy, ut = pt - qt;
    const float d2 = ux * ux + uy * uy + ut * ut;
    if (d2 < c2) c2 = d2;
    repulsion_add_partial(k, ux, uy, ut, eps, &sum_x, &sum_y, &sum_t);
  }
  *ax_sum = sum_x, *ay_sum = sum_y, *at_sum = sum_t, *closest2 = c2;
}

/** Far term of Eq. 1 for the cells cx_lo … cx_hi of row (cy, ct), from triangles not owned by `own` (with
 * own_only, owned by it) (repulsion.cpp): every triangle's centroid in slot order, or with far_cells
 * the row's runs in order (grid_runs), a run's mean centroid counted once per triangle of the run. */
AP_INLINE void repulsion_far_slots(const GridInfo grid,
                                   __global const int* cell_start,
                                   int cy,
                                   int ct,
                                   int cx_lo,
                                   int cx_hi,
                                   int own,
                                   int own_only,
                                   float px,
                                   float py,
                                   float pt,
                                   float eps,
                                   __global const int* slot_element,
                                   __global const float* slot_cx,
                                   __global const float* slot_cy,
                                   __global const float* slot_ct,
                                   __global const int* run_start,
                                   __global const int* run_element,
                                   __global const float4* runs,
                                   float* sx,
                                   float* sy,
                                   float* st) {
  if (grid.far_cells) {
    const int2 range = grid_row_range(grid, run_start, cy, ct, cx_lo, cx_hi);
    for (int r = range.x; r < range.y; ++r) {
      if ((run_element[r] == own) != (own_only != 0)) continue;
      const float4 m = runs[r];
      repulsion_add_term(px - m.x, py - m.y, pt - m.z, eps, m.w, sx, sy, st);
    }
    return;
  }
  const int2 range = grid_row_range(grid, cell_start, cy, ct, cx_lo, cx_hi);
  for (int k = range.x; k < range.y; ++k) {
    if ((slot_element[k] == own) != (own_only != 0)) continue;
    repulsion_add_term(px - slot_cx[k], py - slot_cy[k], pt - slot_ct[k], eps, 1.0f, sx, sy, st);
  }
}

/** Eq. 1's sum at (px, py, pt) (reference eq1_sum): the 3x3x3 near block with exact closest points in
 * four partial sums, joined as (p0 + p1) + (p2 + p3); then the outer shell of the 5x5x5 block with
 * centroids added to that one by one (the reference collects both lists and sums near before far), row by
 * row. Triangles of elements other than `own`, or with own_only of `own` alone; *closest2 is the least
 * squared near distance. */
void repulsion_sum(const GridInfo grid,
                   __global const int* cell_start,
                   __global const int* slot_element,
                   __global const float* slot_vertices,
                   __global const float* slot_cx,
                   __global const float* slot_cy,
                   __global const float* slot_ct,
                   __global const int* run_start,
                   __global const int* run_element,
                   __global const float4* runs,
                   int own,
                   int own_only,
                   float px,
                   float py,
                   float pt,
                   float eps,
                   float* out_x,
                   float* out_y,
                   float* out_t,
                   float* out_closest2) {
  float4 near_x = (float4)(0.0f), near_y = (float4)(0.0f), near_t = (float4)(0.0f);
  float closest2 = INFINITY;
  const int qx = grid_axis_cell(px, grid.cell, grid.n);
  const int qy = grid_axis_cell(py, grid.cell, grid.n);
  const int qt = grid_axis_cell(pt, grid.cell, grid.n);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy) {
      const int2 row = grid_row_range(grid, cell_start, qy + dy, qt + dz, qx - 1, qx + 1);
      if (!grid.far_cells) {
        repulsion_near_slots(row, own, own_only, px, py, pt, eps, slot_element, slot_vertices, grid.triangles, &near_x,
                             &near_y, &near_t, &closest2);
        continue;
      }
      /* The row's runs (grid_runs) say where its slots of the element to leave out lie: the slots
       * between them are walked, the runs left out are not (the walk would add +0 for each of their
       * slots, which leaves the partials as they are). Runs and slots are both in cell order. */
      const int2 run = grid_row_range(grid, run_start, qy + dy, qt + dz, qx - 1, qx + 1);
      int k = row.x, from = row.x;
      for (int r = run.x; r < run.y; ++r) {
        const int count = (int)runs[r].w;
        if ((run_element[r] == own) != (own_only != 0)) {
          if (from < k)
            repulsion_near_slots((int2)(from, k), own, own_only, px, py, pt, eps, slot_element, slot_vertices,
                                 grid.triangles, &near_x, &near_y, &near_t, &closest2);
          from = k + count;
        }
        k += count;
      }
      if (from < row.y)
        repulsion_near_slots((int2)(from, row.y), own, own_only, px, py, pt, eps, slot_element, slot_vertices,
                             grid.triangles, &near_x, &near_y, &near_t, &closest2);
    }
  float sx = (near_x.x + near_x.y) + (near_x.z + near_x.w);
  float sy = (near_y.x + near_y.y) + (near_y.z + near_y.w);
  float st = (near_t.x + near_t.y) + (near_t.z + near_t.w);
  for (int dz = -2; dz <= 2; ++dz) {
    for (int dy = -2; dy <= 2; ++dy) {
      const int cy = qy + dy, ct = qt + dz;
      if (abs(dz) == 2 || abs(dy) == 2) { /* the whole row is in the shell */
        repulsion_far_slots(grid, cell_start, cy, ct, qx - 2, qx + 2, own, own_only, px, py, pt, eps, slot_element,
                            slot_cx, slot_cy, slot_ct, run_start, run_element, runs, &sx, &sy, &st);
      } else { /* only the row's two end cells are */
        repulsion_far_slots(grid, cell_start, cy, ct, qx - 2, qx - 2, own, own_only, px, py, pt, eps, slot_element,
                            slot_cx, slot_cy, slot_ct, run_start, run_element, runs, &sx, &sy, &st);
        repulsion_far_slots(grid, cell_start, cy, ct, qx + 2, qx + 2, own, own_only, px, py, pt, eps, slot_element,
                            slot_cx, slot_cy, slot_ct, run_start, run_element, runs, &sx, &sy, &st);
      }
    }
  }
  *out_x = sx, *out_y = sy, *out_t = st, *out_closest2 = closest2;
}

/** Eq. 1 for each boundary vertex, with its distance to the nearest other element (+inf when nothing
 * is near) and its overlap test (a vertex that overlaps gets no Eq. 1 force: Eq. 3 takes over).
 * One work-item per boundary vertex, so no work-item of a group idles through an interior vertex;
 * step_forces reads the results back per vertex. */
__kernel void repulsion_force(
    const GridInfo grid,
    const ForceParams p,
    const WorldInfo world,
    __global const int* boundary_vertices,        /* input: world.boundaries of them */
    __global const float* positions,              /* input: x, y, t */
    __global const int* vertex_topology,          /* input: AP_TOPO_ELEMENT, AP_TOPO_SLICE */
    __global const int* grid_index,               /* input: AP_INDEX_* */
    __global const float* slot_vertices,          /* input: per grid slot (slot_positions) */
    __global const float* slot_centroids,         /* input: per grid slot (grid_gather) */
    __global const float4* runs,                  /* input: per run (grid_runs) */
    __global const int* slice_topology,           /* input: AP_SLICES_* */
    __global const float* slice_geometry,         /* input: AP_GEOM_X0 … AP_GEOM_T, slice_boxes */
    __global const float* curve_planes,           /* input: AP_CURVE_*, tangents and handles */
    __global const float* growth,                 /* input: g per slice */
    __global float* repulsion,                    /* output: AP_RPL_* per boundary vertex */
    __global uchar* repulsion_contact,            /* output: AP_CONTACT_OVERLAP / _INSIDE / _YIELD / _BLOCK */
    __global const OverlapGridInfo* overlap_grid, /* the overlap test's broadphase */
    __global const int* overlap_start,            /* input: its cells + 1 */
    __global const int* overlap_elements) {       /* input: its element lists */
  const int i = get_global_id(0);
  if (i >= world.boundaries) return;
  const int vs = world.vertex_stride, ss = world.slice_stride;
  __global const float* x = positions + AP_X * vs;
  __global const float* y = positions + AP_Y * vs;
  __global const float* t = positions + AP_T * vs;
  __global const int* element = vertex_topology + AP_TOPO_ELEMENT * vs;
  __global const int* cell_start = grid_index + AP_INDEX_CELL_START * grid.index_stride;
  __global const int* slot_element = grid_index + AP_INDEX_SLOT_ELEMENT * grid.index_stride;
  __global const int* run_start = grid_index + AP_INDEX_RUN_START * grid.index_stride;
  __global const int* run_element = grid_index + AP_INDEX_RUN_ELEMENT * grid.index_stride;
  __global const float* slot_cx = slot_centroids + AP_X * grid.slot_stride;
  __global const float* slot_cy = slot_centroids + AP_Y * grid.slot_stride;
  __global const float* slot_ct = slot_centroids + AP_T * grid.slot_stride;
  const int v = boundary_vertices[i];
  const float px = x[v], py = y[v], pt = t[v];
  const int own = element[v];
  float way_out_x, way_out_y;
  const CurveArrays curve = {x,
                             y,
                             curve_planes + AP_CURVE_TANGENT_X * vs,
                             curve_planes + AP_CURVE_TANGENT_Y * vs,
                             curve_planes + AP_CURVE_HANDLE_PX * vs,
                             curve_planes + AP_CURVE_HANDLE_PY * vs,
                             curve_planes + AP_CURVE_HANDLE_QX * vs,
                             curve_planes + AP_CURVE_HANDLE_QY * vs};
  const uchar bits = overlap_test(v, p.interval_points, world.elements, element, vertex_topology + AP_TOPO_SLICE * vs,
                                  slice_topology + AP_SLICES_ELEMENT_BEGIN * ss, slice_topology + AP_SLICES_BEGIN * ss,
                                  slice_topology + AP_SLICES_BOUNDARY * ss, slice_geometry + AP_GEOM_X0 * ss,
                                  slice_geometry + AP_GEOM_Y0 * ss, slice_geometry + AP_GEOM_X1 * ss,
                                  slice_geometry + AP_GEOM_Y1 * ss, slice_geometry + AP_GEOM_T * ss, t, curve,
                                  p.motion_curve, growth, slice_topology + AP_SLICES_SECONDARY * ss, *overlap_grid,
                                  overlap_start, overlap_elements, &way_out_x, &way_out_y);
  const bool overlapping = bits != 0;
  const float eps = p.repulsion_epsilon;
  float sx, sy, st, closest2;
  repulsion_sum(grid, cell_start, slot_element, slot_vertices, slot_cx, slot_cy, slot_ct, run_start, run_element, runs,
                own, 0, px, py, pt, eps, &sx, &sy, &st, &closest2);
  const float k = p.k_repulsion;
  repulsion[AP_RPL_X * vs + v] = overlapping ? 0.0f : k * sx;
  repulsion[AP_RPL_Y * vs + v] = overlapping ? 0.0f : k * sy;
  repulsion[AP_RPL_T * vs + v] = overlapping ? 0.0f : k * st;
  repulsion[AP_RPL_CLOSEST * vs + v] = sqrt(closest2);
  repulsion_contact[v] = bits;
  repulsion[AP_RPL_DEPTH_X * vs + v] = way_out_x;
  repulsion[AP_RPL_DEPTH_Y * vs + v] = way_out_y;
}
