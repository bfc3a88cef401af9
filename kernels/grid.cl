/* Collision grid of §5.1, device half: envelope-triangle centroids and their cells. The stable
 * counting sort runs on the host (opencl_backend.cpp) from the cell ids this writes. */

/** Cell of one coordinate: clamp(floor(c / cell), 0, n - 1) in float, NaN to 0 (grid.cpp). */
int grid_axis_cell(float c, float cell, int n) {
  float f = floor(c / cell);
  if (!(f >= 0.0f)) f = 0.0f;
  const float last = (float)(n - 1);
  if (f > last) f = last;
  return (int)f;
}

/** Centroid (a + b + c) / 3 and linear cell of every envelope triangle; one work-item per triangle. */
__kernel void envelope_cells(const GridInfo grid,            /* input */
                             __global const int* env_a,      /* input: vertex ids per triangle */
                             __global const int* env_b,      /* input */
                             __global const int* env_c,      /* input */
                             __global const float* x,        /* input: positions per vertex */
                             __global const float* y,        /* input */
                             __global const float* t,        /* input */
                             __global float* cx,             /* output: centroid per triangle */
                             __global float* cy,             /* output */
                             __global float* ct,             /* output */
                             __global int* triangle_cell) {  /* output: linear cell per triangle */
  const int i = get_global_id(0);
  if (i >= grid.triangles) return;
  const int a = env_a[i], b = env_b[i], c = env_c[i];
  const float px = (x[a] + x[b] + x[c]) / 3.0f;
  const float py = (y[a] + y[b] + y[c]) / 3.0f;
  const float pt = (t[a] + t[b] + t[c]) / 3.0f;
  cx[i] = px;
  cy[i] = py;
  ct[i] = pt;
  const int ix = grid_axis_cell(px, grid.cell, grid.n);
  const int iy = grid_axis_cell(py, grid.cell, grid.n);
  const int it = grid_axis_cell(pt, grid.cell, grid.n);
  triangle_cell[i] = (it * grid.n + iy) * grid.n + ix;
}
