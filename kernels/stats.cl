/* Per-slice statistics for the stop test (src/solver/reference/stats.cpp), so the host reads a few
 * numbers per slice instead of the whole state. */

/** Slice s's closest gap (min in vertex order), its overlapping and outside vertices and its first
 * non-finite vertex. */
__kernel void slice_statistics(const WorldInfo world,
                               __global const int* slice_topology, /* input: slice_begin */
                               __global const float* closest,      /* input: per vertex, from step_forces */
                               __global const uchar* contact,      /* input: AP_CONTACT_* per vertex */
                               __global const uchar* changed,      /* input: AP_GROWTH_* per slice */
                               __global const float* positions,    /* input: x, y, t */
                               __global const float* velocities,   /* input: x, y, t */
                               __global float* slice_gap,          /* output: per slice */
                               __global int* slice_overlap,        /* output: overlapping vertices per slice */
                               __global int* slice_outside, /* output: vertices outside the container per slice */
                               __global int* slice_bad) {   /* output: first non-finite vertex, or -1 */
  __global const int* slice_begin = slice_topology + AP_SLICES_BEGIN * world.slice_stride;
  __global const float* x = positions + AP_X * world.vertex_stride;
  __global const float* y = positions + AP_Y * world.vertex_stride;
  __global const float* t = positions + AP_T * world.vertex_stride;
  __global const float* vx = velocities + AP_X * world.vertex_stride;
  __global const float* vy = velocities + AP_Y * world.vertex_stride;
  __global const float* vt = velocities + AP_T * world.vertex_stride;
  const int s = get_global_id(0);
  if (s >= world.slices) return;
  float gap = INFINITY;
  int overlapping = 0, outside = 0, bad = -1;
  for (int v = slice_begin[s]; v < slice_begin[s + 1]; ++v) {
    gap = closest[v] < gap ? closest[v] : gap;
    overlapping += (contact[v] & AP_CONTACT_OVERLAP) != 0;
    outside += (contact[v] & AP_CONTACT_OUTSIDE) != 0;
    const bool ok =
        isfinite(x[v]) && isfinite(y[v]) && isfinite(t[v]) && isfinite(vx[v]) && isfinite(vy[v]) && isfinite(vt[v]);
    if (!ok && bad < 0) bad = v;
  }
  slice_gap[s] = (changed[s] & AP_GROWTH_HELD) != 0 ? 0.0f : gap; /* held back by growth_ratio: touching */
  slice_overlap[s] = overlapping;
  slice_outside[s] = outside;
  slice_bad[s] = bad;
}
