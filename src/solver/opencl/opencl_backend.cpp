// The OpenCL backend: the reference backend's step (src/solver/reference/backend.cpp) with the state
// on the device. The two grids are built either on the device (GPUs: a step then never waits for the
// host) or on the host (CPU devices): the collision grid's stable counting sort (count → exclusive scan
// → scatter) from the cell ids read back, and the overlap test's broadphase from the slice boxes read
// back every step (overlap_broadphase.cpp), and the repulsion kernel's work order by cell, refreshed every
// 100 steps (boundary_order.cpp). Statistics are per-slice reductions read on demand (every
// check_interval steps, and every step while the run settles), and the full state comes back only in
// state(). The topology and scratch buffers are made in device_buffers.cpp.
#include <algorithm>
#include <chrono>
#include <limits>
#include <stdexcept>

#include "../counting_sort.hpp"
#include "animpak/error.hpp"
#include "animpak/reference/grid.hpp"
#include "animpak/step_params.hpp"
#include "boundary_order.hpp"
#include "device_buffers.hpp"
#include "device_sort.hpp"
#include "kernel.hpp"
#include "overlap_broadphase.hpp"

namespace animpak {

GridSort parse_grid_sort(std::string_view text, std::string_view option) {
  if (text == "auto") return GridSort::automatic;
  if (text == "host") return GridSort::host;
  if (text == "device") return GridSort::device;
  throw UsageError(std::string(option) + ": '" + std::string(text) + "' is not a grid sort; use auto, host or device");
}

const char* grid_sort_name(GridSort sort) {
  switch (sort) {
    case GridSort::host:
      return "host";
    case GridSort::device:
      return "device";
    case GridSort::automatic:
      break;
  }
  return "auto";
}

namespace {

using opencl::check;
using opencl::Kernel;
using opencl::ScratchBuffers;
using opencl::TopologyBuffers;

void validate(const Topology& topo) {
  const std::int32_t n = topo.vertex_count();
  if (topo.slice_begin.empty() || topo.slice_begin.front() != 0 || topo.slice_begin.back() != n)
    throw std::invalid_argument("opencl backend: the slices must cover the vertices in order");
  std::vector<std::uint8_t> used(n, 0);
  for (std::size_t i = 0; i < topo.loop_end.size(); ++i)
    for (const std::int32_t v : {topo.loop_end[i], topo.loop_start[i]}) {
      if (used[v]) throw std::invalid_argument("opencl backend: vertex " + std::to_string(v) + " is in two loop pairs");
      used[v] = 1;
    }
}

class DeviceBackend final : public OpenclBackend {
 public:
  DeviceBackend(const Topology& topology, SimState initial, const Params& params, const DeviceInfo& info, GridSort sort)
      : topo_(topology),
        info_(info),
        iteration_(initial.iteration),
        settling_since_(initial.settling_since),
        secondary_since_(initial.secondary_since),
        rebuild_(params.forces.grid_rebuild_interval),
        sort_(sort != GridSort::automatic ? sort
              : info.gpu                  ? GridSort::device
                                          : GridSort::host) {
    validate(topo_);
    copy_progress_marks(initial, marks_);
    const cl::Program program = create_queue();
    world_ = {topo_.vertex_count(),
              topo_.slice_count(),
              topo_.element_count(),
              static_cast<std::int32_t>(topo_.loop_end.size()),
              static_cast<std::int32_t>(topo_.container.ax.size()),
              0};
    grid_ = opencl::grid_info(params, topo_.envelope_count());
    upload_state(initial);
    topo_buf_ = opencl::upload_topology(context_, queue_, topo_);
    allocate_scratch();
    broadphase_ = opencl::OverlapBroadphase(context_, queue_, program, topo_, scratch_, sort_ == GridSort::device);
    std::vector<std::int32_t> boundary;
    for (std::int32_t v = 0; v < world_.vertices; ++v)
      if ((topo_.flags[v] & vertex_boundary) != 0) boundary.push_back(v);
    boundary_ = opencl::BoundaryOrder(context_, queue_, program, std::move(boundary), grid_, x_, y_, t_,
                                      sort_ == GridSort::device);
    bind_grid_kernels(program);
    bind_step_kernels(program, step_params(params));
    check(queue_.finish(), "clFinish(upload)");
  }

