/* Growth of §5.3 (src/solver/reference/growth.cpp): each slice proposes its next g from its contacts
 * (shrink while outside or while overlapping an element no larger there; while settling, shrink faster
 * and whenever it overlaps; pause while overlapping only larger ones or at the wall; grow otherwise;
 * overlaps count only with elements that do not give way, AP_CONTACT_BLOCK; a secondary element keeps
 * its size while hold_secondary is set),
 * then every slice is limited to growth_ratio × the smallest proposal of its element, and the springs
 * touching a changed slice take their rest length from the scaled rest copy. */

/** growth_multiplier of src/solver/reference/growth.cpp: a free slice grows growth_step × clamp(its gap /
 * boost_gap, 1, growth_boost), and no faster than the outline may move (boost_step). */
float growth_multiplier(const float gap, const float boost_gap, const float boost, const float speed_limit) {
  float m = gap / boost_gap;
  if (m > boost) m = boost;
  if (m > speed_limit) m = speed_limit;
  return m > 1.0f ? m : 1.0f;
}

/** Slice s's proposed g; one work-item per slice. */
__kernel void propose_growth(const WorldInfo world,
                             const ForceParams p,
                             const int growing,                  /* input: 0 in the settling phase */
                             const int hold_secondary,           /* input: 1 while secondary elements wait */
                             __global const int* slice_topology, /* input: slice_begin, slice_element, ... */
                             __global const uchar* contact,      /* input: AP_CONTACT_* per vertex, from step_forces */
                             __global const float* closest,      /* input: per vertex, from step_forces */
                             __global const float* vertex_rest,  /* input: rest copy per vertex */
                             __global const float* slice_rest_copy_cx,
                             __global const float* slice_rest_copy_cy, /* input: per slice */
                             __global const float* growth,             /* input: g per slice */
                             __global float* proposed) {               /* output: proposed g per slice */
  __global const int* slice_begin = slice_topology + AP_SLICES_BEGIN * world.slice_stride;
  __global const int* slice_element = slice_topology + AP_SLICES_ELEMENT * world.slice_stride;
  __global const int* element_secondary = slice_topology + AP_SLICES_SECONDARY * world.slice_stride;
  __global const float* rest_copy_x = vertex_rest + AP_REST_COPY_X * world.vertex_stride;
  __global const float* rest_copy_y = vertex_rest + AP_REST_COPY_Y * world.vertex_stride;
  const int s = get_global_id(0);
  if (s >= world.slices) return;
  uchar bits = 0;
  float gap = INFINITY, radius2 = 0.0f;
  for (int v = slice_begin[s]; v < slice_begin[s + 1]; ++v) {
    bits |= contact[v];
    gap = closest[v] < gap ? closest[v] : gap;
    const float dx = rest_copy_x[v] - slice_rest_copy_cx[s], dy = rest_copy_y[v] - slice_rest_copy_cy[s];
    const float r2 = dx * dx + dy * dy;
    radius2 = r2 > radius2 ? r2 : radius2;
  }
  const float g = growth[s];
  float next = g;
  const bool yields = (bits & AP_CONTACT_BLOCK) != 0 && (growing == 0 || (bits & AP_CONTACT_YIELD) != 0);
  const bool held = hold_secondary != 0 && element_secondary[slice_element[s]] != 0;
  if ((bits & AP_CONTACT_OUTSIDE) != 0 || yields) {
    next = g - (growing != 0 ? p.shrink_step : p.settle_shrink_step);
    if (next < 1.0f) next = 1.0f;
  } else if (growing != 0 && !held && (bits & (AP_CONTACT_WALL | AP_CONTACT_BLOCK)) == 0 && g < p.max_growth) {
    const float speed_limit = p.boost_step / (sqrt(radius2) * p.growth_step);
    next = g + p.growth_step * growth_multiplier(gap, p.boost_gap, p.growth_boost, speed_limit);
    if (next > p.max_growth) next = p.max_growth;
  }
  proposed[s] = next;
}

/** Slice s's new g: its proposal, limited to growth_ratio × the smallest proposal of its element (a min
 * over the element's slices in order) and to neighbour_growth_ratio × each time neighbour's proposal;
 * `changed` says whether it grew or shrank and whether a limit held it. */
