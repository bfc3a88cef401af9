/* Torsional force, paper Eq. 5 (src/solver/reference/torsion.cpp), about each slice's current
 * centroid, which a per-slice kernel computes first from the same snapshot of positions. */

/** Mean x, y of every slice's vertices in index order; one work-item per slice. */
__kernel void slice_centroids(
    const WorldInfo world,              /* input */
    __global const int* slice_topology, /* input: slice s holds [slice_begin[s], slice_begin[s+1]) */
    __global const float* positions,    /* input: x, y, t per vertex */
    __global float* slice_geometry) {   /* output: centroid per slice */
  __global const int* slice_begin = slice_topology + AP_SLICES_BEGIN * world.slice_stride;
  __global const float* x = positions + AP_X * world.vertex_stride;
  __global const float* y = positions + AP_Y * world.vertex_stride;
  __global float* slice_cx = slice_geometry + AP_GEOM_CX * world.slice_stride;
  __global float* slice_cy = slice_geometry + AP_GEOM_CY * world.slice_stride;
  const int s = get_global_id(0);
  if (s >= world.slices) return;
  float sx = 0.0f, sy = 0.0f;
  for (int v = slice_begin[s]; v < slice_begin[s + 1]; ++v) {
    sx = sx + x[v];
    sy = sy + y[v];
  }
  const float count = (float)(slice_begin[s + 1] - slice_begin[s]);
  slice_cx[s] = 0.0f;
  slice_cy[s] = 0.0f;
  if (count > 0.0f) {
    slice_cx[s] = sx / count;
    slice_cy[s] = sy / count;
  }
}

/** Eq. 5: −sign(θ) k u⊥ turning u = x − c back towards the rest direction (rx, ry); the caller picks k,
 * k_tor or k_target_angle. */
void torsion_force(const float k, float px, float py, float cx, float cy, float rx, float ry, float* fx, float* fy) {
  const float ux = px - cx, uy = py - cy;
  const float cross = rx * uy - ry * ux;
  if (cross == 0.0f) return;
  const float inv_len = 1.0f / sqrt(ux * ux + uy * uy);
  const float signed_k = cross > 0.0f ? -k : k;
  *fx = signed_k * (-uy * inv_len);
  *fy = signed_k * (ux * inv_len);
}
