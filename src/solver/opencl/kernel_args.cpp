// The kernels' parameter table and named argument values (kernel_args.hpp).
#include "kernel_args.hpp"

#include <stdexcept>

namespace animpak::opencl {

const std::vector<KernelParameters>& kernel_parameters() {
  // One row per __kernel, in program order (program.cpp, kernel_files); the names are the kernels' own.
  static const std::vector<KernelParameters> table = {
      {"envelope_cells", {"grid", "env_a", "env_b", "env_c", "x", "y", "t", "cx", "cy", "ct", "triangle_cell"}},
      {"grid_clear", {"grid", "cell_count"}},
      {"grid_count", {"grid", "triangle_cell", "cell_count"}},
      {"grid_block_sums", {"grid", "cell_count", "block_sum"}},
      {"grid_scan_blocks", {"grid", "block_sum"}},
      {"grid_scan_cells", {"grid", "cell_count", "block_start", "cell_start", "cursor"}},
      {"grid_scatter", {"grid", "triangle_cell", "cursor", "sorted_triangles"}},
      {"grid_order_cells", {"grid", "cell_start", "sorted_triangles"}},
      {"grid_gather",
       {"grid", "sorted_triangles", "env_element", "cx", "cy", "ct", "slot_element", "slot_cx", "slot_cy", "slot_ct"}},
      {"slot_positions", {"grid", "sorted_triangles", "env_a", "env_b", "env_c", "x", "y", "t", "slot_vertices"}},
      {"grid_run_counts", {"grid", "cell_start", "slot_element", "cell_runs"}},
      {"grid_runs",
       {"grid", "cell_start", "slot_element", "slot_cx", "slot_cy", "slot_ct", "run_start", "run_element", "runs"}},
      {"boundary_cells", {"grid", "order", "x", "y", "t", "cell", "previous"}},
      {"boundary_gather", {"grid", "sorted", "previous", "order"}},
      {"curve_tangents",
       {"world", "slice", "slice_begin", "slice_element", "element_slice_begin", "curve_prev", "curve_next", "x", "y",
        "t", "tangent_x", "tangent_y"}},
      {"curve_spline_tangents",
       {"tracks", "track_vertex", "track_chain", "chain_begin", "chain_slice", "chain_offset", "chain_alias",
        "chain_period", "slice_begin", "x", "y", "t", "cp", "z", "tangent_x", "tangent_y"}},
      {"slice_boxes",
       {"world",
        "slice_begin",
        "slice_boundary",
        "slice_element",
        "element_slice_begin",
        "x",
        "y",
        "t",
        "tangent_x",
        "tangent_y",
        "mode",
        "handle_px",
        "handle_py",
        "handle_qx",
        "handle_qy",
        "box_x0",
        "box_y0",
        "box_x1",
        "box_y1",
        "box_t"}},
      {"overlap_grid_extent",
       {"pairs", "cell_capacity", "pair_slice", "box_x0", "box_y0", "box_x1", "box_y1", "box_t", "grid_info"}},
      {"overlap_grid_count",
       {"pairs", "pair_slice", "box_x0", "box_y0", "box_x1", "box_y1", "box_t", "grid_info", "cell_count"}},
      {"overlap_grid_scatter",
       {"pairs", "cell_capacity", "capacity", "pair_slice", "pair_element", "box_x0", "box_y0", "box_x1", "box_y1",
        "box_t", "grid_info", "cell_start", "cursor", "elements"}},
      {"overlap_grid_order", {"cell_capacity", "capacity", "cell_start", "elements", "grid_info", "total"}},
      {"repulsion_force",
       {"grid", "p", "world", "boundary_vertices", "positions", "vertex_topology", "grid_index", "slot_vertices",
        "slot_centroids", "runs", "slice_topology", "slice_geometry", "curve_planes", "growth", "repulsion",
        "repulsion_contact", "overlap_grid", "overlap_start", "overlap_elements"}},
      {"apply_containment",
       {"world", "seg_ax", "seg_ay", "seg_bx", "seg_by", "container_index", "container_lists", "x", "y", "vx", "vy"}},
      {"wall_mirror_force",
       {"grid", "p", "world", "boundary_vertices", "positions", "vertex_topology", "grid_index", "slot_vertices",
        "slot_centroids", "runs", "segments", "container_index", "container_lists", "wall", "wall_inside"}},
      {"contact_gap",
       {"world", "p", "positions", "vertex_topology", "slice_topology", "repulsion", "repulsion_contact", "wall",
        "wall_inside", "segments", "container_index", "container_lists", "closest", "contact"}},
      {"slice_centroids", {"world", "slice_begin", "x", "y", "slice_cx", "slice_cy"}},
      {"step_forces",
       {"world",
        "p",
        "positions",
        "vertex_topology",
        "vertex_rest",
        "springs",
        "spring_rest",
        "triangles",
        "growth",
        "repulsion",
        "repulsion_contact",
        "targets",
        "segments",
        "container_index",
        "container_lists",
        "slice_geometry",
        "wall",
        "wall_inside",
        "forces",
        "breakdown"}},
      {"integrate", {"world", "p", "fx", "fy", "ft", "vx", "vy", "vt", "x", "y", "t"}},
      {"slice_constraints", {"world", "slice_begin", "slice_element", "element_slice_begin", "t"}},
      {"loop_constraint", {"world", "loop_end", "loop_start", "x", "y"}},
      {"propose_growth",
       {"world", "p", "growing", "hold_secondary", "slice_begin", "slice_element", "element_secondary", "contact",
        "closest", "rest_copy_x", "rest_copy_y", "slice_rest_copy_cx", "slice_rest_copy_cy", "growth", "proposed"}},
      {"grow_slices", {"world", "p", "slice_element", "element_slice_begin", "proposed", "growth", "changed"}},
      {"update_rest_lengths",
       {"world", "slice", "spring_begin", "spring_other", "changed", "growth", "rest_copy_x", "rest_copy_y",
        "rest_copy_t", "slice_rest_copy_cx", "slice_rest_copy_cy", "spring_rest"}},
      {"slice_statistics",
       {"world", "slice_begin", "closest", "contact", "changed", "x", "y", "t", "vx", "vy", "vt", "slice_gap",
        "slice_overlap", "slice_outside", "slice_bad"}},
  };
  return table;
}

const KernelParameters& kernel_parameters(std::string_view kernel) {
  for (const KernelParameters& row : kernel_parameters())
    if (row.kernel == kernel) return row;
  throw std::invalid_argument("kernel " + std::string(kernel) +
                              " has no row in kernel_parameters (src/solver/opencl/kernel_args.cpp); add its "
                              "parameters' names there in order");
}

void Arg::apply(const cl::Kernel& kernel, cl_uint index, const std::string& what) const {
  const cl_int err = is_buffer_ ? clSetKernelArg(kernel(), index, sizeof(cl_mem), &buffer_())
                                : clSetKernelArg(kernel(), index, bytes_.size(), bytes_.data());
  check(err, "clSetKernelArg(" + what + ")");
}

void ArgValues::add(const Arg& arg) {
  for (Arg& a : args_)
    if (a.name() == arg.name()) {
      a = arg;
      return;
    }
  args_.push_back(arg);
}

const Arg* ArgValues::find(std::string_view name) const {
  for (const Arg& a : args_)
    if (a.name() == name) return &a;
  return nullptr;
}

}  // namespace animpak::opencl
