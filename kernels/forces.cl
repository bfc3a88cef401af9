/* Total force, paper Eq. 7, gathered per vertex (src/solver/reference/step_forces.cpp): the overlap
 * test first, then every force, summed left to right in this order:
 *   F = ((((((F_rpl + F_edg) + F_tgt) + F_bdr) + F_ovr) + F_tor) + F_tmp)
 * Zero forces are still added, so a −0 sum turns into +0 exactly as in the reference. */

/** Eq. 7 for vertex i from one snapshot of positions; writes only vertex i's outputs. */
__kernel void step_forces(const WorldInfo world, const GridInfo grid, const ForceParams p,
                          __global const float* x, __global const float* y, __global const float* t, /* input: positions */
                          __global const int* element,        /* input: per vertex */
                          __global const int* slice,          /* input: per vertex */
                          __global const uchar* flags,        /* input: VertexFlag bits per vertex */
                          __global const float* rest_t,       /* input: per vertex */
                          __global const float* rest_dir_x,   /* input: per vertex */
                          __global const float* rest_dir_y,   /* input: per vertex */
                          __global const int* target,         /* input: target point per vertex, or -1 */
                          __global const int* spring_begin,   /* input: CSR rows, vertices + 1 */
                          __global const int* spring_other,   /* input: per slot */
                          __global const uchar* spring_class, /* input: per slot */
                          __global const float* spring_rest,  /* input: per slot */
                          __global const int* tri_a, __global const int* tri_b, __global const int* tri_c, /* input: slice triangles */
                          __global const int* tri_begin,      /* input: incident-triangle rows, vertices + 1 */
                          __global const int* tri_list,       /* input */
                          __global const int* slice_begin,    /* input: slices + 1 */
                          __global const int* slice_boundary, /* input: per slice */
                          __global const int* element_slice_begin, /* input: elements + 1 */
                          __global const int* env_a, __global const int* env_b, __global const int* env_c, /* input: envelope */
                          __global const int* env_element,    /* input: per envelope triangle */
                          __global const int* cell_start,     /* input: cells + 1 (host counting sort) */
                          __global const int* sorted_triangles, /* input: triangle ids by cell */
                          __global const float* env_cx, __global const float* env_cy, __global const float* env_ct, /* input: centroids */
                          __global const float* target_x, __global const float* target_y, __global const float* target_t, /* input */
                          __global const float* seg_ax, __global const float* seg_ay, /* input: container segments */
                          __global const float* seg_bx, __global const float* seg_by, /* input */
                          __global const float* slice_cx, __global const float* slice_cy, /* input: slice centroids */
                          __global float* fx, __global float* fy, __global float* ft, /* output: Eq. 7 per vertex */
                          __global float* closest,            /* output: distance to the nearest other element */
                          __global uchar* inside_flag,        /* output: 1 when inside another element */
                          __global float* breakdown) {        /* output when world.breakdown: every force apart */
  const int v = get_global_id(0);
  if (v >= world.vertices) return;
  const float px = x[v], py = y[v], pt = t[v];
  const int own = element[v];
  const bool boundary = (flags[v] & AP_VERTEX_BOUNDARY) != 0;

  const bool inside = boundary && inside_other_element(grid, own, px, py, pt, cell_start, sorted_triangles,
                                                       env_element, element_slice_begin, slice_begin,
                                                       slice_boundary, x, y, t);
  float rpl_x = 0.0f, rpl_y = 0.0f, rpl_t = 0.0f, dist = INFINITY;
  if (boundary)
    repulsion_force(grid, p, own, px, py, pt, inside, cell_start, sorted_triangles, env_element, env_a, env_b, env_c,
                    x, y, t, env_cx, env_cy, env_ct, &rpl_x, &rpl_y, &rpl_t, &dist);
  float edg_x, edg_y, edg_t;
  spring_force(p, v, spring_begin, spring_other, spring_class, spring_rest, x, y, t, &edg_x, &edg_y, &edg_t);
  float tgt_x = 0.0f, tgt_y = 0.0f, tgt_t = 0.0f;
  if (target[v] >= 0 && (flags[v] & AP_VERTEX_ANCHOR) != 0)
    target_force(p, target[v], px, py, pt, target_x, target_y, target_t, &tgt_x, &tgt_y, &tgt_t);
  float bdr_x = 0.0f, bdr_y = 0.0f;
  const float bdr_t = 0.0f;
  boundary_force(p, world.segments, px, py, seg_ax, seg_ay, seg_bx, seg_by, &bdr_x, &bdr_y);
  float ovr_x = 0.0f, ovr_y = 0.0f, ovr_t = 0.0f;
  if (inside) overlap_force(p, v, tri_begin, tri_list, tri_a, tri_b, tri_c, x, y, t, &ovr_x, &ovr_y, &ovr_t);
  const int s = slice[v];
  float tor_x = 0.0f, tor_y = 0.0f;
  const float tor_t = 0.0f;
  torsion_force(p, px, py, slice_cx[s], slice_cy[s], rest_dir_x[v], rest_dir_y[v], &tor_x, &tor_y);
  const float tmp_x = 0.0f, tmp_y = 0.0f;
  const float tmp_t = temporal_force(p, rest_t[v], pt);

  fx[v] = rpl_x + edg_x + tgt_x + bdr_x + ovr_x + tor_x + tmp_x;
  fy[v] = rpl_y + edg_y + tgt_y + bdr_y + ovr_y + tor_y + tmp_y;
  ft[v] = rpl_t + edg_t + tgt_t + bdr_t + ovr_t + tor_t + tmp_t;
  closest[v] = dist;
  inside_flag[v] = inside ? 1 : 0;
  if (world.breakdown == 0) return;
  const int n = world.vertices;
  const float parts[AP_FORCE_COMPONENTS][3] = {{rpl_x, rpl_y, rpl_t}, {edg_x, edg_y, edg_t}, {tgt_x, tgt_y, tgt_t},
                                               {bdr_x, bdr_y, bdr_t}, {ovr_x, ovr_y, ovr_t}, {tor_x, tor_y, tor_t},
                                               {tmp_x, tmp_y, tmp_t}};
  for (int c = 0; c < AP_FORCE_COMPONENTS; ++c)
    for (int axis = 0; axis < 3; ++axis) breakdown[(c * 3 + axis) * n + v] = parts[c][axis];
}
