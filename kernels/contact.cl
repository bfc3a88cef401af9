/* What a step reads besides the forces (src/solver/reference/contact.cpp): each vertex's gap to its
 * nearest neighbour, the wall counted as one (§5.3's slice gap), and its contact bits, from the
 * repulsion kernel's distance and overlap bits and the container query step_forces or
 * wall_mirror_force made. Growth (§5.3) and the statistics read them. */

/** Vertex v's gap and AP_CONTACT_* bits; one work-item per vertex, after step_forces. */
__kernel void contact_gap(const WorldInfo world,
                          const ForceParams p,
                          __global const float* positions,          /* input: x, y, t */
                          __global const int* vertex_topology,      /* input: AP_TOPO_SLICE, AP_TOPO_FLAGS */
                          __global const int* slice_topology,       /* input: AP_SLICES_BEGIN, AP_SLICES_BOUNDARY */
                          __global const float* repulsion,          /* input: AP_RPL_CLOSEST */
                          __global const uchar* repulsion_contact,  /* input: repulsion_force's overlap bits */
                          __global const float* wall,               /* input: AP_WALL_D2, the container query */
                          __global const uchar* wall_inside,        /* input: the same, inside */
                          __global const float* segments,           /* input: AP_SEG_*, the container */
                          const ContainerIndexInfo container_index, /* the container's index */
                          __global const int* container_lists,      /* input: its lists */
                          __global float* closest,                  /* output: gap to the nearest element or wall */
                          __global uchar* contact) {                /* output: AP_CONTACT_* bits */
  const int v = get_global_id(0);
  if (v >= world.vertices) return;
  const int vs = world.vertex_stride;
  __global const float* x = positions + AP_X * vs;
  __global const float* y = positions + AP_Y * vs;
  const bool boundary = (vertex_topology[AP_TOPO_FLAGS * vs + v] & AP_VERTEX_BOUNDARY) != 0;
  const uchar overlap_bits = boundary ? repulsion_contact[v] : 0;
  const bool overlapping = overlap_bits != 0;
  const float dist = boundary ? repulsion[AP_RPL_CLOSEST * vs + v] : INFINITY;
  const bool in_container = wall_inside[v] != 0;
  /* The wall is a neighbour too (§5.3's slice gap). */
  uchar bits = in_container ? 0 : AP_CONTACT_OUTSIDE;
  float gap = dist;
  if (boundary) {
    const float wall2 = wall[AP_WALL_D2 * vs + v];
    float wall_gap = in_container ? sqrt(wall2) : 0.0f;
    if (p.k_mirror != 0.0f) wall_gap = wall_gap + wall_gap; /* the mirror image's gap */
    /* Both ends inside, the edge to the next boundary vertex may still leave around a reflex corner. */
    if (in_container) {
      const int s = vertex_topology[AP_TOPO_SLICE * vs + v];
      const int lo = slice_topology[AP_SLICES_BEGIN * world.slice_stride + s];
      const int next = v - lo + 1 == slice_topology[AP_SLICES_BOUNDARY * world.slice_stride + s] ? lo : v + 1;
      const float px = x[v], py = y[v];
      const float ex = x[next] - px, ey = y[next] - py;
      if (wall2 < ex * ex + ey * ey && edge_crosses_container_at(world, segments, container_index, container_lists, px,
                                                                 py, x[next], y[next], positions[AP_T * vs + v])) {
        bits = AP_CONTACT_OUTSIDE;
        wall_gap = 0.0f;
      }
    }
    gap = overlapping ? 0.0f : (wall_gap < dist ? wall_gap : dist);
    if (wall_gap < p.stop_gap) bits |= AP_CONTACT_WALL;
  }
  closest[v] = gap;
  contact[v] = bits | overlap_bits;
}
