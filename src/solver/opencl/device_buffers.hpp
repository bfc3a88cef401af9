// The OpenCL backend's device memory (opencl_backend.cpp): the topology's arrays, uploaded once and
// read-only, and the scratch that one phase of a step hands to the next, sized once from the world and
// the collision grid. The state that moves (SimState) and the results the host reads stay with the
// backend, which owns their lifetimes and transfers.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cl_host.hpp"

namespace animpak::opencl {

/// A device buffer holding `data` (read-write unless `flags` says otherwise), written with a blocking
/// write on `queue`; an empty vector gives a 1-byte buffer (make_buffer) with nothing written.
template <typename T>
cl::Buffer upload_buffer(const cl::Context& context, const cl::CommandQueue& queue, const std::vector<T>& data,
                         const char* name, cl_mem_flags flags = CL_MEM_READ_WRITE) {
  cl::Buffer b = make_buffer(context, flags, sizeof(T) * data.size(), name);
  if (!data.empty())
    check(queue.enqueueWriteBuffer(b, CL_TRUE, 0, sizeof(T) * data.size(), data.data()),
          std::string("clEnqueueWriteBuffer(") + name + ")");
  return b;
}

/// The topology's arrays on the device, read-only, one buffer per Topology field the kernels read.
struct TopologyBuffers {
  cl::Buffer element, slice, flags, rest_t, rest_dir_x, rest_dir_y, target;
  cl::Buffer spring_begin, spring_other, spring_class;
  cl::Buffer tri_a, tri_b, tri_c, tri_begin, tri_list;
  cl::Buffer slice_begin, slice_boundary, slice_element, element_slice_begin, element_secondary;
  cl::Buffer env_a, env_b, env_c, env_element;
  cl::Buffer target_x, target_y, target_t;
  cl::Buffer seg_ax, seg_ay, seg_bx, seg_by, container_index;
  cl::Buffer loop_end, loop_start;
  cl::Buffer curve_prev, curve_next;  // curve_links: the slices before and after each slice
  cl::Buffer chain_begin, chain_slice, chain_offset, chain_alias, chain_period;  // curve_chains: the spline's
  cl::Buffer track_vertex, track_chain;                                          // tracks
  std::int32_t tracks = 0;
  cl::Buffer rest_copy_x, rest_copy_y, rest_copy_t, rest_copy_cx, rest_copy_cy;
};

/// Uploads every array of `topo` the kernels read.
TopologyBuffers upload_topology(const cl::Context& context, const cl::CommandQueue& queue, const Topology& topo);

/// Scratch one phase of a step hands to the next; nothing here outlives a step.
struct ScratchBuffers {
  cl::Buffer env_cx, env_cy, env_ct, triangle_cell;                   // centroids and cells
  cl::Buffer cell_start, sorted;                                      // grid sort
  cl::Buffer slot_element, slot_vertices, slot_cx, slot_cy, slot_ct;  // triangles in cell order
  cl::Buffer cell_runs, run_start, run_element, runs;                 // far-field cell aggregates, packed in cell order
  cl::Buffer rpl_x, rpl_y, rpl_t, rpl_closest, rpl_contact, depth_x, depth_y;  // repulsion, overlap test
  cl::Buffer slice_cx, slice_cy, box_x0, box_y0, box_x1, box_y1, box_t;        // per-slice geometry
  cl::Buffer tangent_x, tangent_y, spline_cp, spline_z;                        // the curve between slices
  cl::Buffer handle_px, handle_py, handle_qx, handle_qy;  // its Bézier handles, per boundary vertex (slice_boxes)
  cl::Buffer mirror_x, mirror_y, mirror_t;                // the wall's mirror image
  cl::Buffer wall_inside, wall_d2, wall_qx, wall_qy;      // its container query, which step_forces reuses
  cl::Buffer proposed;                                    // growth proposals
};

/// Allocates the scratch for a world of `vertices` and `slices` and the collision grid `grid`.
ScratchBuffers allocate_scratch(const cl::Context& context, std::int32_t vertices, std::int32_t slices,
                                const GridInfo& grid);

}  // namespace animpak::opencl
