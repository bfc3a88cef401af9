// The OpenCL backend (device_backend.hpp): construction, the state's buffers and the step, phase by
// phase in the reference's order (src/solver/reference/backend.cpp).
#include <limits>
#include <stdexcept>

#include "animpak/error.hpp"
#include "animpak/step_params.hpp"
#include "device_backend.hpp"

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

namespace opencl {
namespace {

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

std::vector<std::int32_t> boundary_vertices(const Topology& topo) {
  std::vector<std::int32_t> boundary;
  for (std::int32_t v = 0; v < topo.vertex_count(); ++v)
    if ((topo.flags[v] & vertex_boundary) != 0) boundary.push_back(v);
  return boundary;
}

}  // namespace

DeviceBackend::DeviceBackend(const Topology& topology, SimState initial, const Params& params, const DeviceInfo& info,
                             GridSort sort)
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
  std::vector<std::int32_t> boundary = boundary_vertices(topo_);
  world_ = world_info(topo_, static_cast<std::int32_t>(boundary.size()), alignment_);
  grid_ = with_grid_strides(grid_info(params, topo_.envelope_count()), alignment_);
  upload_state(initial);
  topo_buf_ = upload_topology(context_, queue_, topo_, world_);
  allocate_scratch();
  broadphase_ = OverlapBroadphase(context_, queue_, program, topo_, world_, scratch_, sort_ == GridSort::device);
  boundary_ = BoundaryOrder(context_, queue_, program, std::move(boundary), grid_, world_, positions_.buffer(),
                            sort_ == GridSort::device);
  const ForceParams p = step_params(params);
  curve_mode_ = p.motion_curve;
  const ArgValues values = argument_values(p);
  bind_grid_kernels(program, values);
  bind_step_kernels(program, values, p);
  check(queue_.finish(), "clFinish(upload)");
}

void DeviceBackend::stop_growth() {
  if (settling_since_ != 0) return;
  settling_since_ = iteration_;
  propose_growth_.set("growing", 0);
}

bool DeviceBackend::start_secondary_growth() {
  if (secondary_since_ != 0 || !topo_.has_secondary()) return false;
  secondary_since_ = iteration_;
  propose_growth_.set("hold_secondary", 0);
  return true;
}

void DeviceBackend::step() {
  if (iteration_ % static_cast<std::uint64_t>(rebuild_) == 0 || !grid_built_) build_grid();
  if (!boundary_ordered_ || iteration_ - boundary_ordered_at_ >= BoundaryOrder::interval()) order_boundary_by_cell();
  timed(times_.grid, slot_positions_, grid_.triangles);
  timed(times_.forces, slice_centroids_, world_.slices);
  timed(times_.forces, curve_tangents_kernel(), curve_tangents_items());
  timed(times_.forces, slice_boxes_, world_.slices);
  build_overlap_grid();
  timed(times_.forces, repulsion_force_, world_.boundaries);
  if (mirror_) timed(times_.forces, wall_mirror_, world_.boundaries);
  timed(times_.forces, forces_, world_.vertices);
  timed(times_.forces, contact_gap_, world_.vertices);
  timed(times_.integrate, integrate_, world_.vertices);
  timed(times_.constraints, constraints_, world_.slices);
  timed(times_.loop, loop_, world_.loops);
  timed(times_.constraints, apply_containment_, world_.vertices);
  timed(times_.growth, propose_growth_, world_.slices);
  timed(times_.growth, grow_, world_.slices);
  timed(times_.growth, rest_lengths_, world_.vertices);
  ++iteration_;
}

void DeviceBackend::force_phases() {
  slot_positions_.run(queue_, grid_.triangles);
  slice_centroids_.run(queue_, world_.slices);
  curve_tangents_kernel().run(queue_, curve_tangents_items());
  slice_boxes_.run(queue_, world_.slices);
  build_overlap_grid();
  repulsion_force_.run(queue_, world_.boundaries);
  if (mirror_) wall_mirror_.run(queue_, world_.boundaries);
  forces_.run(queue_, world_.vertices);
  contact_gap_.run(queue_, world_.vertices);
}

