// The OpenCL backend's kernels and the values their arguments are bound from (device_backend.hpp). Every
// kernel takes its arguments by name through the parameter table (kernel_args.cpp); argument_values is
// the one list of what each name means here, a row per buffer or value, so a kernel that reads a buffer
// already listed needs no change in this file, and a new buffer is one row
// (docs/architecture.md, "How to add a force").
#include "device_backend.hpp"

namespace animpak::opencl {

ArgValues DeviceBackend::argument_values(const ForceParams& p) const {
  const TopologyBuffers& b = topo_buf_;
  const ScratchBuffers& w = scratch_;
  ArgValues v{
      // Sizes, shapes and the step's constants, by value.
      {"world", world_},
      {"grid", grid_},
      {"p", p},
      {"mode", curve_mode_},
      {"tracks", b.tracks},
      {"container_index", container_index_info(topo_.container.index)},
      {"growing", settling_since_ == 0 ? 1 : 0},
      {"hold_secondary", secondary_since_ == 0 ? 1 : 0},
      // The state (SimState), as groups: a kernel names the planes it reads (shared_types.h).
      {"positions", positions_.buffer()},
      {"velocities", velocities_.buffer()},
      {"spring_rest", rest_},
      {"growth", growth_},
      // The topology (device_buffers.cpp).
      {"vertex_topology", b.vertex_topology.buffer()},
      {"vertex_rest", b.vertex_rest.buffer()},
      {"slice_rest_copy_cx", b.rest_copy_cx},
      {"slice_rest_copy_cy", b.rest_copy_cy},
      {"springs", b.springs.buffer()},
      {"triangles", b.triangles.buffer()},
      {"slice_topology", b.slice_topology.buffer()},
      {"targets", b.targets.buffer()},
      {"segments", b.segments.buffer()},
      {"container_lists", b.container_index},
      {"env_a", b.env_a},
      {"env_b", b.env_b},
      {"env_c", b.env_c},
      {"env_element", b.env_element},
      {"loop_end", b.loop_end},
      {"loop_start", b.loop_start},
      {"curve_prev", b.curve_prev},
      {"curve_next", b.curve_next},
      {"track_vertex", b.track_vertex},
      {"track_chain", b.track_chain},
      {"chain_begin", b.chain_begin},
      {"chain_slice", b.chain_slice},
      {"chain_offset", b.chain_offset},
      {"chain_alias", b.chain_alias},
      {"chain_period", b.chain_period},
      {"boundary_vertices", boundary_.buffer()},
      // The collision grid (§5.1).
      {"cx", w.env_cx},
      {"cy", w.env_cy},
      {"ct", w.env_ct},
      {"triangle_cell", w.triangle_cell},
      {"sorted_triangles", w.sorted},
      {"grid_index", w.grid_index.buffer()},
      {"slot_vertices", w.slot_vertices},
      {"slot_centroids", w.slot_centroids.buffer()},
      {"cell_runs", w.cell_runs},
      {"runs", w.runs},
      // The force phases' scratch, in step order.
      {"slice_geometry", w.slice_geometry.buffer()},
      {"curve_planes", w.curve.buffer()},
      {"cp", w.spline_cp},
      {"z", w.spline_z},
      {"repulsion", w.repulsion.buffer()},
      {"repulsion_contact", w.repulsion_contact},
      {"wall", w.wall.buffer()},
      {"wall_inside", w.wall_inside},
      {"forces", forces_buf_.buffer()},
      {"breakdown", breakdown_},
      // What the step leaves for growth and the statistics.
      {"closest", closest_},
      {"contact", contact_},
      {"proposed", w.proposed},
      {"changed", changed_},
      {"slice_gap", slice_gap_},
      {"slice_overlap", slice_overlap_},
      {"slice_outside", slice_outside_},
      {"slice_bad", slice_bad_},
  };
  broadphase_.add_values(v);
  return v;
}

// The collision grid's kernels (§5.1): centroids and cells, the device sort, the per-slot copies.
void DeviceBackend::bind_grid_kernels(const cl::Program& program, const ArgValues& values) {
  const ScratchBuffers& w = scratch_;
  envelope_cells_ = Kernel(program, "envelope_cells");
  envelope_cells_.bind(values);
  if (sort_ == GridSort::device)
    grid_sort_ =
        DeviceCountingSort(context_, program, grid_.triangles, grid_.cells, w.triangle_cell,
                           StartPlane{w.grid_index.buffer(), AP_INDEX_CELL_START, w.grid_index.stride()}, w.sorted);
  grid_gather_ = Kernel(program, "grid_gather");
  grid_gather_.bind(values);
  slot_positions_ = Kernel(program, "slot_positions");
  slot_positions_.bind(values);
  run_counts_ = Kernel(program, "grid_run_counts");
  run_counts_.bind(values);
  run_scan_ = DeviceScan(context_, program, grid_.cells, w.cell_runs,
                         StartPlane{w.grid_index.buffer(), AP_INDEX_RUN_START, w.grid_index.stride()}, "runs: ");
  grid_runs_ = Kernel(program, "grid_runs");
  grid_runs_.bind(values);
}

// Every kernel's tangents for the curve between slices: the spline's, a solve per track, or Steffen's,
// one work-item per vertex (reference::curve_tangents).
Kernel& DeviceBackend::curve_tangents_kernel() {
  return curve_mode_ == AP_CURVE_SPLINE ? curve_spline_tangents_ : curve_tangents_;
}
std::int32_t DeviceBackend::curve_tangents_items() const {
  return curve_mode_ == AP_CURVE_SPLINE ? topo_buf_.tracks : world_.vertices;
}

// Every other phase of a step, in step order: forces (§5), integration, constraints (§5.2),
// containment, growth (§5.3), then the statistics read on demand.
void DeviceBackend::bind_step_kernels(const cl::Program& program, const ArgValues& values, const ForceParams& p) {
  mirror_ = p.k_mirror != 0.0f;
  const std::pair<Kernel*, const char*> kernels[] = {
      // The tangents before the boxes: on the spline the slice boxes hold the curve's handles
      // (curve_tangents, then slice_boxes, as reference::step_forces does).
      {&curve_tangents_, "curve_tangents"},
      {&curve_spline_tangents_, "curve_spline_tangents"},
      {&slice_centroids_, "slice_centroids"},
      {&slice_boxes_, "slice_boxes"},
      {&repulsion_force_, "repulsion_force"},
      {&wall_mirror_, "wall_mirror_force"},
      {&forces_, "step_forces"},
      {&contact_gap_, "contact_gap"},
      {&integrate_, "integrate"},
      {&constraints_, "slice_constraints"},
      {&loop_, "loop_constraint"},
      {&apply_containment_, "apply_containment"},
      {&propose_growth_, "propose_growth"},
      {&grow_, "grow_slices"},
      {&rest_lengths_, "update_rest_lengths"},
      {&statistics_, "slice_statistics"},
  };
  for (const auto& [kernel, name] : kernels) {
    *kernel = Kernel(program, name);
    kernel->bind(values);
  }
}

}  // namespace animpak::opencl
