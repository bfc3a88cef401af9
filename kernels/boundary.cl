/* Boundary force, paper Eq. 4, and the containment projection (src/solver/reference/boundary.cpp):
 * k_bdr (p_b − x) in x, y for a vertex outside the container (even-odd over every ring, so inside a
 * hole is outside); a vertex still outside after a step moves onto the boundary. The container at a
 * vertex's t is the one at rest moved by its motion at that t (container_query_at). */

/** One segment's turn at the nearest point: the first segment (by index) reaching the minimum wins. */
void container_try_segment(int i,
                           float px,
                           float py,
                           __global const float* ax,
                           __global const float* ay,
                           __global const float* bx,
                           __global const float* by,
                           float* distance2,
                           float* qx,
                           float* qy) {
  float cx, cy;
  const float d2 = closest_point_on_segment(px, py, ax[i], ay[i], bx[i], by[i], &cx, &cy);
  if (d2 < *distance2) {
    *distance2 = d2;
    *qx = cx;
    *qy = cy;
  }
}

/** The container query (reference container_query): returns whether (px, py) is inside; when it is not,
 * or when `nearest`, also the squared distance to and the nearest point on the boundary (the first
 * segment reaching the minimum wins). With the index, the even-odd ray tries only the segments of py's
 * band and the nearest point only those of the point's cell (or every segment outside the grid), in
 * index order: the same answer as trying every segment. Without a container every point is inside, at
 * +inf. */
AP_INLINE bool container_query(int segments,
                               const ContainerIndexInfo ix,
                               __global const int* index,
                               float px,
                               float py,
                               bool nearest,
                               __global const float* ax,
                               __global const float* ay,
                               __global const float* bx,
                               __global const float* by,
                               float* distance2,
                               float* qx,
                               float* qy) {
  *distance2 = INFINITY;
  *qx = 0.0f;
  *qy = 0.0f;
  if (segments == 0) return true;
  bool inside = false;
  if (ix.nx > 0) {
    const int j = grid_axis_cell(py - ix.y0, ix.cell, ix.ny); /* grid.cl */
    for (int k = index[j]; k < index[j + 1]; ++k) {
      const int i = index[ix.band_segments + k];
      if (ray_crosses_segment(px, py, ax[i], ay[i], bx[i], by[i])) inside = !inside;
    }
  } else {
    for (int i = 0; i < segments; ++i)
      if (ray_crosses_segment(px, py, ax[i], ay[i], bx[i], by[i])) inside = !inside;
  }
  *qx = px;
  *qy = py;
  if (inside && !nearest) return true;

  const float fx = floor((px - ix.x0) / ix.cell), fy = floor((py - ix.y0) / ix.cell);
  if (ix.nx > 0 && fx >= 0.0f && fy >= 0.0f && fx < (float)ix.nx && fy < (float)ix.ny) {
    const int c = (int)fy * ix.nx + (int)fx;
    for (int k = index[ix.cell_start + c]; k < index[ix.cell_start + c + 1]; ++k)
      container_try_segment(index[ix.cell_segments + k], px, py, ax, ay, bx, by, distance2, qx, qy);
  } else {
    for (int i = 0; i < segments; ++i) container_try_segment(i, px, py, ax, ay, bx, by, distance2, qx, qy);
  }
  return inside;
}

/** Whether the boundary edge p → n properly crosses a container segment (reference
 * edge_crosses_container): with the index, only the segments of the bands from the edge's lower end to
 * its upper end, which hold every segment that can cross it. */
bool edge_crosses_container(int segments,
                            const ContainerIndexInfo ix,
                            __global const int* index,
                            float px,
                            float py,
                            float nx,
                            float ny,
                            __global const float* ax,
                            __global const float* ay,
                            __global const float* bx,
                            __global const float* by) {
  if (ix.nx > 0) {
    const int j0 = grid_axis_cell((ny < py ? ny : py) - ix.y0, ix.cell, ix.ny); /* std::min, std::max */
    const int j1 = grid_axis_cell((py < ny ? ny : py) - ix.y0, ix.cell, ix.ny);
    for (int j = j0; j <= j1; ++j)
      for (int k = index[j]; k < index[j + 1]; ++k) {
        const int i = index[ix.band_segments + k];
        if (segments_cross_properly(px, py, nx, ny, ax[i], ay[i], bx[i], by[i])) return true;
      }
    return false;
  }
  for (int i = 0; i < segments; ++i)
    if (segments_cross_properly(px, py, nx, ny, ax[i], ay[i], bx[i], by[i])) return true;
  return false;
}

/** The container's motion at time t (reference container_frame): the two entries of the motion table
 * around t, clamped to the table, interpolated linearly; w = [a -b; b a] p + e. */
