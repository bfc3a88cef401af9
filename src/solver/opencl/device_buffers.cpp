// The OpenCL backend's device memory (device_buffers.hpp).
#include "device_buffers.hpp"

#include <algorithm>

#include "animpak/curve.hpp"

namespace animpak::opencl {

TopologyBuffers upload_topology(const cl::Context& context, const cl::CommandQueue& queue, const Topology& topo) {
  auto in = [&](const auto& v, const char* name) { return upload_buffer(context, queue, v, name, CL_MEM_READ_ONLY); };
  TopologyBuffers b;
  b.element = in(topo.element, "element"), b.slice = in(topo.slice, "slice"), b.flags = in(topo.flags, "flags");
  b.rest_t = in(topo.rest_t, "rest_t");
  b.rest_dir_x = in(topo.rest_dir_x, "rest_dir_x"), b.rest_dir_y = in(topo.rest_dir_y, "rest_dir_y");
  b.target = in(topo.target, "target");
  b.spring_begin = in(topo.spring_begin, "spring_begin"), b.spring_other = in(topo.spring_other, "spring_other");
  b.spring_class = in(topo.spring_class, "spring_class");
  b.tri_a = in(topo.tri_a, "tri_a"), b.tri_b = in(topo.tri_b, "tri_b"), b.tri_c = in(topo.tri_c, "tri_c");
  b.tri_begin = in(topo.tri_begin, "tri_begin"), b.tri_list = in(topo.tri_list, "tri_list");
  b.slice_begin = in(topo.slice_begin, "slice_begin"), b.slice_boundary = in(topo.slice_boundary, "slice_boundary");
  b.slice_element = in(topo.slice_element, "slice_element");
  b.element_slice_begin = in(topo.element_slice_begin, "element_slice_begin");
  // One byte per element; a topology built without the array (tests) has no secondary element.
  std::vector<std::uint8_t> secondary(static_cast<std::size_t>(std::max(topo.element_count(), 1)), 0);
  for (std::int32_t e = 0; e < topo.element_count(); ++e) secondary[e] = topo.secondary(e) ? 1 : 0;
  b.element_secondary = in(secondary, "element_secondary");
  b.env_a = in(topo.env_a, "env_a"), b.env_b = in(topo.env_b, "env_b"), b.env_c = in(topo.env_c, "env_c");
  b.env_element = in(topo.env_element, "env_element");
  b.target_x = in(topo.target_x, "target_x"), b.target_y = in(topo.target_y, "target_y");
  b.target_t = in(topo.target_t, "target_t");
  b.seg_ax = in(topo.container.ax, "container.ax"), b.seg_ay = in(topo.container.ay, "container.ay");
  b.seg_bx = in(topo.container.bx, "container.bx"), b.seg_by = in(topo.container.by, "container.by");
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
  b.rest_copy_x = in(topo.rest_copy_x, "rest_copy_x"), b.rest_copy_y = in(topo.rest_copy_y, "rest_copy_y");
  b.rest_copy_t = in(topo.rest_copy_t, "rest_copy_t");
  b.rest_copy_cx = in(topo.slice_rest_copy_cx, "slice_rest_copy_cx");
  b.rest_copy_cy = in(topo.slice_rest_copy_cy, "slice_rest_copy_cy");
  return b;
}

ScratchBuffers allocate_scratch(const cl::Context& context, std::int32_t vertices, std::int32_t slices,
                                const GridInfo& grid) {
  const auto scratch = [&](std::size_t bytes, const char* name) {
    return make_buffer(context, CL_MEM_READ_WRITE, bytes, name);
  };
  const std::size_t fn = sizeof(float) * vertices, fs = sizeof(float) * slices, ft = sizeof(float) * grid.triangles,
                    it = sizeof(std::int32_t) * grid.triangles;
  ScratchBuffers w;
  w.env_cx = scratch(ft, "env_cx"), w.env_cy = scratch(ft, "env_cy"), w.env_ct = scratch(ft, "env_ct");
  w.triangle_cell = scratch(it, "triangle_cell");
  w.cell_start = scratch(sizeof(std::int32_t) * (static_cast<std::size_t>(grid.cells) + 1), "cell_start");
  w.sorted = scratch(it, "sorted_triangles");
  // Both end in 16 spare slots: the near block's lanes read a whole group past a row's end (repulsion.cl).
  const std::size_t spare = 16;
  w.slot_element = scratch(it + sizeof(std::int32_t) * spare, "slot_element");
  w.slot_vertices = scratch(9 * ft + sizeof(float) * spare, "slot_vertices");  // nine planes: a.x, …, c.t
  w.slot_cx = scratch(ft, "slot_cx"), w.slot_cy = scratch(ft, "slot_cy"), w.slot_ct = scratch(ft, "slot_ct");
  // At most one run per slot (grid_runs).
  w.cell_runs = scratch(sizeof(std::int32_t) * static_cast<std::size_t>(grid.cells), "cell_runs");
  w.run_start = scratch(sizeof(std::int32_t) * (static_cast<std::size_t>(grid.cells) + 1), "run_start");
  w.run_element = scratch(it, "run_element"), w.runs = scratch(4 * ft, "runs");
  w.rpl_x = scratch(fn, "repulsion_x"), w.rpl_y = scratch(fn, "repulsion_y"), w.rpl_t = scratch(fn, "repulsion_t");
  w.rpl_closest = scratch(fn, "repulsion_closest"), w.rpl_contact = scratch(vertices, "repulsion_contact");
  w.depth_x = scratch(fn, "overlap_depth_x"), w.depth_y = scratch(fn, "overlap_depth_y");
  w.mirror_x = scratch(fn, "mirror_x"), w.mirror_y = scratch(fn, "mirror_y"), w.mirror_t = scratch(fn, "mirror_t");
  w.wall_inside = scratch(vertices, "wall_inside"), w.wall_d2 = scratch(fn, "wall_d2");
  w.wall_qx = scratch(fn, "wall_qx"), w.wall_qy = scratch(fn, "wall_qy");
  w.slice_cx = scratch(fs, "slice_cx"), w.slice_cy = scratch(fs, "slice_cy");
  w.box_x0 = scratch(fs, "slice_box_x0"), w.box_y0 = scratch(fs, "slice_box_y0");
  w.box_x1 = scratch(fs, "slice_box_x1"), w.box_y1 = scratch(fs, "slice_box_y1");
  w.box_t = scratch(fs, "slice_t");
  w.tangent_x = scratch(fn, "curve_tangent_x"), w.tangent_y = scratch(fn, "curve_tangent_y");
  w.handle_px = scratch(fn, "curve_handle_px"), w.handle_py = scratch(fn, "curve_handle_py");
  w.handle_qx = scratch(fn, "curve_handle_qx"), w.handle_qy = scratch(fn, "curve_handle_qy");
  w.spline_cp = scratch(fn, "spline_cp"), w.spline_z = scratch(fn, "spline_z");
  w.proposed = scratch(fs, "proposed_growth");
  return w;
}

}  // namespace animpak::opencl
