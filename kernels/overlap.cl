/* Overlap test and force, paper Eq. 3 (src/solver/reference/overlap.cpp). */

/** Half-open ray-crossing step of the even-odd test (boundary.cpp: ray_crosses_segment). */
bool ray_crosses_segment(float px, float py, float ax, float ay, float bx, float by) {
  if ((ay > py) == (by > py)) return false;
  const float xi = (bx - ax) * (py - ay) / (by - ay) + ax;
  return px < xi;
}

/** Even-odd test of (px, py) against element e's boundary polygon interpolated at t between the first
 * pair of consecutive slices whose times bracket t; a slice's time is its first vertex's t. */
bool inside_element_at(int e, float px, float py, float pt, __global const int* element_slice_begin,
                       __global const int* slice_begin, __global const int* slice_boundary,
                       __global const float* x, __global const float* y, __global const float* t) {
  for (int s = element_slice_begin[e]; s + 1 < element_slice_begin[e + 1]; ++s) {
    const float t0 = t[slice_begin[s]], t1 = t[slice_begin[s + 1]];
    /* std::min / std::max spelled out, so NaN compares exactly as in the reference. */
    const float lo_t = t1 < t0 ? t1 : t0, hi_t = t0 < t1 ? t1 : t0;
    if (!(lo_t <= pt && pt <= hi_t)) continue;
    const float w = t1 != t0 ? (pt - t0) / (t1 - t0) : 0.0f;
    const int lo = slice_begin[s], hi = slice_begin[s + 1];
    const int count = slice_boundary[s];
    bool inside = false;
    for (int k = 0; k < count; ++k) {
      const int j = k + 1 == count ? 0 : k + 1;
      const float ax = x[lo + k] + (x[hi + k] - x[lo + k]) * w;
      const float ay = y[lo + k] + (y[hi + k] - y[lo + k]) * w;
      const float bx = x[lo + j] + (x[hi + j] - x[lo + j]) * w;
      const float by = y[lo + j] + (y[hi + j] - y[lo + j]) * w;
      if (ray_crosses_segment(px, py, ax, ay, bx, by)) inside = !inside;
    }
    return inside;
  }
  return false;
}

/* How many distinct elements inside_other_element remembers. Only a shortcut: the answer is "inside
 * any element owning a near triangle", the same whichever repeats are skipped. */
#define AP_TESTED_CACHE 8

/** Whether boundary vertex (px, py, pt) of element `own` lies inside another element owning one of the
 * envelope triangles in the 3x3x3 block of cells around it; the block is walked row by row through
 * the grid slots' owners (grid_gather), in the reference's cell order. */
bool inside_other_element(const GridInfo grid, int own, float px, float py, float pt,
                          __global const int* cell_start, __global const int* slot_element,
                          __global const int* element_slice_begin, __global const int* slice_begin,
                          __global const int* slice_boundary, __global const float* x, __global const float* y,
                          __global const float* t) {
  int tested[AP_TESTED_CACHE];
  int tested_count = 0;
  const int qx = grid_axis_cell(px, grid.cell, grid.n);
  const int qy = grid_axis_cell(py, grid.cell, grid.n);
  const int qt = grid_axis_cell(pt, grid.cell, grid.n);
  for (int dz = -1; dz <= 1; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      const int2 range = grid_row_range(grid, cell_start, qy + dy, qt + dz, qx - 1, qx + 1);
      for (int k = range.x; k < range.y; ++k) {
        const int e = slot_element[k];
        if (e == own) continue;
        bool seen = false;
        for (int i = 0; i < tested_count && !seen; ++i) seen = tested[i] == e;
        if (seen) continue;
        if (tested_count < AP_TESTED_CACHE) tested[tested_count++] = e;
        if (inside_element_at(e, px, py, pt, element_slice_begin, slice_begin, slice_boundary, x, y, t)) return true;
      }
    }
  }
  return false;
}

/** Eq. 3: k_ovr Σ (p_i − x) over centroids p_i of v's incident slice triangles, in list order. */
void overlap_force(const ForceParams p, int v, __global const int* tri_begin, __global const int* tri_list,
                   __global const int* tri_a, __global const int* tri_b, __global const int* tri_c,
                   __global const float* x, __global const float* y, __global const float* t, float* fx, float* fy,
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
  *fx = k_ovr * sx;
  *fy = k_ovr * sy;
  *ft = k_ovr * st;
}
