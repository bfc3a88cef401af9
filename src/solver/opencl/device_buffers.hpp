// The OpenCL backend's device memory (device_backend.hpp): the topology's arrays, uploaded once and
// read-only, and the scratch that one phase of a step hands to the next, sized once from the world and
// the collision grid. Related arrays travel as grouped buffers (plane_buffer.hpp; kernels/shared_types.h,
// "Grouped buffers"), their planes' strides in WorldInfo and GridInfo. The state that moves (SimState)
// and the results the host reads stay with the backend, which owns their lifetimes and transfers.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cl_host.hpp"
#include "plane_buffer.hpp"

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

/// The strides of the world's grouped buffers for `topo` on a device whose planes align to `alignment`
/// elements (plane_alignment), with its sizes; breakdown 0.
WorldInfo world_info(const Topology& topo, std::int32_t boundaries, std::int32_t alignment);

/// `grid` with the strides of its grouped buffers (grid_index, slot_centroids).
GridInfo with_grid_strides(GridInfo grid, std::int32_t alignment);

/// The topology's arrays on the device, read-only: the groups of shared_types.h and the arrays no
/// group holds.
struct TopologyBuffers {
  PlaneBuffer vertex_topology, vertex_rest, springs, triangles, slice_topology, targets, segments;
  cl::Buffer env_a, env_b, env_c, env_element, container_index;
  cl::Buffer loop_end, loop_start;
  cl::Buffer curve_prev, curve_next;  // curve_links: the slices before and after each slice
  cl::Buffer chain_begin, chain_slice, chain_offset, chain_alias, chain_period;  // curve_chains: the spline's
  cl::Buffer track_vertex, track_chain;                                          // tracks
  std::int32_t tracks = 0;
  cl::Buffer rest_copy_cx, rest_copy_cy;  // the rest copy's centroid per slice
};

/// Uploads every array of `topo` the kernels read, in the groups of `world`'s strides.
TopologyBuffers upload_topology(const cl::Context& context, const cl::CommandQueue& queue, const Topology& topo,
                                const WorldInfo& world);

/// Scratch one phase of a step hands to the next; nothing here outlives a step.
struct ScratchBuffers {
  cl::Buffer env_cx, env_cy, env_ct, triangle_cell;  // centroids and cells
  cl::Buffer sorted;                                 // grid sort
  PlaneBuffer grid_index;                            // cell and run ranges, slot and run elements (AP_INDEX_*)
  cl::Buffer slot_vertices;                          // triangles in cell order: nine planes a.x … c.t
  PlaneBuffer slot_centroids;                        // their centroids
  cl::Buffer cell_runs, runs;                        // far-field cell aggregates, packed in cell order
  PlaneBuffer repulsion;                             // repulsion and the overlap test (AP_RPL_*)
  cl::Buffer repulsion_contact;                      // the overlap test's bits
  PlaneBuffer slice_geometry;                        // per-slice centroids and boxes (AP_GEOM_*)
  PlaneBuffer curve;                                 // the curve between slices: tangents, handles (AP_CURVE_*)
  cl::Buffer spline_cp, spline_z;                    // the spline's solve
  PlaneBuffer wall;                                  // the wall's mirror image and query (AP_WALL_*)
  cl::Buffer wall_inside;                            // the query's inside
  cl::Buffer proposed;                               // growth proposals
};

/// Allocates the scratch for `world` and the collision grid `grid` (with_grid_strides).
ScratchBuffers allocate_scratch(const cl::Context& context, const WorldInfo& world, const GridInfo& grid);

}  // namespace animpak::opencl
