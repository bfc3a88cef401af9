/* Total force, paper Eq. 7, gathered per vertex (src/solver/reference/forces.cpp): the overlap
 * test and repulsion first (the repulsion kernel, one work-item per boundary vertex), the container
 * query, then every other force, summed left to right in the order of AP_FORCE_TERMS (shared_types.h):
 *   F = ((((((F_rpl + F_edg) + F_tgt) + F_bdr) + F_ovr) + F_tor) + F_tmp)
 * with F_edg the springs' sum plus the fold guard and the forces of AP_LOCAL_FORCES last. Zero forces are still added, so a −0 sum turns into +0
 * exactly as in the reference. What the step reads besides the forces, each vertex's gap and contact
 * bits, is contact_gap's (contact.cl), from the container query this kernel leaves in `wall`. */

/** Eq. 7 for vertex i from one snapshot of positions; writes only vertex i's outputs. */
__kernel void step_forces(const WorldInfo world,
                          const ForceParams p,
                          __global const float* positions,          /* input: x, y, t */
                          __global const int* vertex_topology,      /* input: AP_TOPO_* */
                          __global const float* vertex_rest,        /* input: AP_REST_* */
                          __global const int* springs,              /* input: AP_SPRINGS_* */
                          __global const float* spring_rest,        /* input: per slot */
                          __global const int* triangles,            /* input: AP_TRIS_* */
                          __global const float* growth,             /* input: g per slice (fold_force) */
                          __global const float* repulsion,          /* input: AP_RPL_*, repulsion_force */
                          __global const uchar* repulsion_contact,  /* input: repulsion_force's overlap bits */
                          __global const float* targets,            /* input: target points */
                          __global const float* segments,           /* input: AP_SEG_*, the container */
                          const ContainerIndexInfo container_index, /* the container's index */
                          __global const int* container_lists,      /* input: its lists */
                          __global const float* slice_geometry,     /* input: AP_GEOM_CX, AP_GEOM_CY */
                          __global float* wall,                     /* input/output: AP_WALL_*; the container query */
                          __global uchar* wall_inside,              /* input/output: the same, inside */
                          __global float* forces,                   /* output: Eq. 7 per vertex, x, y, t */
                          __global float* breakdown) {              /* output when world.breakdown: every force apart */
  const int v = get_global_id(0);
  if (v >= world.vertices) return;
  const int vs = world.vertex_stride;
  __global const float* x = positions + AP_X * vs;
  __global const float* y = positions + AP_Y * vs;
  __global const float* t = positions + AP_T * vs;
  __global const int* slice = vertex_topology + AP_TOPO_SLICE * vs;
  __global const int* flags = vertex_topology + AP_TOPO_FLAGS * vs;
  __global const int* target = vertex_topology + AP_TOPO_TARGET * vs;
  __global const int* tri_a = triangles + AP_TRIS_A * world.triangle_stride;
  __global const int* tri_b = triangles + AP_TRIS_B * world.triangle_stride;
  __global const int* tri_c = triangles + AP_TRIS_C * world.triangle_stride;
  __global const int* tri_begin = triangles + AP_TRIS_BEGIN * world.triangle_stride;
  __global const int* tri_list = triangles + AP_TRIS_LIST * world.triangle_stride;
  __global float* wall_d2 = wall + AP_WALL_D2 * vs;
  __global float* wall_qx = wall + AP_WALL_QX * vs;
  __global float* wall_qy = wall + AP_WALL_QY * vs;
  const float px = x[v], py = y[v], pt = t[v];
  const bool boundary = (flags[v] & AP_VERTEX_BOUNDARY) != 0;

  const uchar overlap_bits = boundary ? repulsion_contact[v] : 0;
  const bool overlapping = overlap_bits != 0, inside = (overlap_bits & AP_CONTACT_INSIDE) != 0;
  const float repulsion_x = boundary ? repulsion[AP_RPL_X * vs + v] : 0.0f,
              repulsion_y = boundary ? repulsion[AP_RPL_Y * vs + v] : 0.0f,
              repulsion_t = boundary ? repulsion[AP_RPL_T * vs + v] : 0.0f;
  float wall2, wall_x, wall_y;
  bool in_container;
  if (boundary && p.k_mirror != 0.0f) { /* wall_mirror_force made this query, nearest point included */
    in_container = wall_inside[v] != 0;
    wall2 = wall_d2[v], wall_x = wall_qx[v], wall_y = wall_qy[v];
  } else { /* made here, and left for contact_gap */
    in_container = container_query_at(world, segments, container_index, container_lists, px, py, pt, boundary, &wall2,
                                      &wall_x, &wall_y);
    wall_inside[v] = in_container ? 1 : 0;
    wall_d2[v] = wall2;
  }
  float springs_x, springs_y, springs_t;
  spring_force(p, v, springs + AP_SPRINGS_BEGIN * world.spring_stride, springs + AP_SPRINGS_OTHER * world.spring_stride,
               springs + AP_SPRINGS_CLASS * world.spring_stride, spring_rest, x, y, t, &springs_x, &springs_y,
               &springs_t);
  { /* F_edg = springs + the fold guard (reference step_forces) */
    float fold_x, fold_y;
    fold_force(p, v, slice, tri_begin, tri_list, tri_a, tri_b, tri_c, vertex_rest + AP_REST_COPY_X * vs,
               vertex_rest + AP_REST_COPY_Y * vs, growth, x, y, &fold_x, &fold_y);
    springs_x = springs_x + fold_x;
    springs_y = springs_y + fold_y;
  }
  float target_x = 0.0f, target_y = 0.0f, target_t = 0.0f;
  if (target[v] >= 0 && (flags[v] & AP_VERTEX_ANCHOR) != 0)
    target_force(p, target[v], px, py, pt, targets + AP_X * world.target_stride, targets + AP_Y * world.target_stride,
                 targets + AP_T * world.target_stride, &target_x, &target_y, &target_t);
  float boundary_x = 0.0f, boundary_y = 0.0f, boundary_t = 0.0f;
  boundary_force(p, in_container, wall2, wall_x, wall_y, px, py, boundary, &boundary_x, &boundary_y);
  if (boundary && p.k_mirror != 0.0f && !overlapping) { /* the wall's mirror image (wall_mirror_force) */
    boundary_x = boundary_x + wall[AP_WALL_MIRROR_X * vs + v];
    boundary_y = boundary_y + wall[AP_WALL_MIRROR_Y * vs + v];
    boundary_t = boundary_t + wall[AP_WALL_MIRROR_T * vs + v];
  }
  float overlap_x = 0.0f, overlap_y = 0.0f, overlap_t = 0.0f;
  if (overlapping)
    overlap_force(p, v, inside, repulsion[AP_RPL_DEPTH_X * vs + v], repulsion[AP_RPL_DEPTH_Y * vs + v], tri_begin,
                  tri_list, tri_a, tri_b, tri_c, x, y, t, &overlap_x, &overlap_y, &overlap_t);
  const int s = slice[v];
  float torsion_x = 0.0f, torsion_y = 0.0f;
  const float torsion_t = 0.0f;
  const float k_tor = (flags[v] & AP_VERTEX_HOLD_ANGLE) != 0 ? p.k_target_angle : p.k_torsion;
  torsion_force(k_tor, px, py, slice_geometry[AP_GEOM_CX * world.slice_stride + s],
                slice_geometry[AP_GEOM_CY * world.slice_stride + s], vertex_rest[AP_REST_DIR_X * vs + v],
                vertex_rest[AP_REST_DIR_Y * vs + v], &torsion_x, &torsion_y);
  const LocalForceInputs in = {x,
                               y,
                               t,
                               vertex_topology + AP_TOPO_ELEMENT * vs,
                               slice,
                               flags,
                               target,
                               vertex_rest + AP_REST_T * vs,
                               vertex_rest + AP_REST_DIR_X * vs,
                               vertex_rest + AP_REST_DIR_Y * vs,
                               vertex_rest + AP_REST_COPY_X * vs,
                               vertex_rest + AP_REST_COPY_Y * vs,
                               vertex_rest + AP_REST_COPY_T * vs};
#define AP_KERNEL_LOCAL_FORCE(name, ...) \
  float name##_x, name##_y, name##_t;    \
  name##_force(p, in, v, &name##_x, &name##_y, &name##_t);
  AP_LOCAL_FORCES(AP_KERNEL_LOCAL_FORCE)
#undef AP_KERNEL_LOCAL_FORCE

#define AP_KERNEL_PART(name, ...) {name##_x, name##_y, name##_t},
  const float part[AP_FORCE_COMPONENTS][3] = {AP_FORCE_TERMS(AP_KERNEL_PART)};
#undef AP_KERNEL_PART
  for (int axis = 0; axis < 3; ++axis) {
    float sum = part[0][axis];
    for (int c = 1; c < AP_FORCE_COMPONENTS; ++c) sum = sum + part[c][axis];
    forces[axis * vs + v] = sum;
  }
  if (world.breakdown == 0) return;
  const int n = world.vertices;
  for (int c = 0; c < AP_FORCE_COMPONENTS; ++c)
    for (int axis = 0; axis < 3; ++axis) breakdown[(c * 3 + axis) * n + v] = part[c][axis];
}
