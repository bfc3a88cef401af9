/* Slice constraints of §5.2 (src/solver/reference/constraints.cpp). End-to-end and simultaneity
 * touch disjoint slices, so each slice is one work-item; the loop pass pairs disjoint vertices. */

/** End-to-end (an element's first slice to t = 0, its last to t = 1; a one-slice element ends at 1, as
 * the reference applies end-to-end's second assignment last) or simultaneity (an inner slice snapped
 * to the mean t of its vertices, summed in index order). */
__kernel void slice_constraints(const WorldInfo world,
                                __global const int* slice_topology, /* input: slice_begin, slice_element, ... */
                                __global float* positions) {        /* input/output: vertex times */
  __global const int* slice_begin = slice_topology + AP_SLICES_BEGIN * world.slice_stride;
  __global const int* slice_element = slice_topology + AP_SLICES_ELEMENT * world.slice_stride;
  __global const int* element_slice_begin = slice_topology + AP_SLICES_ELEMENT_BEGIN * world.slice_stride;
  __global float* t = positions + AP_T * world.vertex_stride;
  const int s = get_global_id(0);
  if (s >= world.slices) return;
  const int e = slice_element[s];
  const int first = element_slice_begin[e], last = element_slice_begin[e + 1] - 1;
  const int lo = slice_begin[s], hi = slice_begin[s + 1];
  if (s == last || s == first) {
    const float end = s == last ? 1.0f : 0.0f;
    for (int v = lo; v < hi; ++v) t[v] = end;
    return;
  }
  if (hi == lo) return;
  float sum = 0.0f;
  for (int v = lo; v < hi; ++v) sum = sum + t[v];
  const float mean = sum / (float)(hi - lo);
  for (int v = lo; v < hi; ++v) t[v] = mean;
}

/** Loop constraint: both vertices of pair i move to the average of their x, y; t untouched. The host
 * checks that no vertex is in two pairs, so the pairs run in parallel. */
__kernel void loop_constraint(const WorldInfo world,
                              __global const int* loop_end,   /* input: vertex on a t = 1 slice */
                              __global const int* loop_start, /* input: its partner on the t = 0 slice */
                              __global float* positions) {    /* input/output: x, y */
  __global float* x = positions + AP_X * world.vertex_stride;
  __global float* y = positions + AP_Y * world.vertex_stride;
  const int i = get_global_id(0);
  if (i >= world.loops) return;
  const int a = loop_end[i], b = loop_start[i];
  const float mx = (x[a] + x[b]) * 0.5f;
  const float my = (y[a] + y[b]) * 0.5f;
  x[a] = mx;
  x[b] = mx;
  y[a] = my;
  y[b] = my;
}
