/* Total force, paper Eq. 7, gathered per vertex (src/solver/reference/forces.cpp): the overlap
 * test and repulsion first (the repulsion kernel, one work-item per boundary vertex), the container
 * query, then every other force, summed left to right in this order:
 *   F = ((((((F_rpl + F_edg) + F_tgt) + F_bdr) + F_ovr) + F_tor) + F_tmp)
 * with F_edg the springs' sum plus the fold guard. Zero forces are still added, so a −0 sum turns into +0
 * exactly as in the reference. */

/** Eq. 7 for vertex i from one snapshot of positions; writes only vertex i's outputs. */
__kernel void step_forces(const WorldInfo world,
                          const ForceParams p,
                          __global const float* x,
                          __global const float* y,
                          __global const float* t,            /* input: positions */
                          __global const int* slice,          /* input: per vertex */
                          __global const int* slice_begin,    /* input: slices + 1 */
                          __global const int* slice_boundary, /* input: boundary vertices per slice */
                          __global const uchar* flags,        /* input: VertexFlag bits per vertex */
                          __global const float* rest_t,       /* input: per vertex */
                          __global const float* rest_dir_x,   /* input: per vertex */
                          __global const float* rest_dir_y,   /* input: per vertex */
                          __global const int* target,         /* input: target point per vertex, or -1 */
                          __global const int* spring_begin,   /* input: CSR rows, vertices + 1 */
                          __global const int* spring_other,   /* input: per slot */
                          __global const uchar* spring_class, /* input: per slot */
                          __global const float* spring_rest,  /* input: per slot */
                          __global const int* tri_a,
                          __global const int* tri_b,
                          __global const int* tri_c,     /* input: slice triangles */
                          __global const int* tri_begin, /* input: incident-triangle rows, vertices + 1 */
                          __global const int* tri_list,  /* input */
                          __global const float* rest_copy_x,
                          __global const float* rest_copy_y, /* input: the rest copy, per vertex (fold_force) */
                          __global const float* growth,      /* input: g per slice (fold_force) */
                          __global const float* rpl_x_in,
                          __global const float* rpl_y_in,    /* input: Eq. 1 */
                          __global const float* rpl_t_in,    /* input: Eq. 1 */
                          __global const float* rpl_closest, /* input: repulsion kernel, boundary vertices */
                          __global const uchar* rpl_contact, /* input: repulsion kernel, boundary vertices */
                          __global const float* depth_x,
                          __global const float* depth_y, /* input: repulsion kernel */
                          __global const float* target_x,
                          __global const float* target_y,
                          __global const float* target_t, /* input */
                          __global const float* seg_ax,
                          __global const float* seg_ay, /* input: container segments */
                          __global const float* seg_bx,
                          __global const float* seg_by,             /* input */
                          const ContainerIndexInfo container_index, /* the container's index */
                          __global const int* container_lists,      /* input: its lists */
                          __global const float* slice_cx,
                          __global const float* slice_cy, /* input: slice centroids */
                          __global const float* mirror_x,
                          __global const float* mirror_y,
                          __global const float* mirror_t,           /* input: wall_mirror_force, when k_mirror != 0 */
                          __global const uchar* mirror_wall_inside, /* input: its container query, the same */
                          __global const float* mirror_wall_d2,
                          __global const float* mirror_wall_qx,
                          __global const float* mirror_wall_qy,
                          __global float* fx,
                          __global float* fy,
                          __global float* ft,          /* output: Eq. 7 per vertex */
                          __global float* closest,     /* output: distance to the nearest element or wall */
                          __global uchar* contact_out, /* output: AP_CONTACT_* bits per vertex */
                          __global float* breakdown) { /* output when world.breakdown: every force apart */
  const int v = get_global_id(0);
  if (v >= world.vertices) return;
  const float px = x[v], py = y[v], pt = t[v];
  const bool boundary = (flags[v] & AP_VERTEX_BOUNDARY) != 0;

  const uchar overlap_bits = boundary ? rpl_contact[v] : 0;
  const bool overlapping = overlap_bits != 0, inside = (overlap_bits & AP_CONTACT_INSIDE) != 0;
  const float rpl_x = boundary ? rpl_x_in[v] : 0.0f, rpl_y = boundary ? rpl_y_in[v] : 0.0f,
              rpl_t = boundary ? rpl_t_in[v] : 0.0f, dist = boundary ? rpl_closest[v] : INFINITY;
  float wall2, wall_qx, wall_qy;
  bool in_container;
  if (boundary && p.k_mirror != 0.0f) { /* wall_mirror_force made this query, nearest point included */
    in_container = mirror_wall_inside[v] != 0;
    wall2 = mirror_wall_d2[v], wall_qx = mirror_wall_qx[v], wall_qy = mirror_wall_qy[v];
  } else {
    in_container = container_query(world.segments, container_index, container_lists, px, py, boundary, seg_ax, seg_ay,
                                   seg_bx, seg_by, &wall2, &wall_qx, &wall_qy);
  }
  float edg_x, edg_y, edg_t;
  spring_force(p, v, spring_begin, spring_other, spring_class, spring_rest, x, y, t, &edg_x, &edg_y, &edg_t);
  { /* F_edg = springs + the fold guard (reference step_forces) */
    float fold_x, fold_y;
    fold_force(p, v, slice, tri_begin, tri_list, tri_a, tri_b, tri_c, rest_copy_x, rest_copy_y, growth, x, y, &fold_x,
               &fold_y);
    edg_x = edg_x + fold_x;
    edg_y = edg_y + fold_y;
  }
  float tgt_x = 0.0f, tgt_y = 0.0f, tgt_t = 0.0f;
  if (target[v] >= 0 && (flags[v] & AP_VERTEX_ANCHOR) != 0)
    target_force(p, target[v], px, py, pt, target_x, target_y, target_t, &tgt_x, &tgt_y, &tgt_t);
  float bdr_x = 0.0f, bdr_y = 0.0f, bdr_t = 0.0f;
  boundary_force(p, in_container, wall2, wall_qx, wall_qy, px, py, boundary, &bdr_x, &bdr_y);
  if (boundary && p.k_mirror != 0.0f && !overlapping) { /* the wall's mirror image (wall_mirror_force) */
    bdr_x = bdr_x + mirror_x[v];
    bdr_y = bdr_y + mirror_y[v];
    bdr_t = bdr_t + mirror_t[v];
  }
  float ovr_x = 0.0f, ovr_y = 0.0f, ovr_t = 0.0f;
  if (overlapping)
    overlap_force(p, v, inside, depth_x[v], depth_y[v], tri_begin, tri_list, tri_a, tri_b, tri_c, x, y, t, &ovr_x,
                  &ovr_y, &ovr_t);
  const int s = slice[v];
  float tor_x = 0.0f, tor_y = 0.0f;
  const float tor_t = 0.0f;
  const float k_tor = (flags[v] & AP_VERTEX_HOLD_ANGLE) != 0 ? p.k_target_angle : p.k_torsion;
  torsion_force(k_tor, px, py, slice_cx[s], slice_cy[s], rest_dir_x[v], rest_dir_y[v], &tor_x, &tor_y);
  const float temporal_x = 0.0f, temporal_y = 0.0f;
  const float temporal_t = temporal_force(p, rest_t[v], pt);

  fx[v] = rpl_x + edg_x + tgt_x + bdr_x + ovr_x + tor_x + temporal_x;
  fy[v] = rpl_y + edg_y + tgt_y + bdr_y + ovr_y + tor_y + temporal_y;
  ft[v] = rpl_t + edg_t + tgt_t + bdr_t + ovr_t + tor_t + temporal_t;
  /* The wall is a neighbour too (§5.3's slice gap). */
  uchar bits = in_container ? 0 : AP_CONTACT_OUTSIDE;
  float gap = dist;
  if (boundary) {
    float wall_gap = in_container ? sqrt(wall2) : 0.0f;
    if (p.k_mirror != 0.0f) wall_gap = wall_gap + wall_gap; /* the mirror image's gap */
    /* Both ends inside, the edge to the next boundary vertex may still leave around a reflex corner. */
    if (in_container) {
      const int lo = slice_begin[s];
      const int next = v - lo + 1 == slice_boundary[s] ? lo : v + 1;
      const float ex = x[next] - px, ey = y[next] - py;
      if (wall2 < ex * ex + ey * ey && edge_crosses_container(world.segments, container_index, container_lists, px, py,
                                                              x[next], y[next], seg_ax, seg_ay, seg_bx, seg_by)) {
        bits = AP_CONTACT_OUTSIDE;
        wall_gap = 0.0f;
      }
    }
    gap = overlapping ? 0.0f : (wall_gap < dist ? wall_gap : dist);
    if (wall_gap < p.stop_gap) bits |= AP_CONTACT_WALL;
  }
  closest[v] = gap;
  contact_out[v] = bits | overlap_bits;
  if (world.breakdown == 0) return;
  const int n = world.vertices;
  const float parts[AP_FORCE_COMPONENTS][3] = {{rpl_x, rpl_y, rpl_t},
                                               {edg_x, edg_y, edg_t},
                                               {tgt_x, tgt_y, tgt_t},
                                               {bdr_x, bdr_y, bdr_t},
                                               {ovr_x, ovr_y, ovr_t},
                                               {tor_x, tor_y, tor_t},
                                               {temporal_x, temporal_y, temporal_t}};
  for (int c = 0; c < AP_FORCE_COMPONENTS; ++c)
    for (int axis = 0; axis < 3; ++axis) breakdown[(c * 3 + axis) * n + v] = parts[c][axis];
}
