/* Collision grid of §5.1 on the device: envelope-triangle centroids and their cells, the stable
 * counting sort (or its host twin in grid_schedule.cpp), the per-slot copies the force kernels read,
 * and the row ranges they walk. */

/** Cell of one coordinate: clamp(floor(c / cell), 0, n - 1) in float, NaN to 0 (state.hpp). */
int grid_axis_cell(float c, float cell, int n) {
  float f = floor(c / cell);
  if (!(f >= 0.0f)) f = 0.0f;
  const float last = (float)(n - 1);
  if (f > last) f = last;
  return (int)f;
}

/** Linear cell of point (x, y, t): t-major, then y, then x (state.hpp, grid_linear_cell). */
int grid_linear_cell(const GridInfo grid, float x, float y, float t) {
  return (grid_axis_cell(t, grid.cell, grid.n) * grid.n + grid_axis_cell(y, grid.cell, grid.n)) * grid.n +
         grid_axis_cell(x, grid.cell, grid.n);
}

/** Centroid (a + b + c) / 3 and linear cell of every envelope triangle; one work-item per triangle. */
__kernel void envelope_cells(const GridInfo grid,             /* input */
                             const WorldInfo world,           /* input: positions' stride */
                             __global const int* env_a,       /* input: vertex ids per triangle */
                             __global const int* env_b,       /* input */
                             __global const int* env_c,       /* input */
                             __global const float* positions, /* input: x, y, t per vertex */
                             __global float* cx,              /* output: centroid per triangle */
                             __global float* cy,              /* output */
                             __global float* ct,              /* output */
                             __global int* triangle_cell) {   /* output: linear cell per triangle */
  __global const float* x = positions + AP_X * world.vertex_stride;
  __global const float* y = positions + AP_Y * world.vertex_stride;
  __global const float* t = positions + AP_T * world.vertex_stride;
  const int i = get_global_id(0);
  if (i >= grid.triangles) return;
  const int a = env_a[i], b = env_b[i], c = env_c[i];
  const float px = (x[a] + x[b] + x[c]) / 3.0f;
  const float py = (y[a] + y[b] + y[c]) / 3.0f;
  const float pt = (t[a] + t[b] + t[c]) / 3.0f;
  cx[i] = px;
  cy[i] = py;
  ct[i] = pt;
  triangle_cell[i] = grid_linear_cell(grid, px, py, pt);
}

/* The stable counting sort on the device, for devices where reading the cell ids back to the host
 * costs more than sorting them here (GPUs; src/solver/opencl/opencl_backend.cpp picks). The same three
 * steps as grid.cpp: count, exclusive scan, scatter. The scatter claims slots with atomics, so each
 * cell's range is then put in increasing triangle id: exactly the order the stable scatter gives. */

/** Zeroes the per-cell counts; one work-item per cell. */
__kernel void grid_clear(const GridInfo grid, __global int* cell_count) { /* output: per cell */
  const int c = get_global_id(0);
  if (c < grid.cells) cell_count[c] = 0;
}

/** Counts the triangles of every cell; one work-item per triangle. */
__kernel void grid_count(const GridInfo grid,
                         __global const int* triangle_cell, /* input: per triangle */
                         __global int* cell_count) {        /* in/out: per cell */
  const int i = get_global_id(0);
  if (i < grid.triangles) atomic_inc(&cell_count[triangle_cell[i]]);
}

/** Sum of each block of AP_SCAN_BLOCK cells (shared_types.h); one work-item per block. */
__kernel void grid_block_sums(const GridInfo grid,
                              __global const int* cell_count, /* input: per cell */
                              __global int* block_sum) {      /* output: per block */
  const int b = get_global_id(0);
  const int blocks = (grid.cells + AP_SCAN_BLOCK - 1) / AP_SCAN_BLOCK;
  if (b >= blocks) return;
  const int end = min(grid.cells, (b + 1) * AP_SCAN_BLOCK);
  int sum = 0;
  for (int c = b * AP_SCAN_BLOCK; c < end; ++c) sum += cell_count[c];
  block_sum[b] = sum;
}

/** Exclusive scan of the block sums in place, by one work-group of AP_LOCAL_SIZE items: each item
 * scans a run of blocks, the runs' totals are scanned in local memory, then each run is offset. */