void container_frame(const WorldInfo world,
                     __global const float* segments,
                     float t,
                     float* a,
                     float* b,
                     float* ex,
                     float* ey) {
  __global const float* ma = segments + AP_SEG_MOTION_A * world.segment_stride;
  __global const float* mb = segments + AP_SEG_MOTION_B * world.segment_stride;
  __global const float* mx = segments + AP_SEG_MOTION_EX * world.segment_stride;
  __global const float* my = segments + AP_SEG_MOTION_EY * world.segment_stride;
  const int intervals = world.motion_entries - 1;
  const float u = t * (float)intervals;
  float f = floor(u);
  if (!(f >= 0.0f)) f = 0.0f;
  const float last = (float)(intervals - 1);
  if (f > last) f = last;
  const int i = (int)f;
  float w = u - f;
  if (!(w >= 0.0f)) w = 0.0f;
  if (w > 1.0f) w = 1.0f;
  *a = ma[i] + (ma[i + 1] - ma[i]) * w;
  *b = mb[i] + (mb[i + 1] - mb[i]) * w;
  *ex = mx[i] + (mx[i + 1] - mx[i]) * w;
  *ey = my[i] + (my[i + 1] - my[i]) * w;
}

/** The point (wx, wy) of the plane at the frame's time, taken back to the container at rest. */
void container_to_rest(float a, float b, float ex, float ey, float wx, float wy, float* px, float* py) {
  const float s2 = a * a + b * b, dx = wx - ex, dy = wy - ey;
  *px = (a * dx + b * dy) / s2;
  *py = (a * dy - b * dx) / s2;
}

/** The container query of (px, py) at time pt (reference container_query with a time): at rest when the
 * container does not move; otherwise taken to the container at rest, queried there, the nearest point
 * brought back and its squared distance measured at pt. */
AP_INLINE bool container_query_at(const WorldInfo world,
                                  __global const float* segments,
                                  const ContainerIndexInfo ix,
                                  __global const int* index,
                                  float px,
                                  float py,
                                  float pt,
                                  bool nearest,
                                  float* distance2,
                                  float* qx,
                                  float* qy) {
  __global const float* ax = segments + AP_SEG_AX * world.segment_stride;
  __global const float* ay = segments + AP_SEG_AY * world.segment_stride;
  __global const float* bx = segments + AP_SEG_BX * world.segment_stride;
  __global const float* by = segments + AP_SEG_BY * world.segment_stride;
  if (world.motion_entries == 0)
    return container_query(world.segments, ix, index, px, py, nearest, ax, ay, bx, by, distance2, qx, qy);
  float a, b, ex, ey, lx, ly;
  container_frame(world, segments, pt, &a, &b, &ex, &ey);
  container_to_rest(a, b, ex, ey, px, py, &lx, &ly);
  const bool inside = container_query(world.segments, ix, index, lx, ly, nearest, ax, ay, bx, by, distance2, qx, qy);
  if (!(*distance2 < INFINITY)) { /* no nearest point was sought: the point itself, as at rest */
    *qx = px;
    *qy = py;
    return inside;
  }
  const float rx = *qx, ry = *qy;
  *qx = a * rx - b * ry + ex;
  *qy = b * rx + a * ry + ey;
  const float ux = *qx - px, uy = *qy - py;
  *distance2 = ux * ux + uy * uy;
  return inside;
}

/** edge_crosses_container at time pt (reference edge_crosses_container with a time): both ends taken to
 * the container at rest by its motion at pt. */
bool edge_crosses_container_at(const WorldInfo world,
                               __global const float* segments,
                               const ContainerIndexInfo ix,
                               __global const int* index,
                               float px,
                               float py,
                               float nx,
                               float ny,
                               float pt) {
  __global const float* ax = segments + AP_SEG_AX * world.segment_stride;
  __global const float* ay = segments + AP_SEG_AY * world.segment_stride;
  __global const float* bx = segments + AP_SEG_BX * world.segment_stride;
  __global const float* by = segments + AP_SEG_BY * world.segment_stride;
  if (world.motion_entries == 0)
    return edge_crosses_container(world.segments, ix, index, px, py, nx, ny, ax, ay, bx, by);
  float a, b, ex, ey, lx, ly, mx, my;
  container_frame(world, segments, pt, &a, &b, &ex, &ey);
  container_to_rest(a, b, ex, ey, px, py, &lx, &ly);
  container_to_rest(a, b, ex, ey, nx, ny, &mx, &my);
  return edge_crosses_container(world.segments, ix, index, lx, ly, mx, my, ax, ay, bx, by);
}

/** The container's force from the query of (px, py) (reference boundary_force): Eq. 4 outside; inside,
 * for a boundary vertex within wall_range of the wall, the wall's Eq. 1-shaped repulsion from its
 * nearest point. */
void boundary_force(const ForceParams p,
                    bool inside,
                    float distance2,
                    float qx,
                    float qy,
                    float px,
                    float py,
                    bool boundary,
                    float* fx,
                    float* fy) {
  if (!inside) {
    *fx = p.k_boundary * (qx - px);
    *fy = p.k_boundary * (qy - py);
    return;
  }
  if (!boundary || !(distance2 > 0.0f) || !(distance2 < p.wall_range2)) return;
  const float ux = px - qx, uy = py - qy;
  const float inv_len = 1.0f / sqrt(distance2);
  const float w = inv_len * (1.0f / (p.repulsion_epsilon + distance2));
  *fx = p.k_wall * (ux * w);
  *fy = p.k_wall * (uy * w);
}

