/* The overlap test's broadphase built on the device, so that a step on a GPU never waits for the host
 * (docs/architecture.md, "The overlap test"). It does the job of reference::build_overlap_grid, with
 * its own cell rule in float: the broadphase only chooses which elements the exact box test tries,
 * and any grid that lists every element whose slice-pair box meets a cell gives the same forces.
 *
 * The steps, one launch each: overlap_grid_extent (one work-group) spans the slice pairs' boxes and
 * picks the cells; grid_clear; overlap_grid_count (one item per pair); the collision grid's scan
 * (grid_block_sums, grid_scan_blocks, grid_scan_cells, grid.cl) over the cell capacity;
 * overlap_grid_scatter (one item per pair); overlap_grid_order (one item per cell). A cell may list
 * an element more than once (several of its pairs meet the cell): the query's merge skips repeats
 * (overlap_next_candidate). When the lists outgrow their buffer, the grid is dropped for that step
 * (nx = 0: every query tries every element, the same forces, slower) and the total is left for the
 * host to read with the statistics and make room. */

/** The box of slice pair s → s + 1, the union of the two slices' boxes and their t range (reference
 * pair_box in overlap.cpp), as its low corner then its high one: x0, y0, t0, x1, y1, t1. */
void overlap_pair_box(int s,
                      __global const float* box_x0,
                      __global const float* box_y0,
                      __global const float* box_x1,
                      __global const float* box_y1,
                      __global const float* box_t,
                      float* b) {
  b[0] = ap_min(box_x0[s], box_x0[s + 1]), b[1] = ap_min(box_y0[s], box_y0[s + 1]);
  b[2] = ap_min(box_t[s], box_t[s + 1]);
  b[3] = ap_max(box_x1[s], box_x1[s + 1]), b[4] = ap_max(box_y1[s], box_y1[s + 1]);
  b[5] = ap_max(box_t[s], box_t[s + 1]);
}

/** Cells per axis for a span and a cell edge, at most 1024 (reference build_overlap_grid). */
long overlap_grid_axis(float span, float edge) { return (long)fmin(1024.0f, floor(span / edge) + 1.0f); }

/** The grid over the pairs' boxes, by one work-group of AP_LOCAL_SIZE items: the union of the boxes,
 * a cell edge of their mean extent (the larger of x and y; t on its own), doubled until the cells are
 * no more than 8 per pair + 64 and no more than `cell_capacity`. A box that is not finite (a blown-up
 * state) leaves the grid without cells (nx = 0), as the reference does for NaN. */