__kernel void grow_slices(const WorldInfo world,
                          const ForceParams p,
                          __global const int* slice_topology, /* input: slice_element, element_slice_begin */
                          __global const float* proposed,     /* input: from propose_growth */
                          __global float* growth,             /* input/output: g per slice */
                          __global uchar* changed) {          /* output: AP_GROWTH_* bits */
  __global const int* slice_element = slice_topology + AP_SLICES_ELEMENT * world.slice_stride;
  __global const int* element_slice_begin = slice_topology + AP_SLICES_ELEMENT_BEGIN * world.slice_stride;
  const int s = get_global_id(0);
  if (s >= world.slices) return;
  const int e = slice_element[s];
  const int first = element_slice_begin[e], end = element_slice_begin[e + 1];
  float smallest = proposed[first];
  for (int k = first + 1; k < end; ++k) smallest = proposed[k] < smallest ? proposed[k] : smallest;
  float bound = p.growth_ratio * smallest;
  const float before = p.neighbour_growth_ratio * (s > first ? proposed[s - 1] : 0.0f);
  const float after = p.neighbour_growth_ratio * (s + 1 < end ? proposed[s + 1] : 0.0f);
  if (s > first && before < bound) bound = before;
  if (s + 1 < end && after < bound) bound = after;
  const float g = proposed[s] < bound ? proposed[s] : bound;
  const float old = growth[s];
  /* Held below its proposal, or below one step at the paper's rate (reference grow_slices). */
  const float base = old + p.growth_step;
  const float wanted = proposed[s] < base ? proposed[s] : base;
  uchar bits = wanted < bound ? 0 : AP_GROWTH_HELD;
  if (g > old) bits |= AP_GROWTH_GREW;
  if (g < old) bits |= AP_GROWTH_SHRANK;
  changed[s] = bits;
  growth[s] = g;
}

/** Rest length of every CSR slot of vertex v whose spring has an end on a changed slice
 * (state.hpp: rest_copy_length, each end's slice scaled by its g about its rest copy centroid). */
__kernel void update_rest_lengths(const WorldInfo world,
                                  __global const int* vertex_topology, /* input: slice per vertex */
                                  __global const int* springs,         /* input: CSR rows and the other ends */
                                  __global const uchar* changed,       /* input: per slice */
                                  __global const float* growth,        /* input: g per slice */
                                  __global const float* vertex_rest,   /* input: rest copy per vertex */
                                  __global const float* slice_rest_copy_cx,
                                  __global const float* slice_rest_copy_cy, /* input: per slice */
                                  __global float* spring_rest) {            /* output: per slot */
  __global const int* slice = vertex_topology + AP_TOPO_SLICE * world.vertex_stride;
  __global const int* spring_begin = springs + AP_SPRINGS_BEGIN * world.spring_stride;
  __global const int* spring_other = springs + AP_SPRINGS_OTHER * world.spring_stride;
  __global const float* rest_copy_x = vertex_rest + AP_REST_COPY_X * world.vertex_stride;
  __global const float* rest_copy_y = vertex_rest + AP_REST_COPY_Y * world.vertex_stride;
  __global const float* rest_copy_t = vertex_rest + AP_REST_COPY_T * world.vertex_stride;
  const int v = get_global_id(0);
  if (v >= world.vertices) return;
  const int sv = slice[v];
  for (int k = spring_begin[v]; k < spring_begin[v + 1]; ++k) {
    const int w = spring_other[k];
    const int sw = slice[w];
    if (((changed[sv] | changed[sw]) & (AP_GROWTH_GREW | AP_GROWTH_SHRANK)) == 0) continue;
    const float xv = slice_rest_copy_cx[sv] + growth[sv] * (rest_copy_x[v] - slice_rest_copy_cx[sv]);
    const float yv = slice_rest_copy_cy[sv] + growth[sv] * (rest_copy_y[v] - slice_rest_copy_cy[sv]);
    const float xw = slice_rest_copy_cx[sw] + growth[sw] * (rest_copy_x[w] - slice_rest_copy_cx[sw]);
    const float yw = slice_rest_copy_cy[sw] + growth[sw] * (rest_copy_y[w] - slice_rest_copy_cy[sw]);
    const float dx = xw - xv, dy = yw - yv, dt = rest_copy_t[w] - rest_copy_t[v];
    spring_rest[k] = sqrt(dx * dx + dy * dy + dt * dt);
  }
}
