// The kernels' parameter table and named argument values (kernel_args.hpp).
#include "kernel_args.hpp"

#include <stdexcept>

namespace animpak::opencl {

const std::vector<KernelParameters>& kernel_parameters() {
  // One row per __kernel, in program order (program.cpp, kernel_files()); the names are the kernels' own.
  static const std::vector<KernelParameters> table = {
      {"envelope_cells", {"grid", "world", "env_a", "env_b", "env_c", "positions", "cx", "cy", "ct", "triangle_cell"}},
      {"grid_clear", {"grid", "cell_count"}},
      {"grid_count", {"grid", "triangle_cell", "cell_count"}},
      {"grid_block_sums", {"grid", "cell_count", "block_sum"}},
      {"grid_scan_blocks", {"grid", "block_sum"}},
      {"grid_scan_cells", {"grid", "start_plane", "cell_count", "block_start", "starts", "cursor"}},
      {"grid_scatter", {"grid", "triangle_cell", "cursor", "sorted_triangles"}},
      {"grid_order_cells", {"grid", "start_plane", "starts", "sorted_triangles"}},
      {"grid_gather", {"grid", "sorted_triangles", "env_element", "cx", "cy", "ct", "grid_index", "slot_centroids"}},
      {"slot_positions",
       {"grid", "world", "sorted_triangles", "env_a", "env_b", "env_c", "positions", "slot_vertices"}},
      {"grid_run_counts", {"grid", "grid_index", "cell_runs"}},
      {"grid_runs", {"grid", "grid_index", "slot_centroids", "runs"}},
      {"boundary_cells", {"grid", "world", "order", "positions", "cell", "previous"}},
      {"boundary_gather", {"grid", "sorted", "previous", "order"}},
      {"curve_tangents",
       {"world", "vertex_topology", "slice_topology", "curve_prev", "curve_next", "positions", "curve_planes"}},
      {"curve_spline_tangents",
       {"world", "tracks", "track_vertex", "track_chain", "chain_begin", "chain_slice", "chain_offset", "chain_alias",
        "chain_period", "slice_topology", "positions", "cp", "z", "curve_planes"}},
      {"slice_boxes", {"world", "slice_topology", "positions", "curve_planes", "mode", "slice_geometry"}},
      {"overlap_grid_extent", {"world", "pairs", "cell_capacity", "pair_slice", "slice_geometry", "grid_info"}},
      {"overlap_grid_count", {"world", "pairs", "pair_slice", "slice_geometry", "grid_info", "cell_count"}},
      {"overlap_grid_scatter",
       {"world", "pairs", "cell_capacity", "capacity", "pair_slice", "pair_element", "slice_geometry", "grid_info",
        "cell_start", "cursor", "elements"}},
      {"overlap_grid_order", {"cell_capacity", "capacity", "cell_start", "elements", "grid_info", "total"}},
      {"repulsion_force",
       {"grid", "p", "world", "boundary_vertices", "positions", "vertex_topology", "grid_index", "slot_vertices",
        "slot_centroids", "runs", "slice_topology", "slice_geometry", "curve_planes", "growth", "repulsion",
        "repulsion_contact", "overlap_grid", "overlap_start", "overlap_elements"}},
      {"apply_containment", {"world", "segments", "container_index", "container_lists", "positions", "velocities"}},
      {"wall_mirror_force",
       {"grid", "p", "world", "boundary_vertices", "positions", "vertex_topology", "grid_index", "slot_vertices",
        "slot_centroids", "runs", "segments", "container_index", "container_lists", "wall", "wall_inside"}},
      {"contact_gap",
       {"world", "p", "positions", "vertex_topology", "slice_topology", "repulsion", "repulsion_contact", "wall",
        "wall_inside", "segments", "container_index", "container_lists", "closest", "contact"}},
      {"slice_centroids", {"world", "slice_topology", "positions", "slice_geometry"}},
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
      {"integrate", {"world", "p", "forces", "velocities", "positions"}},
      {"slice_constraints", {"world", "slice_topology", "positions"}},
      {"loop_constraint", {"world", "loop_end", "loop_start", "positions"}},
      {"propose_growth",
       {"world", "p", "growing", "hold_secondary", "slice_topology", "contact", "closest", "vertex_rest",
        "slice_rest_copy_cx", "slice_rest_copy_cy", "growth", "proposed"}},
      {"grow_slices", {"world", "p", "slice_topology", "proposed", "growth", "changed"}},
      {"update_rest_lengths",
       {"world", "vertex_topology", "springs", "changed", "growth", "vertex_rest", "slice_rest_copy_cx",
        "slice_rest_copy_cy", "spring_rest"}},
      {"slice_statistics",
       {"world", "slice_topology", "closest", "contact", "changed", "positions", "velocities", "slice_gap",
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