/** Containment: a vertex outside the container moves past its nearest boundary point by
 * AP_CONTAINMENT_MARGIN and stops in x, y; one work-item per vertex. */
__kernel void apply_containment(const WorldInfo world,
                                __global const float* segments,           /* input: AP_SEG_*, the container */
                                const ContainerIndexInfo container_index, /* the container's index */
                                __global const int* container_lists,      /* input: its lists */
                                __global float* positions,                /* input/output: x, y */
                                __global float* velocities) {             /* input/output: x, y */
  __global float* x = positions + AP_X * world.vertex_stride;
  __global float* y = positions + AP_Y * world.vertex_stride;
  __global const float* t = positions + AP_T * world.vertex_stride;
  __global float* vx = velocities + AP_X * world.vertex_stride;
  __global float* vy = velocities + AP_Y * world.vertex_stride;
  const int v = get_global_id(0);
  if (v >= world.vertices) return;
  const float px = x[v], py = y[v];
  float d2, qx, qy;
  if (container_query_at(world, segments, container_index, container_lists, px, py, t[v], false, &d2, &qx, &qy)) return;
  const float dx = qx - px, dy = qy - py;
  const float e2 = dx * dx + dy * dy;
  if (!(e2 > 0.0f)) return;
  const float w = AP_CONTAINMENT_MARGIN / sqrt(e2);
  x[v] = qx + dx * w;
  y[v] = qy + dy * w;
  vx[v] = 0.0f;
  vy[v] = 0.0f;
}

/** The wall as the mirror image of the element (reference wall_mirror_force): for a boundary vertex
 * inside within wall_range of its nearest wall point q, Eq. 1 at the reflection 2q − x from the element's
 * own triangles (repulsion_sum with own_only), reflected back across the wall's tangent at q and weighted
 * k_mirror; zero otherwise. One work-item per boundary vertex; step_forces adds it to the wall's force,
 * and takes the container query made here (the one it would make itself: the same point, nearest
 * point included) instead of making it again. */
__kernel void wall_mirror_force(const GridInfo grid,
                                const ForceParams p,
                                const WorldInfo world,
                                __global const int* boundary_vertices,    /* input: world.boundaries of them */
                                __global const float* positions,          /* input: x, y, t */
                                __global const int* vertex_topology,      /* input: AP_TOPO_ELEMENT */
                                __global const int* grid_index,           /* input: AP_INDEX_* */
                                __global const float* slot_vertices,      /* input: per grid slot (slot_positions) */
                                __global const float* slot_centroids,     /* input: per grid slot (grid_gather) */
                                __global const float4* runs,              /* input: per run (grid_runs) */
                                __global const float* segments,           /* input: AP_SEG_*, the container */
                                const ContainerIndexInfo container_index, /* the container's index */
                                __global const int* container_lists,      /* input: its lists */
                                __global float* wall,                     /* output: AP_WALL_* per boundary vertex */
                                __global uchar* wall_inside) {            /* output: its container query's inside */
  const int i = get_global_id(0);
  if (i >= world.boundaries) return;
  const int vs = world.vertex_stride;
  const int v = boundary_vertices[i];
  const float px = positions[AP_X * vs + v], py = positions[AP_Y * vs + v], pt = positions[AP_T * vs + v];
  float d2, qx, qy;
  const bool inside =
      container_query_at(world, segments, container_index, container_lists, px, py, pt, true, &d2, &qx, &qy);
  float mx = 0.0f, my = 0.0f, mt = 0.0f;
  if (p.k_mirror != 0.0f && inside && d2 > 0.0f && d2 < p.wall_range2) {
    float sx, sy, st, closest2;
    repulsion_sum(grid, grid_index + AP_INDEX_CELL_START * grid.index_stride,
                  grid_index + AP_INDEX_SLOT_ELEMENT * grid.index_stride, slot_vertices,
                  slot_centroids + AP_X * grid.slot_stride, slot_centroids + AP_Y * grid.slot_stride,
                  slot_centroids + AP_T * grid.slot_stride, grid_index + AP_INDEX_RUN_START * grid.index_stride,
                  grid_index + AP_INDEX_RUN_ELEMENT * grid.index_stride, runs,
                  vertex_topology[AP_TOPO_ELEMENT * vs + v], 1, qx + (qx - px), qy + (qy - py), pt, p.repulsion_epsilon,
                  &sx, &sy, &st, &closest2);
    const float nx = px - qx, ny = py - qy;
    const float twice = 2.0f * ((sx * nx + sy * ny) / d2);
    mx = p.k_mirror * (sx - twice * nx);
    my = p.k_mirror * (sy - twice * ny);
    mt = p.k_mirror * st;
  }
  wall[AP_WALL_MIRROR_X * vs + v] = mx;
  wall[AP_WALL_MIRROR_Y * vs + v] = my;
  wall[AP_WALL_MIRROR_T * vs + v] = mt;
  wall_inside[v] = inside ? 1 : 0;
  wall[AP_WALL_D2 * vs + v] = d2;
  wall[AP_WALL_QX * vs + v] = qx;
  wall[AP_WALL_QY * vs + v] = qy;
}