  std::string name() const override { return info_.name; }
  const DeviceInfo& device() const override { return info_; }
  GridSort grid_sort() const override { return sort_; }
  void finish() override { settle_times(); }
  void set_progress_mark(const SimState& marks) override { copy_progress_marks(marks, marks_); }
  void stop_growth() override {
    if (settling_since_ != 0) return;
    settling_since_ = iteration_;
    propose_growth_.set(2, 0);
  }
  bool start_secondary_growth() override {
    if (secondary_since_ != 0 || !topo_.has_secondary()) return false;
    secondary_since_ = iteration_;
    propose_growth_.set(3, 0);
    return true;
  }
  const PhaseTimes& times() const override { return times_; }
  std::vector<KernelTime> kernel_times() const override {
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

  void step() override {
    if (iteration_ % static_cast<std::uint64_t>(rebuild_) == 0 || !grid_built_) build_grid();
    if (!boundary_ordered_ || iteration_ - boundary_ordered_at_ >= opencl::BoundaryOrder::interval())
      order_boundary_by_cell();
    timed(times_.grid, slot_positions_, grid_.triangles);
    timed(times_.forces, slice_centroids_, world_.slices);
    timed(times_.forces, curve_tangents_kernel(), curve_tangents_items());
    timed(times_.forces, slice_boxes_, world_.slices);
    build_overlap_grid();
    timed(times_.forces, repulsion_force_, boundary_.count());
    if (mirror_) timed(times_.forces, wall_mirror_, boundary_.count());
    timed(times_.forces, forces_, world_.vertices);
    timed(times_.integrate, integrate_, world_.vertices);
    timed(times_.constraints, constraints_, world_.slices);
    timed(times_.loop, loop_, world_.loops);
    timed(times_.constraints, apply_containment_, world_.vertices);
    timed(times_.growth, propose_growth_, world_.slices);
    timed(times_.growth, grow_, world_.slices);
    timed(times_.growth, rest_lengths_, world_.vertices);
    ++iteration_;
  }

  StepStatistics statistics() override {
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

  SimState state() override {
    SimState s;
    const std::size_t n = static_cast<std::size_t>(world_.vertices);
    s.x.resize(n), s.y.resize(n), s.t.resize(n), s.vx.resize(n), s.vy.resize(n), s.vt.resize(n);
    s.spring_rest.resize(spring_count_);
    s.growth.resize(world_.slices);
    read(x_, s.x, "x"), read(y_, s.y, "y"), read(t_, s.t, "t");
    read(vx_, s.vx, "vx"), read(vy_, s.vy, "vy"), read(vt_, s.vt, "vt");
    read(rest_, s.spring_rest, "spring_rest");
    read(growth_, s.growth, "growth", true);
    settle_times();
    s.iteration = iteration_;
    s.settling_since = settling_since_;
    s.secondary_since = secondary_since_;
    copy_progress_marks(marks_, s);
    return s;
  }

  StepForces evaluate_forces(ForceBreakdown* out) override {
    build_grid();
    order_boundary_by_cell();
    const std::int32_t n = world_.vertices;
    if (out != nullptr) {
      breakdown_ =
          opencl::make_buffer(context_, CL_MEM_READ_WRITE, sizeof(float) * 3 * AP_FORCE_COMPONENTS * n, "breakdown");
      forces_.set(breakdown_arg_, breakdown_);
    }
    WorldInfo world = world_;
    world.breakdown = out != nullptr ? 1 : 0;
    forces_.set(0, world);
    slot_positions_.run(queue_, grid_.triangles);
    slice_centroids_.run(queue_, world_.slices);
    curve_tangents_kernel().run(queue_, curve_tangents_items());
    slice_boxes_.run(queue_, world_.slices);
    build_overlap_grid();
    repulsion_force_.run(queue_, boundary_.count());
    if (mirror_) wall_mirror_.run(queue_, boundary_.count());
    forces_.run(queue_, n);
    forces_.set(0, world_);
    StepForces r;
    r.total.assign(n);
    r.closest.resize(n);
    r.contact.resize(n);
    read(fx_, r.total.x, "fx"), read(fy_, r.total.y, "fy"), read(ft_, r.total.t, "ft");
    read(closest_, r.closest, "closest");
    read(contact_, r.contact, "contact", true);
    if (out != nullptr) {
      std::vector<float> all(static_cast<std::size_t>(3) * AP_FORCE_COMPONENTS * n);
      read(breakdown_, all, "breakdown", true);
      ForceField* fields[AP_FORCE_COMPONENTS] = {};
      fields[AP_FORCE_REPULSION] = &out->repulsion, fields[AP_FORCE_SPRINGS] = &out->springs;
      fields[AP_FORCE_TARGET] = &out->target, fields[AP_FORCE_BOUNDARY] = &out->boundary;
      fields[AP_FORCE_OVERLAP] = &out->overlap, fields[AP_FORCE_TORSION] = &out->torsion;
      fields[AP_FORCE_TEMPORAL] = &out->temporal;
      for (int c = 0; c < AP_FORCE_COMPONENTS; ++c) {
        const auto at = [&](int axis) { return all.begin() + (static_cast<std::ptrdiff_t>(c) * 3 + axis) * n; };
        fields[c]->x.assign(at(0), at(1));
        fields[c]->y.assign(at(1), at(2));
        fields[c]->t.assign(at(2), at(3));
      }
    }
    pending_.clear();
    return r;
  }

  CollisionGrid build_and_read_grid() override {
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
      read(w.cell_start, g.cell_start, "cell_start", true);
    }
    pending_.clear();
    reference::fill_slot_elements(topo_, g);
    // The runs are the reference's own, from the arrays just read (the equivalence suite compares the
    // forces they give, not the buffers).
    if (grid_.far_cells != 0) reference::build_far_runs(g);
    return g;
  }

  OverlapGrid build_and_read_overlap_grid() override {
    curve_tangents_kernel().run(queue_, curve_tangents_items());
    slice_boxes_.run(queue_, world_.slices);
    build_overlap_grid();
    settle_times();
    return broadphase_.read(queue_);
  }

  void set_overlap_room(std::size_t entries) override { broadphase_.set_capacity(entries); }

  std::vector<std::int32_t> refresh_and_read_boundary_order() override {
    order_boundary_by_cell();  // from the positions and the grid's fixed shape
    std::vector<std::int32_t> order = boundary_.read(queue_);
    settle_times();
    return order;
  }

 private:
  // The context and an in-order, profiling queue on the chosen device; returns the built program.
  cl::Program create_queue() {
    const cl::Device device = opencl::device_for(info_);
    cl_int err = CL_SUCCESS;
    context_ = cl::Context(device, nullptr, nullptr, nullptr, &err);
    check(err, "clCreateContext(" + info_.name + ")");
    queue_ = cl::CommandQueue(context_, device, CL_QUEUE_PROFILING_ENABLE, &err);
    check(err, "clCreateCommandQueue(" + info_.name + ")");
    return opencl::build_program(context_, device);
  }

  // Everything that moves (SimState), the per-vertex and per-slice results the host reads, and the
  // boundary vertices the repulsion kernel runs over.
  void upload_state(const SimState& initial) {
    x_ = upload(initial.x, "x"), y_ = upload(initial.y, "y"), t_ = upload(initial.t, "t");
    vx_ = upload(initial.vx, "vx"), vy_ = upload(initial.vy, "vy"), vt_ = upload(initial.vt, "vt");
    rest_ = upload(initial.spring_rest, "spring_rest");
    growth_ = upload(initial.growth, "growth");
    spring_count_ = initial.spring_rest.size();
    const std::int32_t n = world_.vertices, slices = world_.slices;
    // Before the first step the statistics see what the reference starts from: no gap, no overlap.
    closest_ = upload(std::vector<float>(n, std::numeric_limits<float>::infinity()), "closest");
    contact_ = upload(std::vector<std::uint8_t>(n, 0), "contact");
    changed_ = upload(std::vector<std::uint8_t>(slices, 0), "growth_changed");
    const std::size_t fn = sizeof(float) * n, fs = sizeof(float) * slices, is = sizeof(std::int32_t) * slices;
    fx_ = scratch(fn, "fx"), fy_ = scratch(fn, "fy"), ft_ = scratch(fn, "ft");
    breakdown_ = scratch(1, "breakdown (unused)");
    slice_gap_ = scratch(fs, "slice_gap");
    slice_overlap_ = scratch(is, "slice_overlap");
    slice_outside_ = scratch(is, "slice_outside");
    slice_bad_ = scratch(is, "slice_bad");
  }

  // The device scratch (device_buffers.cpp) and the host arrays the host sort and the broadphase fill.
  void allocate_scratch() {
    scratch_ = opencl::allocate_scratch(context_, world_.vertices, world_.slices, grid_);
    cells_.resize(grid_.triangles);
    cell_start_.resize(static_cast<std::size_t>(grid_.cells) + 1);
    sorted_.resize(grid_.triangles);
    const std::size_t slices = static_cast<std::size_t>(world_.slices);
    boxes_.x0.resize(slices), boxes_.y0.resize(slices), boxes_.x1.resize(slices), boxes_.y1.resize(slices);
    boxes_.t.resize(slices);
  }

  // The collision grid's kernels (§5.1): centroids and cells, the device sort, the per-slot copies.
  void bind_grid_kernels(const cl::Program& program) {
    const TopologyBuffers& b = topo_buf_;
    const ScratchBuffers& w = scratch_;
    envelope_cells_ = Kernel(program, "envelope_cells");
    envelope_cells_.bind(grid_, b.env_a, b.env_b, b.env_c, x_, y_, t_, w.env_cx, w.env_cy, w.env_ct, w.triangle_cell);
    if (sort_ == GridSort::device)
      grid_sort_ = opencl::DeviceCountingSort(context_, program, grid_.triangles, grid_.cells, w.triangle_cell,
                                              w.cell_start, w.sorted);
    grid_gather_ = Kernel(program, "grid_gather");
    grid_gather_.bind(grid_, w.sorted, b.env_element, w.env_cx, w.env_cy, w.env_ct, w.slot_element, w.slot_cx,
                      w.slot_cy, w.slot_ct);
    slot_positions_ = Kernel(program, "slot_positions");
    slot_positions_.bind(grid_, w.sorted, b.env_a, b.env_b, b.env_c, x_, y_, t_, w.slot_vertices);
    run_counts_ = Kernel(program, "grid_run_counts");
    run_counts_.bind(grid_, w.cell_start, w.slot_element, w.cell_runs);
    run_scan_ = opencl::DeviceScan(context_, program, grid_.cells, w.cell_runs, w.run_start, "runs: ");
    grid_runs_ = Kernel(program, "grid_runs");
    grid_runs_.bind(grid_, w.cell_start, w.slot_element, w.slot_cx, w.slot_cy, w.slot_ct, w.run_start, w.run_element,
                    w.runs);
  }

  // Every vertex's tangent for the curve between slices: the spline's, a solve per track, or Steffen's,
  // one work-item per vertex (reference::curve_tangents).
  Kernel& curve_tangents_kernel() { return curve_mode_ == AP_CURVE_SPLINE ? curve_spline_tangents_ : curve_tangents_; }
  std::int32_t curve_tangents_items() const {
    return curve_mode_ == AP_CURVE_SPLINE ? topo_buf_.tracks : world_.vertices;
  }

  // Every other phase of a step, in step order: forces (§5), integration, constraints (§5.2),
  // containment, growth (§5.3), then the statistics read on demand.
  void bind_step_kernels(const cl::Program& program, const ForceParams& p) {
    const TopologyBuffers& b = topo_buf_;
    const ScratchBuffers& w = scratch_;
    // The tangents first: on the spline the slice boxes hold the curve's handles (curve_tangents, then
    // slice_boxes, as reference::step_forces does).
    curve_mode_ = p.motion_curve;
    slice_boxes_ = Kernel(program, "slice_boxes");
    slice_boxes_.bind(world_, b.slice_begin, b.slice_boundary, b.slice_element, b.element_slice_begin, x_, y_, t_,
                      w.tangent_x, w.tangent_y, curve_mode_, w.handle_px, w.handle_py, w.handle_qx, w.handle_qy,
                      w.box_x0, w.box_y0, w.box_x1, w.box_y1, w.box_t);
    repulsion_force_ = Kernel(program, "repulsion_force");
    // The broadphase's three arguments come last; build_overlap_grid sets them every step.
    overlap_grid_arg_ = repulsion_force_.bind(
        grid_, p, boundary_.count(), world_.elements, boundary_.buffer(), x_, y_, t_, b.element, b.slice, w.cell_start,
        w.slot_element, w.slot_vertices, w.slot_cx, w.slot_cy, w.slot_ct, w.run_start, w.run_element, w.runs,
        b.element_slice_begin, b.slice_begin, b.slice_boundary, w.box_x0, w.box_y0, w.box_x1, w.box_y1, w.box_t,
        w.tangent_x, w.tangent_y, w.handle_px, w.handle_py, w.handle_qx, w.handle_qy, growth_, b.element_secondary,
        w.rpl_x, w.rpl_y, w.rpl_t, w.rpl_closest, w.rpl_contact, w.depth_x, w.depth_y);
    mirror_ = p.k_mirror != 0.0f;
    wall_mirror_ = Kernel(program, "wall_mirror_force");
    wall_mirror_.bind(grid_, p, world_, boundary_.count(), boundary_.buffer(), x_, y_, t_, b.element, w.cell_start,
                      w.slot_element, w.slot_vertices, w.slot_cx, w.slot_cy, w.slot_ct, w.run_start, w.run_element,
                      w.runs, b.seg_ax, b.seg_ay, b.seg_bx, b.seg_by,
                      opencl::container_index_info(topo_.container.index), b.container_index, w.mirror_x, w.mirror_y,
                      w.mirror_t, w.wall_inside, w.wall_d2, w.wall_qx, w.wall_qy);
    curve_tangents_ = Kernel(program, "curve_tangents");
    curve_tangents_.bind(world_, b.slice, b.slice_begin, b.slice_element, b.element_slice_begin, b.curve_prev,
                         b.curve_next, x_, y_, t_, w.tangent_x, w.tangent_y);
    curve_spline_tangents_ = Kernel(program, "curve_spline_tangents");
    curve_spline_tangents_.bind(b.tracks, b.track_vertex, b.track_chain, b.chain_begin, b.chain_slice, b.chain_offset,
                                b.chain_alias, b.chain_period, b.slice_begin, x_, y_, t_, w.spline_cp, w.spline_z,
                                w.tangent_x, w.tangent_y);
    slice_centroids_ = Kernel(program, "slice_centroids");
    slice_centroids_.bind(world_, b.slice_begin, x_, y_, w.slice_cx, w.slice_cy);
    forces_ = Kernel(program, "step_forces");
    breakdown_arg_ =
        forces_.bind(world_, p, x_, y_, t_, b.slice, b.slice_begin, b.slice_boundary, b.flags, b.rest_t, b.rest_dir_x,
                     b.rest_dir_y, b.target, b.spring_begin, b.spring_other, b.spring_class, rest_, b.tri_a, b.tri_b,
                     b.tri_c, b.tri_begin, b.tri_list, b.rest_copy_x, b.rest_copy_y, growth_, w.rpl_x, w.rpl_y, w.rpl_t,
                     w.rpl_closest, w.rpl_contact, w.depth_x, w.depth_y, b.target_x, b.target_y, b.target_t, b.seg_ax,
                     b.seg_ay, b.seg_bx, b.seg_by, opencl::container_index_info(topo_.container.index),
                     b.container_index, w.slice_cx, w.slice_cy, w.mirror_x, w.mirror_y, w.mirror_t, w.wall_inside,
                     w.wall_d2, w.wall_qx, w.wall_qy, fx_, fy_, ft_, closest_, contact_, breakdown_) -
        1;
    integrate_ = Kernel(program, "integrate");
    integrate_.bind(world_, p, fx_, fy_, ft_, vx_, vy_, vt_, x_, y_, t_);
    constraints_ = Kernel(program, "slice_constraints");
    constraints_.bind(world_, b.slice_begin, b.slice_element, b.element_slice_begin, t_);
    loop_ = Kernel(program, "loop_constraint");
    loop_.bind(world_, b.loop_end, b.loop_start, x_, y_);
    apply_containment_ = Kernel(program, "apply_containment");
    apply_containment_.bind(world_, b.seg_ax, b.seg_ay, b.seg_bx, b.seg_by,
                            opencl::container_index_info(topo_.container.index), b.container_index, x_, y_, vx_, vy_);
    propose_growth_ = Kernel(program, "propose_growth");
    propose_growth_.bind(world_, p, settling_since_ == 0 ? 1 : 0, secondary_since_ == 0 ? 1 : 0, b.slice_begin,
                         b.slice_element, b.element_secondary, contact_, closest_, b.rest_copy_x, b.rest_copy_y,
                         b.rest_copy_cx, b.rest_copy_cy, growth_, w.proposed);
    grow_ = Kernel(program, "grow_slices");
    grow_.bind(world_, p, b.slice_element, b.element_slice_begin, w.proposed, growth_, changed_);
    rest_lengths_ = Kernel(program, "update_rest_lengths");
    rest_lengths_.bind(world_, b.slice, b.spring_begin, b.spring_other, changed_, growth_, b.rest_copy_x, b.rest_copy_y,
                       b.rest_copy_t, b.rest_copy_cx, b.rest_copy_cy, rest_);
    statistics_ = Kernel(program, "slice_statistics");
    statistics_.bind(world_, b.slice_begin, closest_, contact_, changed_, x_, y_, t_, vx_, vy_, vt_, slice_gap_,
                     slice_overlap_, slice_outside_, slice_bad_);
  }

  // A device buffer holding `data` (read-write unless `flags` says otherwise).
  template <typename T>
  cl::Buffer upload(const std::vector<T>& data, const char* name) {
    return opencl::upload_buffer(context_, queue_, data, name);
  }

  cl::Buffer scratch(std::size_t bytes, const char* name) {
    return opencl::make_buffer(context_, CL_MEM_READ_WRITE, bytes, name);
  }

  // Reads are non-blocking except the last of a batch: the queue is in order, so one wait covers all.
  template <typename T>
  void read(const cl::Buffer& b, std::vector<T>& out, const char* name, bool wait = false) {
    if (out.empty()) return;
    cl::Event e;
    check(queue_.enqueueReadBuffer(b, wait ? CL_TRUE : CL_FALSE, 0, sizeof(T) * out.size(), out.data(), nullptr, &e),
          std::string("clEnqueueReadBuffer(") + name + ")");
    pending_.push_back({&times_.transfer, e, nullptr});
  }

  // Runs `kernel` on `items` work-items, its device time to count towards the phase `sink` and the
  // kernel's own total (kernel_times, pack --profile).
  void timed(double& sink, Kernel& kernel, std::int32_t items) {
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
  void settle_times() {
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

  // The repulsion kernel's work-items in the order of their vertices' grid cells (boundary_order.hpp):
  // on the device, or on the host from the positions read back (one transfer every 100 steps).
  void order_boundary_by_cell() {
    if (boundary_.on_device()) {
      for (const opencl::Launch& l : boundary_.launches()) timed(times_.grid, *l.kernel, l.items);
    } else {
      const std::size_t n = static_cast<std::size_t>(world_.vertices);
      std::vector<float> px(n), py(n), pt(n);
      read(x_, px, "x"), read(y_, py, "y"), read(t_, pt, "t", true);
      settle_times();
      PhaseStopwatch w(times_.transfer), own(host_reorder_);
      ++host_reorders_;
      boundary_.sort_on_host(queue_, px, py, pt);
    }
    boundary_ordered_ = true;
    boundary_ordered_at_ = iteration_;
  }

  // Centroids and cells on the device, the stable counting sort on the device or on the host (as
  // grid.cpp), then the per-slot copies the force kernels read.
  void build_grid() {
    timed(times_.grid, envelope_cells_, grid_.triangles);
    if (sort_ == GridSort::device) {
      for (const opencl::Launch& l : grid_sort_.launches()) timed(times_.grid, *l.kernel, l.items);
    } else {
      host_sort();
    }
    timed(times_.grid, grid_gather_, grid_.triangles);
    if (grid_.far_cells != 0) {
      timed(times_.grid, run_counts_, grid_.cells);
      for (const opencl::Launch& l : run_scan_.launches()) timed(times_.grid, *l.kernel, l.items);
      timed(times_.grid, grid_runs_, grid_.cells);
    }
    grid_built_ = true;
  }

  void host_sort() {
    read(scratch_.triangle_cell, cells_, "triangle_cell", true);
    settle_times();
    PhaseStopwatch w(times_.grid), own(host_sort_);
    ++host_sorts_;
    counting_sort(cells_, grid_.cells, cell_start_, sorted_);
    // The host vectors stay untouched until the next build, which first waits on this queue.
    check(queue_.enqueueWriteBuffer(scratch_.cell_start, CL_FALSE, 0, sizeof(std::int32_t) * cell_start_.size(),
                                    cell_start_.data()),
          "clEnqueueWriteBuffer(cell_start)");
    if (!sorted_.empty())
      check(queue_.enqueueWriteBuffer(scratch_.sorted, CL_FALSE, 0, sizeof(std::int32_t) * sorted_.size(),
                                      sorted_.data()),
            "clEnqueueWriteBuffer(sorted_triangles)");
  }

  // The overlap test's broadphase from this step's slice boxes: on the device, or on the host from the
  // boxes read back.
  void build_overlap_grid() {
    if (broadphase_.on_device()) {
      for (const opencl::Launch& l : broadphase_.launches()) timed(times_.forces, *l.kernel, l.items);
    } else {
      ScratchBuffers& w = scratch_;
      read(w.box_x0, boxes_.x0, "slice_box_x0"), read(w.box_y0, boxes_.y0, "slice_box_y0");
      read(w.box_x1, boxes_.x1, "slice_box_x1"), read(w.box_y1, boxes_.y1, "slice_box_y1");
      read(w.box_t, boxes_.t, "slice_t", true);
      settle_times();
      PhaseStopwatch watch(times_.forces), own(host_overlap_grid_);
      ++host_overlap_builds_;
      broadphase_.upload(queue_, topo_, boxes_);
    }
    broadphase_.bind(repulsion_force_, overlap_grid_arg_);
  }

  Topology topo_;
  DeviceInfo info_;
  std::uint64_t iteration_;
  std::uint64_t settling_since_;
  std::uint64_t secondary_since_;
  SimState marks_;  ///< holds the stall test's progress marks only (copy_progress_marks)
  int rebuild_;
  GridSort sort_;
  bool grid_built_ = false;
  bool boundary_ordered_ = false;
  std::uint64_t boundary_ordered_at_ = 0;
  WorldInfo world_{};
  GridInfo grid_{};
  std::size_t spring_count_ = 0;
  cl::Context context_;
  cl::CommandQueue queue_;
  TopologyBuffers topo_buf_;  ///< held here: clSetKernelArg does not retain a buffer
  ScratchBuffers scratch_;
  cl::Buffer x_, y_, t_, vx_, vy_, vt_, rest_, growth_;
  cl::Buffer fx_, fy_, ft_, closest_, contact_, changed_, breakdown_, slice_gap_, slice_overlap_, slice_outside_,
      slice_bad_;
  opencl::DeviceCountingSort grid_sort_;  ///< the collision grid's sort where the device builds it
  opencl::DeviceScan run_scan_;           ///< packs the far field's runs in cell order (grid_runs)
  Kernel envelope_cells_, grid_gather_, slot_positions_, run_counts_, grid_runs_, slice_boxes_, curve_tangents_,
      curve_spline_tangents_, repulsion_force_, wall_mirror_, slice_centroids_, forces_, integrate_, constraints_,
      loop_, apply_containment_, propose_growth_, grow_, rest_lengths_, statistics_;
  cl_uint breakdown_arg_ = 0;
  cl_uint overlap_grid_arg_ = 0;
  bool mirror_ = false;    ///< wall_mirror is on: wall_mirror_force runs before step_forces
  cl_int curve_mode_ = 0;  ///< ForceParams.motion_curve: the spline's tangents come from curve_spline_tangents
  SliceBoxes boxes_;       ///< read back for a host build of the broadphase
  opencl::OverlapBroadphase broadphase_;
  opencl::BoundaryOrder boundary_;  ///< the repulsion kernel's work order
  std::vector<std::int32_t> cells_, cell_start_, sorted_;
  struct Pending {
    double* sink;  // the phase's total
    cl::Event event;
    Kernel* kernel;  // the kernel launched, or null for a transfer
  };
  std::vector<Pending> pending_;
  std::vector<Kernel*> profiled_;  // every kernel timed so far, in the order of its first launch
  double host_overlap_grid_ = 0, host_sort_ = 0, host_reorder_ = 0;
  std::uint64_t host_overlap_builds_ = 0, host_sorts_ = 0, host_reorders_ = 0;
  PhaseTimes times_;
};

}  // namespace

std::unique_ptr<OpenclBackend> make_opencl_backend(const Topology& topology, SimState initial, const Params& params,
                                                   const DeviceChoice& choice, GridSort sort) {
  if (choice.reference) throw std::invalid_argument("make_opencl_backend: the choice is the reference solver");
  return std::make_unique<DeviceBackend>(topology, std::move(initial), params, choice.device, sort);
}

}  // namespace animpak
