/* Growth of §5.3 (src/solver/reference/growth.cpp): slices free of overlaps grow, and the springs
 * touching a grown slice take their rest length from the scaled reference copy. */

/** Grows slice s by growth_step up to max_growth unless one of its vertices is inside another element. */
__kernel void grow_slices(const WorldInfo world, const ForceParams p,
                          __global const int* slice_begin, /* input: slices + 1 */
                          __global const uchar* inside,    /* input: per vertex, from step_forces */
                          __global float* growth,          /* input/output: g per slice */
                          __global uchar* grew) {          /* output: 1 when slice s grew */
  const int s = get_global_id(0);
  if (s >= world.slices) return;
  bool blocked = false;
  for (int v = slice_begin[s]; v < slice_begin[s + 1] && !blocked; ++v) blocked = inside[v] != 0;
  grew[s] = 0;
  const float cap = p.max_growth;
  if (blocked || growth[s] >= cap) return;
  const float g = growth[s] + p.growth_step;
  growth[s] = g < cap ? g : cap;
  grew[s] = 1;
}

/** Rest length of every CSR slot of vertex v whose spring has an end on a grown slice
 * (solver.hpp: reference_rest_length, each end's slice scaled by its g about its reference centroid). */
__kernel void update_rest_lengths(const WorldInfo world,
                                  __global const int* slice,          /* input: per vertex */
                                  __global const int* spring_begin,   /* input: vertices + 1 */
                                  __global const int* spring_other,   /* input: per slot */
                                  __global const uchar* grew,         /* input: per slice */
                                  __global const float* growth,       /* input: g per slice */
                                  __global const float* ref_x, __global const float* ref_y,
                                  __global const float* ref_t,        /* input: reference copy per vertex */
                                  __global const float* slice_ref_cx,
                                  __global const float* slice_ref_cy, /* input: per slice */
                                  __global float* spring_rest) {      /* output: per slot */
  const int v = get_global_id(0);
  if (v >= world.vertices) return;
  const int sv = slice[v];
  for (int k = spring_begin[v]; k < spring_begin[v + 1]; ++k) {
    const int w = spring_other[k];
    const int sw = slice[w];
    if (!(grew[sv] || grew[sw])) continue;
    const float xv = slice_ref_cx[sv] + growth[sv] * (ref_x[v] - slice_ref_cx[sv]);
    const float yv = slice_ref_cy[sv] + growth[sv] * (ref_y[v] - slice_ref_cy[sv]);
    const float xw = slice_ref_cx[sw] + growth[sw] * (ref_x[w] - slice_ref_cx[sw]);
    const float yw = slice_ref_cy[sw] + growth[sw] * (ref_y[w] - slice_ref_cy[sw]);
    const float dx = xw - xv, dy = yw - yv, dt = ref_t[w] - ref_t[v];
    spring_rest[k] = sqrt(dx * dx + dy * dy + dt * dt);
  }
}
