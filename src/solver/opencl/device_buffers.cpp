// The OpenCL backend's device memory (device_buffers.hpp).
#include "device_buffers.hpp"

#include <algorithm>

#include "animpak/curve.hpp"

namespace animpak::opencl {

WorldInfo world_info(const Topology& topo, std::int32_t boundaries, std::int32_t alignment) {
  const auto size = [](const auto& v) { return static_cast<std::int64_t>(v.size()); };
  WorldInfo w{};
  w.vertices = topo.vertex_count();
  w.slices = topo.slice_count();
  w.elements = topo.element_count();
  w.loops = static_cast<std::int32_t>(topo.loop_end.size());
  w.segments = static_cast<std::int32_t>(topo.container.ax.size());
  w.breakdown = 0;
  w.boundaries = boundaries;
  w.vertex_stride = plane_stride(w.vertices, alignment);
  w.slice_stride = plane_stride(std::max(w.slices, w.elements) + 1, alignment);
  w.spring_stride = plane_stride(std::max<std::int64_t>(size(topo.spring_begin), size(topo.spring_other)), alignment);
  w.triangle_stride = plane_stride(std::max({size(topo.tri_a), size(topo.tri_begin), size(topo.tri_list)}), alignment);
  w.target_stride = plane_stride(size(topo.target_x), alignment);
  w.motion_entries = static_cast<std::int32_t>(topo.container.motion_a.size());
  w.segment_stride = plane_stride(std::max(w.segments, w.motion_entries), alignment);
  return w;
}

GridInfo with_grid_strides(GridInfo grid, std::int32_t alignment) {
  // The slot elements end in 16 spare slots: the near block's lanes read a whole group past a row's end
  // (repulsion.cl).
  grid.index_stride =
      plane_stride(std::max<std::int64_t>(std::int64_t{grid.cells} + 1, grid.triangles + 16), alignment);
  grid.slot_stride = plane_stride(grid.triangles, alignment);
  return grid;
}

TopologyBuffers upload_topology(const cl::Context& context, const cl::CommandQueue& queue, const Topology& topo,
                                const WorldInfo& world) {
  auto in = [&](const auto& v, const char* name) { return upload_buffer(context, queue, v, name, CL_MEM_READ_ONLY); };
  auto group = [&](int planes, std::int32_t stride, const char* name) {
    return PlaneBuffer(context, CL_MEM_READ_ONLY, planes, stride, name);
  };
  const auto ints = [](const std::vector<std::uint8_t>& bytes) {
    return std::vector<std::int32_t>(bytes.begin(), bytes.end());
  };
  TopologyBuffers b;
  b.vertex_topology = group(AP_TOPO_PLANES, world.vertex_stride, "vertex_topology");
  b.vertex_topology.write(queue, AP_TOPO_ELEMENT, topo.element);
  b.vertex_topology.write(queue, AP_TOPO_SLICE, topo.slice);
  b.vertex_topology.write(queue, AP_TOPO_FLAGS, ints(topo.flags));
  b.vertex_topology.write(queue, AP_TOPO_TARGET, topo.target);
  b.vertex_rest = group(AP_REST_PLANES, world.vertex_stride, "vertex_rest");
  b.vertex_rest.write(queue, AP_REST_T, topo.rest_t);
  b.vertex_rest.write(queue, AP_REST_DIR_X, topo.rest_dir_x);
  b.vertex_rest.write(queue, AP_REST_DIR_Y, topo.rest_dir_y);
  b.vertex_rest.write(queue, AP_REST_COPY_X, topo.rest_copy_x);
  b.vertex_rest.write(queue, AP_REST_COPY_Y, topo.rest_copy_y);
  b.vertex_rest.write(queue, AP_REST_COPY_T, topo.rest_copy_t);
  b.springs = group(AP_SPRINGS_PLANES, world.spring_stride, "springs");
  b.springs.write(queue, AP_SPRINGS_BEGIN, topo.spring_begin);
  b.springs.write(queue, AP_SPRINGS_OTHER, topo.spring_other);
  b.springs.write(queue, AP_SPRINGS_CLASS, ints(topo.spring_class));
  b.triangles = group(AP_TRIS_PLANES, world.triangle_stride, "triangles");
  b.triangles.write(queue, AP_TRIS_A, topo.tri_a);
  b.triangles.write(queue, AP_TRIS_B, topo.tri_b);
  b.triangles.write(queue, AP_TRIS_C, topo.tri_c);
  b.triangles.write(queue, AP_TRIS_BEGIN, topo.tri_begin);
  b.triangles.write(queue, AP_TRIS_LIST, topo.tri_list);
  b.slice_topology = group(AP_SLICES_PLANES, world.slice_stride, "slice_topology");
  b.slice_topology.write(queue, AP_SLICES_BEGIN, topo.slice_begin);
  b.slice_topology.write(queue, AP_SLICES_BOUNDARY, topo.slice_boundary);
  b.slice_topology.write(queue, AP_SLICES_ELEMENT, topo.slice_element);
  b.slice_topology.write(queue, AP_SLICES_ELEMENT_BEGIN, topo.element_slice_begin);
  // One per element; a topology built without the array (tests) has no secondary element.
  std::vector<std::int32_t> secondary(static_cast<std::size_t>(topo.element_count()), 0);
  for (std::int32_t e = 0; e < topo.element_count(); ++e) secondary[e] = topo.secondary(e) ? 1 : 0;
  b.slice_topology.write(queue, AP_SLICES_SECONDARY, secondary);
  b.targets = group(3, world.target_stride, "targets");
  b.targets.write(queue, AP_X, topo.target_x);
  b.targets.write(queue, AP_Y, topo.target_y);
  b.targets.write(queue, AP_T, topo.target_t);
  b.segments = group(AP_SEG_PLANES, world.segment_stride, "container segments");
  b.segments.write(queue, AP_SEG_AX, topo.container.ax);
  b.segments.write(queue, AP_SEG_AY, topo.container.ay);
  b.segments.write(queue, AP_SEG_BX, topo.container.bx);
  b.segments.write(queue, AP_SEG_BY, topo.container.by);
  if (topo.container.moves()) {
    b.segments.write(queue, AP_SEG_MOTION_A, topo.container.motion_a);
    b.segments.write(queue, AP_SEG_MOTION_B, topo.container.motion_b);
    b.segments.write(queue, AP_SEG_MOTION_EX, topo.container.motion_ex);
    b.segments.write(queue, AP_SEG_MOTION_EY, topo.container.motion_ey);
  }
  b.env_a = in(topo.env_a, "env_a"), b.env_b = in(topo.env_b, "env_b"), b.env_c = in(topo.env_c, "env_c");
  b.env_element = in(topo.env_element, "env_element");
  b.container_index = in(topo.container.index.data, "container.index");
  b.loop_end = in(topo.loop_end, "loop_end"), b.loop_start = in(topo.loop_start, "loop_start");
  require_curve_links(topo, "OpenCL backend");
  const CurveLinks& links = topo.curve;
  b.curve_prev = in(links.prev, "curve_prev"), b.curve_next = in(links.next, "curve_next");
  const CurveChains& chains = topo.chains;
  b.chain_begin = in(chains.begin, "chain_begin"), b.chain_slice = in(chains.slice, "chain_slice");
  b.chain_offset = in(chains.offset, "chain_offset"), b.chain_alias = in(chains.alias, "chain_alias");
  b.chain_period = in(chains.period, "chain_period");
  b.track_vertex = in(chains.track_vertex, "track_vertex"), b.track_chain = in(chains.track_chain, "track_chain");
  b.tracks = static_cast<std::int32_t>(chains.track_vertex.size());
  b.rest_copy_cx = in(topo.slice_rest_copy_cx, "slice_rest_copy_cx");
  b.rest_copy_cy = in(topo.slice_rest_copy_cy, "slice_rest_copy_cy");
  return b;
}

ScratchBuffers allocate_scratch(const cl::Context& context, const WorldInfo& world, const GridInfo& grid) {
  const auto scratch = [&](std::size_t bytes, const char* name) {
    return make_buffer(context, CL_MEM_READ_WRITE, bytes, name);
  };
  const auto group = [&](int planes, std::int32_t stride, const char* name) {
    return PlaneBuffer(context, CL_MEM_READ_WRITE, planes, stride, name);
  };
  const std::int32_t vertices = world.vertices;
  const std::size_t fn = sizeof(float) * vertices, fs = sizeof(float) * world.slices,
                    ft = sizeof(float) * grid.triangles, it = sizeof(std::int32_t) * grid.triangles;
  ScratchBuffers w;
  w.env_cx = scratch(ft, "env_cx"), w.env_cy = scratch(ft, "env_cy"), w.env_ct = scratch(ft, "env_ct");
  w.triangle_cell = scratch(it, "triangle_cell");
  w.sorted = scratch(it, "sorted_triangles");
  w.grid_index = group(AP_INDEX_PLANES, grid.index_stride, "grid_index");
  // The slot vertices end in 16 spare slots: the near block's lanes read a whole group past a row's end
  // (repulsion.cl).
  const std::size_t spare = 16;
  w.slot_vertices = scratch(9 * ft + sizeof(float) * spare, "slot_vertices");  // nine planes: a.x, …, c.t
  w.slot_centroids = group(3, grid.slot_stride, "slot_centroids");
  // At most one run per slot (grid_runs).
  w.cell_runs = scratch(sizeof(std::int32_t) * static_cast<std::size_t>(grid.cells), "cell_runs");
  w.runs = scratch(4 * ft, "runs");
  w.repulsion = group(AP_RPL_PLANES, world.vertex_stride, "repulsion");
  w.repulsion_contact = scratch(vertices, "repulsion_contact");
  w.wall = group(AP_WALL_PLANES, world.vertex_stride, "wall");
  w.wall_inside = scratch(vertices, "wall_inside");
  w.slice_geometry = group(AP_GEOM_PLANES, world.slice_stride, "slice_geometry");
  w.curve = group(AP_CURVE_PLANES, world.vertex_stride, "curve");
  w.spline_cp = scratch(fn, "spline_cp"), w.spline_z = scratch(fn, "spline_z");
  w.proposed = scratch(fs, "proposed_growth");
  return w;
}

}  // namespace animpak::opencl