// The context and an in-order, profiling queue on the chosen device; returns the built program.
cl::Program DeviceBackend::create_queue() {
  const cl::Device device = device_for(info_);
  cl_int err = CL_SUCCESS;
  context_ = cl::Context(device, nullptr, nullptr, nullptr, &err);
  check(err, "clCreateContext(" + info_.name + ")");
  queue_ = cl::CommandQueue(context_, device, CL_QUEUE_PROFILING_ENABLE, &err);
  check(err, "clCreateCommandQueue(" + info_.name + ")");
  alignment_ = plane_alignment(device);
  return build_program(context_, device);
}

// Everything that moves (SimState) and the per-vertex and per-slice results the host reads.
void DeviceBackend::upload_state(const SimState& initial) {
  const auto upload = [&](const auto& data, const char* name) { return upload_buffer(context_, queue_, data, name); };
  const auto scratch = [&](std::size_t bytes, const char* name) {
    return make_buffer(context_, CL_MEM_READ_WRITE, bytes, name);
  };
  const auto xyz = [&](const std::vector<float>& x, const std::vector<float>& y, const std::vector<float>& t,
                       const char* name) {
    PlaneBuffer b(context_, CL_MEM_READ_WRITE, 3, world_.vertex_stride, name);
    b.write(queue_, AP_X, x), b.write(queue_, AP_Y, y), b.write(queue_, AP_T, t);
    return b;
  };
  positions_ = xyz(initial.x, initial.y, initial.t, "positions");
  velocities_ = xyz(initial.vx, initial.vy, initial.vt, "velocities");
  rest_ = upload(initial.spring_rest, "spring_rest");
  growth_ = upload(initial.growth, "growth");
  spring_count_ = initial.spring_rest.size();
  const std::int32_t n = world_.vertices, slices = world_.slices;
  // Before the first step the statistics see what the reference starts from: no gap, no overlap.
  closest_ = upload(std::vector<float>(n, std::numeric_limits<float>::infinity()), "closest");
  contact_ = upload(std::vector<std::uint8_t>(n, 0), "contact");
  changed_ = upload(std::vector<std::uint8_t>(slices, 0), "growth_changed");
  const std::size_t fs = sizeof(float) * slices, is = sizeof(std::int32_t) * slices;
  forces_buf_ = PlaneBuffer(context_, CL_MEM_READ_WRITE, 3, world_.vertex_stride, "forces");
  breakdown_ = scratch(1, "breakdown (unused)");
  slice_gap_ = scratch(fs, "slice_gap");
  slice_overlap_ = scratch(is, "slice_overlap");
  slice_outside_ = scratch(is, "slice_outside");
  slice_bad_ = scratch(is, "slice_bad");
}

// The device scratch (device_buffers.cpp) and the host arrays the host sort and the broadphase fill.
void DeviceBackend::allocate_scratch() {
  scratch_ = opencl::allocate_scratch(context_, world_, grid_);
  cells_.resize(grid_.triangles);
  cell_start_.resize(static_cast<std::size_t>(grid_.cells) + 1);
  sorted_.resize(grid_.triangles);
  const std::size_t slices = static_cast<std::size_t>(world_.slices);
  boxes_.x0.resize(slices), boxes_.y0.resize(slices), boxes_.x1.resize(slices), boxes_.y1.resize(slices);
  boxes_.t.resize(slices);
}

}  // namespace opencl

std::unique_ptr<OpenclBackend> make_opencl_backend(const Topology& topology, SimState initial, const Params& params,
                                                   const DeviceChoice& choice, GridSort sort) {
  if (choice.reference) throw std::invalid_argument("make_opencl_backend: the choice is the reference solver");
  return std::make_unique<opencl::DeviceBackend>(topology, std::move(initial), params, choice.device, sort);
}

}  // namespace animpak