__kernel void overlap_grid_extent(const WorldInfo world,
                                  const int pairs,
                                  const int cell_capacity,               /* cells the buffers hold */
                                  __global const int* pair_slice,        /* input: lower slice per pair */
                                  __global const float* slice_geometry,  /* input: slice_boxes */
                                  __global OverlapGridInfo* grid_info) { /* output: one */
  __global const float* box_x0 = slice_geometry + AP_GEOM_X0 * world.slice_stride;
  __global const float* box_y0 = slice_geometry + AP_GEOM_Y0 * world.slice_stride;
  __global const float* box_x1 = slice_geometry + AP_GEOM_X1 * world.slice_stride;
  __global const float* box_y1 = slice_geometry + AP_GEOM_Y1 * world.slice_stride;
  __global const float* box_t = slice_geometry + AP_GEOM_T * world.slice_stride;
  __local float low[3][AP_LOCAL_SIZE], high[3][AP_LOCAL_SIZE], extent[3][AP_LOCAL_SIZE];
  __local int bad[AP_LOCAL_SIZE];
  const int item = get_local_id(0);
  float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, sum[3] = {0.0f, 0.0f, 0.0f};
  int broken = 0;
  for (int i = item; i < pairs; i += AP_LOCAL_SIZE) {
    float b[6];
    overlap_pair_box(pair_slice[i], box_x0, box_y0, box_x1, box_y1, box_t, b);
    for (int a = 0; a < 3; ++a) {
      broken |= !isfinite(b[a]) || !isfinite(b[a + 3]);
      lo[a] = fmin(lo[a], b[a]);
      hi[a] = fmax(hi[a], b[a + 3]);
      sum[a] += b[a + 3] - b[a];
    }
  }
  for (int a = 0; a < 3; ++a) low[a][item] = lo[a], high[a][item] = hi[a], extent[a][item] = sum[a];
  bad[item] = broken;
  barrier(CLK_LOCAL_MEM_FENCE);
  for (int stride = AP_LOCAL_SIZE / 2; stride > 0; stride /= 2) {
    if (item < stride) {
      for (int a = 0; a < 3; ++a) {
        low[a][item] = fmin(low[a][item], low[a][item + stride]);
        high[a][item] = fmax(high[a][item], high[a][item + stride]);
        extent[a][item] += extent[a][item + stride];
      }
      bad[item] |= bad[item + stride];
    }
    barrier(CLK_LOCAL_MEM_FENCE);
  }
  if (item != 0) return;
  OverlapGridInfo g;
  g.nx = g.ny = g.nt = 0;
  g.x0 = low[0][0], g.y0 = low[1][0], g.t0 = low[2][0];
  g.cell = g.cell_t = 1.0f;
  const float span_x = high[0][0] - low[0][0], span_y = high[1][0] - low[1][0], span_t = high[2][0] - low[2][0];
  if (pairs > 0 && !bad[0] && isfinite(span_x) && isfinite(span_y) && isfinite(span_t)) {
    float cell = fmax(extent[0][0], extent[1][0]) / (float)pairs, cell_t = extent[2][0] / (float)pairs;
    if (!(cell > 0.0f)) cell = fmax(fmax(span_x, span_y), 1.0f);
    if (!(cell_t > 0.0f)) cell_t = fmax(span_t, 1.0f);
    const long limit = min(8L * pairs + 64L, (long)cell_capacity);
    /* Each doubling at least halves the cells on an axis above one cell; 64 are far more than needed. */
    for (int k = 0;
         k < 64 &&
         overlap_grid_axis(span_x, cell) * overlap_grid_axis(span_y, cell) * overlap_grid_axis(span_t, cell_t) > limit;
         ++k)
      cell *= 2.0f, cell_t *= 2.0f;
    const long cells =
        overlap_grid_axis(span_x, cell) * overlap_grid_axis(span_y, cell) * overlap_grid_axis(span_t, cell_t);
    if (cells <= limit) {
      g.cell = cell, g.cell_t = cell_t;
      g.nx = (int)overlap_grid_axis(span_x, cell), g.ny = (int)overlap_grid_axis(span_y, cell);
      g.nt = (int)overlap_grid_axis(span_t, cell_t);
    }
  }
  *grid_info = g;
}

/** The cells a pair's box b (overlap_pair_box) meets: [c0, c1] per axis (x, y, t); false when the grid
 * has no cells. */
bool overlap_pair_cells(const OverlapGridInfo g, const float* b, int* c0, int* c1) {
  if (g.nx == 0) return false;
  c0[0] = grid_axis_cell(b[0] - g.x0, g.cell, g.nx), c1[0] = grid_axis_cell(b[3] - g.x0, g.cell, g.nx);
  c0[1] = grid_axis_cell(b[1] - g.y0, g.cell, g.ny), c1[1] = grid_axis_cell(b[4] - g.y0, g.cell, g.ny);
  c0[2] = grid_axis_cell(b[2] - g.t0, g.cell_t, g.nt), c1[2] = grid_axis_cell(b[5] - g.t0, g.cell_t, g.nt);
  return true;
}