__kernel void grid_scan_blocks(const GridInfo grid, __global int* block_sum) { /* in/out: per block */
  __local int run_total[AP_LOCAL_SIZE];
  const int item = get_local_id(0);
  const int blocks = (grid.cells + AP_SCAN_BLOCK - 1) / AP_SCAN_BLOCK;
  const int per_item = (blocks + AP_LOCAL_SIZE - 1) / AP_LOCAL_SIZE;
  const int begin = min(blocks, item * per_item), end = min(blocks, begin + per_item);
  int sum = 0;
  for (int b = begin; b < end; ++b) {
    const int v = block_sum[b];
    block_sum[b] = sum;
    sum += v;
  }
  run_total[item] = sum;
  barrier(CLK_LOCAL_MEM_FENCE);
  int offset = 0;
  for (int k = 0; k < item; ++k) offset += run_total[k];
  for (int b = begin; b < end; ++b) block_sum[b] += offset;
}

/** cell_start (exclusive scan of the counts, plus the total at [cells]) and the scatter cursors;
 * one work-item per block. cell_start is plane start_plane of `starts`, planes grid.index_stride apart
 * (grid_index's cell or run ranges; plane 0 of a buffer of its own). */
__kernel void grid_scan_cells(const GridInfo grid,
                              const int start_plane,
                              __global const int* cell_count,  /* input: per cell */
                              __global const int* block_start, /* input: per block, scanned */
                              __global int* starts,            /* output: cells + 1 in plane start_plane */
                              __global int* cursor) {          /* output: per cell */
  __global int* cell_start = starts + start_plane * grid.index_stride;
  const int b = get_global_id(0);
  const int blocks = (grid.cells + AP_SCAN_BLOCK - 1) / AP_SCAN_BLOCK;
  if (b >= blocks) return;
  const int end = min(grid.cells, (b + 1) * AP_SCAN_BLOCK);
  int start = block_start[b];
  for (int c = b * AP_SCAN_BLOCK; c < end; ++c) {
    cell_start[c] = start;
    cursor[c] = start;
    start += cell_count[c];
  }
  if (end == grid.cells) cell_start[grid.cells] = start;
}

/** Puts every triangle in a slot of its cell's range, in no particular order within the cell. Work-item
 * g takes triangle (triangles - 1 - g): a device that runs work-items in order (PoCL) then fills each
 * cell backwards, so grid_order_cells always has work to do and the equivalence tests exercise it on
 * every device, not only where atomics happen to interleave. */
__kernel void grid_scatter(const GridInfo grid,
                           __global const int* triangle_cell, /* input: per triangle */
                           __global int* cursor,              /* in/out: per cell */
                           __global int* sorted_triangles) {  /* output: triangle ids by cell */
  const int g = get_global_id(0);
  if (g >= grid.triangles) return;
  const int i = grid.triangles - 1 - g;
  sorted_triangles[atomic_inc(&cursor[triangle_cell[i]])] = i;
}

/** Puts ids[begin, end) in increasing order (insertion sort: a grid cell's list is a few dozen long). */
void grid_sort_range(__global int* ids, int begin, int end) {
  for (int k = begin + 1; k < end; ++k) {
    const int id = ids[k];
    int j = k - 1;
    while (j >= begin && ids[j] > id) {
      ids[j + 1] = ids[j];
      --j;
    }
    ids[j + 1] = id;
  }
}

/** Orders one cell's range by triangle id (cell_start as grid_scan_cells writes it). */
__kernel void grid_order_cells(const GridInfo grid,
                               const int start_plane,
                               __global const int* starts,       /* input: cells + 1 in plane start_plane */
                               __global int* sorted_triangles) { /* in/out */
  __global const int* cell_start = starts + start_plane * grid.index_stride;
  const int c = get_global_id(0);
  if (c >= grid.cells) return;
  grid_sort_range(sorted_triangles, cell_start[c], cell_start[c + 1]);
}

/** What the force kernels read per grid slot, copied into sorted order once per rebuild so a cell's
 * triangles are read from consecutive addresses instead of through their ids: owner and centroid (the
 * vertices' positions change every step: slot_positions). Copies only: no arithmetic, so the forces stay
 * bit-identical. */
