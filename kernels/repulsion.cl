/* Repulsion, paper Eq. 1 (src/solver/reference/repulsion.cpp): k_rpl Σ u/|u| · 1/(ε + |u|²) over the
 * exact closest points on the near envelope triangles of other elements, then the centroids of the
 * far ones, in the grid's visiting order (cells by dz, dy, dx ascending, sorted order within a cell). */

/** One term of Eq. 1; a point exactly at x has no direction and adds nothing. */
void repulsion_add_term(float ux, float uy, float ut, float eps, float* sx, float* sy, float* st) {
  const float d2 = ux * ux + uy * uy + ut * ut;
  if (!(d2 > 0.0f)) return;
  const float inv_len = 1.0f / sqrt(d2);
  const float w = inv_len * (1.0f / (eps + d2));
  *sx = *sx + ux * w;
  *sy = *sy + uy * w;
  *st = *st + ut * w;
}

/** Eq. 1 on boundary vertex (px, py, pt) of element `own`, and its distance to the nearest other
 * element (+inf when nothing is near). The force is zero while `inside` (Eq. 3 takes over). */
void repulsion_force(const GridInfo grid, const ForceParams p, int own, float px, float py, float pt, bool inside,
                     __global const int* cell_start, __global const int* sorted_triangles,
                     __global const int* env_element, __global const int* env_a, __global const int* env_b,
                     __global const int* env_c, __global const float* x, __global const float* y,
                     __global const float* t, __global const float* env_cx, __global const float* env_cy,
                     __global const float* env_ct, float* fx, float* fy, float* ft, float* closest) {
  const float eps = p.repulsion_epsilon;
  float sx = 0.0f, sy = 0.0f, st = 0.0f;
  float closest2 = INFINITY;
  const int qx = grid_axis_cell(px, grid.cell, grid.n);
  const int qy = grid_axis_cell(py, grid.cell, grid.n);
  const int qt = grid_axis_cell(pt, grid.cell, grid.n);
  /* Pass 0: the 3x3x3 near block, exact closest points. Pass 1: the outer shell of the 5x5x5 block,
   * centroids only. The reference collects both lists first and sums near before far. */
  for (int pass = 0; pass < 2; ++pass) {
    const int r = pass == 0 ? 1 : 2, min_ring = pass == 0 ? 0 : 2;
    for (int dz = -r; dz <= r; ++dz) {
      for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) {
          const int ring = max(abs(dz), max(abs(dy), abs(dx)));
          if (ring < min_ring) continue;
          const int cx = qx + dx, cy = qy + dy, ct = qt + dz;
          if (cx < 0 || cy < 0 || ct < 0 || cx >= grid.n || cy >= grid.n || ct >= grid.n) continue;
          const int c = (ct * grid.n + cy) * grid.n + cx;
          for (int k = cell_start[c]; k < cell_start[c + 1]; ++k) {
            const int tri = sorted_triangles[k];
            if (env_element[tri] == own) continue;
            if (pass == 0) {
              const int a = env_a[tri], b = env_b[tri], cc = env_c[tri];
              float qpx, qpy, qpt;
              closest_point_on_triangle(px, py, pt, x[a], y[a], t[a], x[b], y[b], t[b], x[cc], y[cc], t[cc], &qpx,
                                        &qpy, &qpt);
              const float ux = px - qpx, uy = py - qpy, ut = pt - qpt;
              const float d2 = ux * ux + uy * uy + ut * ut;
              if (d2 < closest2) closest2 = d2;
              repulsion_add_term(ux, uy, ut, eps, &sx, &sy, &st);
            } else {
              repulsion_add_term(px - env_cx[tri], py - env_cy[tri], pt - env_ct[tri], eps, &sx, &sy, &st);
            }
          }
        }
      }
    }
  }
  *closest = sqrt(closest2);
  if (inside) return;
  const float k = p.k_repulsion;
  *fx = k * sx;
  *fy = k * sy;
  *ft = k * st;
}