/** Counts, per cell, the pairs whose box meets it; one work-item per pair. */
__kernel void overlap_grid_count(const WorldInfo world,
                                 const int pairs,
                                 __global const int* pair_slice,            /* input: lower slice per pair */
                                 __global const float* slice_geometry,      /* input: slice_boxes */
                                 __global const OverlapGridInfo* grid_info, /* input: overlap_grid_extent */
                                 __global int* cell_count) {                /* in/out: per cell */
  __global const float* box_x0 = slice_geometry + AP_GEOM_X0 * world.slice_stride;
  __global const float* box_y0 = slice_geometry + AP_GEOM_Y0 * world.slice_stride;
  __global const float* box_x1 = slice_geometry + AP_GEOM_X1 * world.slice_stride;
  __global const float* box_y1 = slice_geometry + AP_GEOM_Y1 * world.slice_stride;
  __global const float* box_t = slice_geometry + AP_GEOM_T * world.slice_stride;
  const int i = get_global_id(0);
  if (i >= pairs) return;
  float b[6];
  int c0[3], c1[3];
  overlap_pair_box(pair_slice[i], box_x0, box_y0, box_x1, box_y1, box_t, b);
  const OverlapGridInfo g = *grid_info;
  if (!overlap_pair_cells(g, b, c0, c1)) return;
  for (int it = c0[2]; it <= c1[2]; ++it)
    for (int iy = c0[1]; iy <= c1[1]; ++iy)
      for (int ix = c0[0]; ix <= c1[0]; ++ix) atomic_inc(&cell_count[(it * g.ny + iy) * g.nx + ix]);
}

/** Lists pair i's element in every cell its box meets, at slots claimed from the cells' cursors (in
 * no particular order: overlap_grid_order sorts them); nothing when the lists would outgrow
 * `capacity` entries. One work-item per pair. */
__kernel void overlap_grid_scatter(const WorldInfo world,
                                   const int pairs,
                                   const int cell_capacity,
                                   const int capacity,
                                   __global const int* pair_slice,            /* input: lower slice per pair */
                                   __global const int* pair_element,          /* input: owner per pair */
                                   __global const float* slice_geometry,      /* input: slice_boxes */
                                   __global const OverlapGridInfo* grid_info, /* input: overlap_grid_extent */
                                   __global const int* cell_start,            /* input: cell_capacity + 1 */
                                   __global int* cursor,                      /* in/out: per cell */
                                   __global int* elements) {                  /* output: capacity */
  __global const float* box_x0 = slice_geometry + AP_GEOM_X0 * world.slice_stride;
  __global const float* box_y0 = slice_geometry + AP_GEOM_Y0 * world.slice_stride;
  __global const float* box_x1 = slice_geometry + AP_GEOM_X1 * world.slice_stride;
  __global const float* box_y1 = slice_geometry + AP_GEOM_Y1 * world.slice_stride;
  __global const float* box_t = slice_geometry + AP_GEOM_T * world.slice_stride;
  const int i = get_global_id(0);
  if (i >= pairs || cell_start[cell_capacity] > capacity) return;
  float b[6];
  int c0[3], c1[3];
  overlap_pair_box(pair_slice[i], box_x0, box_y0, box_x1, box_y1, box_t, b);
  const OverlapGridInfo g = *grid_info;
  if (!overlap_pair_cells(g, b, c0, c1)) return;
  const int e = pair_element[i];
  for (int it = c0[2]; it <= c1[2]; ++it)
    for (int iy = c0[1]; iy <= c1[1]; ++iy)
      for (int ix = c0[0]; ix <= c1[0]; ++ix) elements[atomic_inc(&cursor[(it * g.ny + iy) * g.nx + ix])] = e;
}

/** Puts each cell's list in increasing element order (grid_sort_range); one work-item per cell. Item 0 leaves the lists' total in *total and, when it outgrew `capacity`
 * (nothing was listed), drops the grid for this step (nx = 0: every query tries every element). */
__kernel void overlap_grid_order(const int cell_capacity,
                                 const int capacity,
                                 __global const int* cell_start,      /* input: cell_capacity + 1 */
                                 __global int* elements,              /* in/out */
                                 __global OverlapGridInfo* grid_info, /* in/out */
                                 __global int* total) {               /* output: one */
  const int c = get_global_id(0);
  if (c >= cell_capacity) return;
  const int all = cell_start[cell_capacity];
  if (c == 0) {
    *total = all;
    if (all > capacity) grid_info->nx = 0;
  }
  if (all <= capacity) grid_sort_range(elements, cell_start[c], cell_start[c + 1]);
}