__kernel void grid_gather(const GridInfo grid,
                          __global const int* sorted_triangles, /* input */
                          __global const int* env_element,      /* input: per triangle */
                          __global const float* cx,
                          __global const float* cy,
                          __global const float* ct,         /* input */
                          __global int* grid_index,         /* output: slot_element per slot */
                          __global float* slot_centroids) { /* output: x, y, t per slot */
  __global int* slot_element = grid_index + AP_INDEX_SLOT_ELEMENT * grid.index_stride;
  __global float* slot_cx = slot_centroids + AP_X * grid.slot_stride;
  __global float* slot_cy = slot_centroids + AP_Y * grid.slot_stride;
  __global float* slot_ct = slot_centroids + AP_T * grid.slot_stride;
  const int k = get_global_id(0);
  if (k >= grid.triangles) return;
  const int tri = sorted_triangles[k];
  slot_element[k] = env_element[tri];
  slot_cx[k] = cx[tri];
  slot_cy[k] = cy[tri];
  slot_ct[k] = ct[tri];
}

/** Every slot's three vertices at this step's positions, in nine planes (AP_SLOT_*), so that the near
 * block reads them from consecutive addresses. Run every step, as the grid may be older than the
 * positions (grid_rebuild_interval); copies only. One work-item per slot. */
__kernel void slot_positions(const GridInfo grid,
                             const WorldInfo world,                /* input: positions' stride */
                             __global const int* sorted_triangles, /* input */
                             __global const int* env_a,
                             __global const int* env_b,
                             __global const int* env_c,
                             __global const float* positions, /* input: x, y, t per vertex */
                             __global float* slot_vertices) { /* output: nine planes of grid.triangles */
  __global const float* x = positions + AP_X * world.vertex_stride;
  __global const float* y = positions + AP_Y * world.vertex_stride;
  __global const float* t = positions + AP_T * world.vertex_stride;
  const int k = get_global_id(0);
  const int n = grid.triangles;
  if (k >= n) return;
  const int tri = sorted_triangles[k];
  const int a = env_a[tri], b = env_b[tri], c = env_c[tri];
  slot_vertices[AP_SLOT_AX * n + k] = x[a];
  slot_vertices[AP_SLOT_AY * n + k] = y[a];
  slot_vertices[AP_SLOT_AT * n + k] = t[a];
  slot_vertices[AP_SLOT_BX * n + k] = x[b];
  slot_vertices[AP_SLOT_BY * n + k] = y[b];
  slot_vertices[AP_SLOT_BT * n + k] = t[b];
  slot_vertices[AP_SLOT_CX * n + k] = x[c];
  slot_vertices[AP_SLOT_CY * n + k] = y[c];
  slot_vertices[AP_SLOT_CT * n + k] = t[c];
}

/** How many runs of slots owned by one element each cell holds (grid_runs); one work-item per cell. */
__kernel void grid_run_counts(const GridInfo grid,
                              __global const int* grid_index, /* input: cell_start, slot_element (grid_gather) */
                              __global int* cell_runs) {      /* output: per cell */
  __global const int* cell_start = grid_index + AP_INDEX_CELL_START * grid.index_stride;
  __global const int* slot_element = grid_index + AP_INDEX_SLOT_ELEMENT * grid.index_stride;
  const int c = get_global_id(0);
  if (c >= grid.cells) return;
  const int begin = cell_start[c], end = cell_start[c + 1];
  int runs = 0;
  for (int k = begin; k < end; ++k) runs += k == begin || slot_element[k] != slot_element[k - 1];
  cell_runs[c] = runs;
}

/** The far field's cell aggregates (grid.cpp, build_far_runs): each run of a cell's slots owned by one
 * element, in slot order, packed over the whole grid in cell order (run_start: the exclusive scan of
 * grid_run_counts), holds the mean of its centroids (summed in slot order, then divided by the count),
 * the count (.w) and its element (run_element). A row of cells then has its runs at consecutive
 * addresses: the far shell walks one range per row instead of hopping from run to run. One work-item
 * per cell. */
