/* Per-slice statistics for the stop test (src/solver/reference/backend.cpp), so the host reads a few
 * numbers per slice instead of the whole state. */

/** Slice s's closest gap (min in vertex order), its overlapping vertices and its first non-finite vertex. */
__kernel void slice_statistics(const WorldInfo world,
                               __global const int* slice_begin, /* input: slices + 1 */
                               __global const float* closest,   /* input: per vertex, from step_forces */
                               __global const uchar* inside,    /* input: per vertex */
                               __global const float* x, __global const float* y, __global const float* t, /* input */
                               __global const float* vx, __global const float* vy, __global const float* vt, /* input */
                               __global float* slice_gap,       /* output: per slice */
                               __global int* slice_inside,      /* output: inside vertices per slice */
                               __global int* slice_bad) {       /* output: first non-finite vertex, or -1 */
  const int s = get_global_id(0);
  if (s >= world.slices) return;
  float gap = INFINITY;
  int count = 0, bad = -1;
  for (int v = slice_begin[s]; v < slice_begin[s + 1]; ++v) {
    gap = closest[v] < gap ? closest[v] : gap;
    count += inside[v];
    const bool ok = isfinite(x[v]) && isfinite(y[v]) && isfinite(t[v]) && isfinite(vx[v]) && isfinite(vy[v]) &&
                    isfinite(vt[v]);
    if (!ok && bad < 0) bad = v;
  }
  slice_gap[s] = gap;
  slice_inside[s] = count;
  slice_bad[s] = bad;
}
