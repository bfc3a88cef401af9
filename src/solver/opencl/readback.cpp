// What the OpenCL backend reads back (device_backend.hpp): statistics as per-slice reductions on
// demand (every check_interval steps, and every step while the run settles), the full state only in
// state(), the forces and grids for the equivalence suite and validate; and the device time of every
// launch and transfer, from the profiling events.
#include "animpak/compare.hpp"
#include "animpak/reference/grid.hpp"
#include "device_backend.hpp"

namespace animpak::opencl {

std::vector<KernelTime> DeviceBackend::kernel_times() const {
  std::vector<KernelTime> out;
  for (const Kernel* kernel : profiled_)
    out.push_back({kernel->name(), kernel->phase(), kernel->seconds(), kernel->launches()});
  // The host's share of a step: the grids when they are built on the host (the overlap broadphase
  // from the slice boxes read back every step, the counting sort at every rebuild, the repulsion
  // order's refresh every 100 steps).
  if (host_overlap_builds_ > 0)
    out.push_back({"host: overlap broadphase", "forces", host_overlap_grid_, host_overlap_builds_});
  if (host_sorts_ > 0) out.push_back({"host: grid counting sort", "grid", host_sort_, host_sorts_});
  if (host_reorders_ > 0) out.push_back({"host: repulsion order", "transfer", host_reorder_, host_reorders_});
  return out;
}

StepStatistics DeviceBackend::statistics() {
  const std::int32_t slices = world_.slices;
  timed(times_.statistics, statistics_, slices);
  SliceStatistics per_slice;
  per_slice.resize(static_cast<std::size_t>(slices));
  std::vector<float> growth(slices);
  std::vector<std::uint8_t> changed(slices);
  read(slice_gap_, per_slice.gap, "slice_gap");
  read(slice_overlap_, per_slice.overlapping, "slice_overlap");
  read(slice_outside_, per_slice.outside, "slice_outside");
  read(slice_bad_, per_slice.first_bad, "slice_bad");
  read(growth_, growth, "growth");
  std::vector<std::int32_t> lists(broadphase_.on_device() ? 1 : 0, -1);
  read(broadphase_.total(), lists, "overlap_total");
  read(changed_, changed, "growth_changed", true);
  settle_times();
  if (!lists.empty()) broadphase_.make_room(lists.front());
  PhaseStopwatch w(times_.statistics);
  StepStatistics st;
  st.iteration = iteration_;
  std::int32_t grown = 0;
  for (const std::uint8_t c : changed) grown += (c & AP_GROWTH_GREW) != 0;
  reduce_slice_statistics(per_slice, growth, grown, st);
  return st;
}

SimState DeviceBackend::state() {
  SimState s;
  const std::size_t n = static_cast<std::size_t>(world_.vertices);
  s.x.resize(n), s.y.resize(n), s.t.resize(n), s.vx.resize(n), s.vy.resize(n), s.vt.resize(n);
  s.spring_rest.resize(spring_count_);
  s.growth.resize(world_.slices);
  read(positions_, AP_X, s.x), read(positions_, AP_Y, s.y), read(positions_, AP_T, s.t);
  read(velocities_, AP_X, s.vx), read(velocities_, AP_Y, s.vy), read(velocities_, AP_T, s.vt);
  read(rest_, s.spring_rest, "spring_rest");
  read(growth_, s.growth, "growth", true);
  settle_times();
  s.iteration = iteration_;
  s.settling_since = settling_since_;
  s.secondary_since = secondary_since_;
  copy_progress_marks(marks_, s);
  return s;
}

StepForces DeviceBackend::evaluate_forces(ForceBreakdown* out) {
  build_grid();
  order_boundary_by_cell();
  const std::int32_t n = world_.vertices;
  if (out != nullptr) {
    breakdown_ = make_buffer(context_, CL_MEM_READ_WRITE, sizeof(float) * 3 * AP_FORCE_COMPONENTS * n, "breakdown");
    forces_.set("breakdown", breakdown_);
  }
  WorldInfo world = world_;
  world.breakdown = out != nullptr ? 1 : 0;
  forces_.set("world", world);
  force_phases();
  forces_.set("world", world_);
  StepForces r;
  r.total.assign(n);
  r.closest.resize(n);
  r.contact.resize(n);
  read(forces_buf_, AP_X, r.total.x), read(forces_buf_, AP_Y, r.total.y), read(forces_buf_, AP_T, r.total.t);
  read(closest_, r.closest, "closest");
  read(contact_, r.contact, "contact", true);
  if (out != nullptr) {
    std::vector<float> all(static_cast<std::size_t>(3) * AP_FORCE_COMPONENTS * n);
    read(breakdown_, all, "breakdown", true);
    // Component c is the row c of AP_FORCE_TERMS, as breakdown_forces lists them.
    for (int c = 0; c < AP_FORCE_COMPONENTS; ++c) {
      const auto at = [&](int axis) { return all.begin() + (static_cast<std::ptrdiff_t>(c) * 3 + axis) * n; };
      ForceField& field = out->*breakdown_forces[c].field;
      field.x.assign(at(0), at(1));
      field.y.assign(at(1), at(2));
      field.t.assign(at(2), at(3));
    }
  }
  pending_.clear();
  return r;
}

CollisionGrid DeviceBackend::build_and_read_grid() {
  build_grid();
  CollisionGrid g;
  g.n = grid_.n;
  g.cell = grid_.cell;
  g.cx.resize(grid_.triangles), g.cy.resize(grid_.triangles), g.ct.resize(grid_.triangles);
  const ScratchBuffers& w = scratch_;
  read(w.env_cx, g.cx, "env_cx"), read(w.env_cy, g.cy, "env_cy"), read(w.env_ct, g.ct, "env_ct", true);
  if (sort_ == GridSort::host) {
    g.triangle_cell = cells_;
    g.cell_start = cell_start_;
    g.sorted_triangles = sorted_;
  } else {
    g.triangle_cell.resize(grid_.triangles), g.cell_start.resize(cell_start_.size());
    g.sorted_triangles.resize(grid_.triangles);
    read(w.triangle_cell, g.triangle_cell, "triangle_cell");
    read(w.sorted, g.sorted_triangles, "sorted_triangles");
    read(w.grid_index, AP_INDEX_CELL_START, g.cell_start, true);
  }
  pending_.clear();
  reference::fill_slot_elements(topo_, g);
  // The runs are the reference's own, from the arrays just read (the equivalence suite compares the
  // forces they give, not the buffers).
  if (grid_.far_cells != 0) reference::build_far_runs(g);
  return g;
}

OverlapGrid DeviceBackend::build_and_read_overlap_grid() {
  curve_tangents_kernel().run(queue_, curve_tangents_items());
  slice_boxes_.run(queue_, world_.slices);
  build_overlap_grid();
  settle_times();
  return broadphase_.read(queue_);
}

std::vector<std::int32_t> DeviceBackend::refresh_and_read_boundary_order() {
  order_boundary_by_cell();  // from the positions and the grid's fixed shape
  std::vector<std::int32_t> order = boundary_.read(queue_);
  settle_times();
  return order;
}

// Runs `kernel` on `items` work-items, its device time to count towards the phase `sink` and the
// kernel's own total (kernel_times, pack --profile).
void DeviceBackend::timed(double& sink, Kernel& kernel, std::int32_t items) {
  cl::Event e = kernel.run(queue_, items);
  if (e() == nullptr) return;
  pending_.push_back({&sink, e, &kernel});
  if (kernel.phase() == nullptr) {  // its first timed launch: name its phase, list it for kernel_times
    const char* phase = "";
    for (const NamedPhase& f : phase_fields)
      if (&(times_.*f.seconds) == &sink) phase = f.name;
    kernel.set_phase(phase);
    profiled_.push_back(&kernel);
  }
}

// Device time per phase from the profiling events. Callers have just waited on a read, so the
// finish is free; it covers batches whose reads were all empty (a world without envelope).
void DeviceBackend::settle_times() {
  check(queue_.finish(), "clFinish");
  for (const Pending& p : pending_) {
    cl_ulong start = 0, end = 0;
    check(p.event.getProfilingInfo(CL_PROFILING_COMMAND_START, &start), "clGetEventProfilingInfo(START)");
    check(p.event.getProfilingInfo(CL_PROFILING_COMMAND_END, &end), "clGetEventProfilingInfo(END)");
    const double seconds = static_cast<double>(end - start) * 1e-9;
    *p.sink += seconds;
    if (p.kernel != nullptr) p.kernel->add_time(seconds);
  }
  pending_.clear();
}

}  // namespace animpak::opencl