__kernel void grid_runs(const GridInfo grid,
                        __global int* grid_index, /* input: cell_start, slot_element, run_start; output: run_element */
                        __global const float* slot_centroids, /* input: x, y, t per slot */
                        __global float* runs) {               /* output: per run, four floats (a float4 to readers) */
  __global const int* cell_start = grid_index + AP_INDEX_CELL_START * grid.index_stride;
  __global const int* slot_element = grid_index + AP_INDEX_SLOT_ELEMENT * grid.index_stride;
  __global const int* run_start = grid_index + AP_INDEX_RUN_START * grid.index_stride;
  __global int* run_element = grid_index + AP_INDEX_RUN_ELEMENT * grid.index_stride;
  __global const float* slot_cx = slot_centroids + AP_X * grid.slot_stride;
  __global const float* slot_cy = slot_centroids + AP_Y * grid.slot_stride;
  __global const float* slot_ct = slot_centroids + AP_T * grid.slot_stride;
  const int c = get_global_id(0);
  if (c >= grid.cells) return;
  const int end = cell_start[c + 1];
  int head = cell_start[c], r = run_start[c];
  while (head < end) {
    const int owner = slot_element[head];
    float sx = 0.0f, sy = 0.0f, st = 0.0f;
    int k = head;
    for (; k < end && slot_element[k] == owner; ++k) {
      sx = sx + slot_cx[k];
      sy = sy + slot_cy[k];
      st = st + slot_ct[k];
    }
    const float count = (float)(k - head);
    runs[4 * r] = sx / count;
    runs[4 * r + 1] = sy / count;
    runs[4 * r + 2] = st / count;
    runs[4 * r + 3] = count;
    run_element[r] = owner;
    ++r;
    head = k;
  }
}

/* The repulsion kernel's work order on the device (src/solver/opencl/boundary_order.cpp): the boundary
 * vertices sorted by the cell they are in, by the counting sort above run over a GridInfo whose
 * `triangles` is the boundary vertex count. Any order gives the same forces. */

/** Each boundary vertex's linear cell (as envelope_cells gives a centroid's) and a copy of the order
 * it is sorted from; one work-item per boundary vertex. */
__kernel void boundary_cells(const GridInfo grid,             /* grid.triangles: the boundary vertices */
                             const WorldInfo world,           /* input: positions' stride */
                             __global const int* order,       /* input: the boundary vertices, last order */
                             __global const float* positions, /* input: x, y, t per vertex */
                             __global int* cell,              /* output: per boundary vertex */
                             __global int* previous) {        /* output: a copy of order */
  __global const float* x = positions + AP_X * world.vertex_stride;
  __global const float* y = positions + AP_Y * world.vertex_stride;
  __global const float* t = positions + AP_T * world.vertex_stride;
  const int i = get_global_id(0);
  if (i >= grid.triangles) return;
  const int v = order[i];
  previous[i] = v;
  cell[i] = grid_linear_cell(grid, x[v], y[v], t[v]);
}

/** The new order: the vertex at each sorted index (grid_scatter and grid_order_cells sorted the indices
 * into `previous` by cell, increasing within a cell); one work-item per boundary vertex. */
__kernel void boundary_gather(const GridInfo grid,          /* grid.triangles: the boundary vertices */
                              __global const int* sorted,   /* input: indices into previous, by cell */
                              __global const int* previous, /* input: from boundary_cells */
                              __global int* order) {        /* output: the boundary vertices */
  const int j = get_global_id(0);
  if (j < grid.triangles) order[j] = previous[sorted[j]];
}

/** The linear cells cx_lo … cx_hi (clamped to the grid) of row (cy, ct), first and last; first > last when
 * none is on the grid. */
int2 grid_row_cells(const GridInfo grid, int cy, int ct, int cx_lo, int cx_hi) {
  if (cy < 0 || ct < 0 || cy >= grid.n || ct >= grid.n) return (int2)(0, -1);
  cx_lo = max(cx_lo, 0);
  cx_hi = min(cx_hi, grid.n - 1);
  const int row = (ct * grid.n + cy) * grid.n;
  return cx_lo > cx_hi ? (int2)(0, -1) : (int2)(row + cx_lo, row + cx_hi);
}

/** The range of grid slots of the cells cx_lo..cx_hi in row (cy, ct), empty when the row is outside
 * the grid. Cells of one row are consecutive in the linear order, so visiting the range front to back
 * visits the cells in dx order and each cell's triangles in sorted order, as the reference's per-cell
 * loop does. */
AP_INLINE int2
grid_row_range(const GridInfo grid, __global const int* cell_start, int cy, int ct, int cx_lo, int cx_hi) {
  const int2 cells = grid_row_cells(grid, cy, ct, cx_lo, cx_hi);
  if (cells.x > cells.y) return (int2)(0, 0);
  return (int2)(cell_start[cells.x], cell_start[cells.y + 1]);
}
