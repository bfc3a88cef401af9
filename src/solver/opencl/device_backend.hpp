// The OpenCL backend: the reference backend's step (src/solver/reference/backend.cpp) with the state
// on the device, in four files by concern:
//   opencl_backend.cpp   construction, the state's buffers and the step in phase order
//   step_kernels.cpp     the kernels and the values their arguments are bound from, by name
//                        (kernel_args.hpp's table: docs/architecture.md, "OpenCL host conventions")
//   grid_schedule.cpp    the grids, built on the device (GPUs: a step then never waits for the host) or
//                        on the host (CPU devices), and the repulsion kernel's work order by cell
//   readback.cpp         statistics, the state, forces and grids read back, timing
// The topology and scratch buffers are made in device_buffers.cpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "animpak/opencl.hpp"
#include "boundary_order.hpp"
#include "device_buffers.hpp"
#include "device_sort.hpp"
#include "kernel.hpp"
#include "overlap_broadphase.hpp"

namespace animpak::opencl {

class DeviceBackend final : public OpenclBackend {
 public:
  DeviceBackend(const Topology& topology, SimState initial, const Params& params, const DeviceInfo& info,
                GridSort sort);

  std::string name() const override { return info_.name; }
  const DeviceInfo& device() const override { return info_; }
  GridSort grid_sort() const override { return sort_; }
  void finish() override { settle_times(); }
  void set_progress_mark(const SimState& marks) override { copy_progress_marks(marks, marks_); }
  void stop_growth() override;
  bool start_secondary_growth() override;
  const PhaseTimes& times() const override { return times_; }
  std::vector<KernelTime> kernel_times() const override;
  void step() override;
  StepStatistics statistics() override;
  SimState state() override;
  StepForces evaluate_forces(ForceBreakdown* out) override;
  CollisionGrid build_and_read_grid() override;
  OverlapGrid build_and_read_overlap_grid() override;
  void set_overlap_room(std::size_t entries) override { broadphase_.set_capacity(entries); }
  std::vector<std::int32_t> refresh_and_read_boundary_order() override;

 private:
  // opencl_backend.cpp
  cl::Program create_queue();
  void upload_state(const SimState& initial);
  void allocate_scratch();
  void force_phases();  ///< the step's force phases, untimed (evaluate_forces)

  // step_kernels.cpp
  ArgValues argument_values(const ForceParams& p) const;
  void bind_grid_kernels(const cl::Program& program, const ArgValues& values);
  void bind_step_kernels(const cl::Program& program, const ArgValues& values, const ForceParams& p);
  Kernel& curve_tangents_kernel();
  std::int32_t curve_tangents_items() const;

  // grid_schedule.cpp
  void order_boundary_by_cell();
  void build_grid();
  void host_sort();
  void build_overlap_grid();

  // readback.cpp
  template <typename T>
  void read(const cl::Buffer& b, std::vector<T>& out, const char* name, bool wait = false);
  template <typename T>
  void read(const PlaneBuffer& b, int plane, std::vector<T>& out, bool wait = false);
  void timed(double& sink, Kernel& kernel, std::int32_t items);
  void settle_times();

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
  std::int32_t alignment_ = 1;  ///< plane_alignment of the device
  std::size_t spring_count_ = 0;
  cl::Context context_;
  cl::CommandQueue queue_;
  // The buffers are held here and in the ArgValues they are bound from: clSetKernelArg does not retain one.
  TopologyBuffers topo_buf_;
  ScratchBuffers scratch_;
  PlaneBuffer positions_, velocities_, forces_buf_;
  cl::Buffer rest_, growth_;
  cl::Buffer closest_, contact_, changed_, breakdown_, slice_gap_, slice_overlap_, slice_outside_, slice_bad_;
  DeviceCountingSort grid_sort_;  ///< the collision grid's sort where the device builds it
  DeviceScan run_scan_;           ///< packs the far field's runs in cell order (grid_runs)
  Kernel envelope_cells_, grid_gather_, slot_positions_, run_counts_, grid_runs_, slice_boxes_, curve_tangents_,
      curve_spline_tangents_, repulsion_force_, wall_mirror_, slice_centroids_, forces_, contact_gap_, integrate_,
      constraints_, loop_, apply_containment_, propose_growth_, grow_, rest_lengths_, statistics_;
  bool mirror_ = false;    ///< wall_mirror is on: wall_mirror_force runs before step_forces
  cl_int curve_mode_ = 0;  ///< ForceParams.motion_curve: the spline's tangents come from curve_spline_tangents
  SliceBoxes boxes_;       ///< read back for a host build of the broadphase
  OverlapBroadphase broadphase_;
  BoundaryOrder boundary_;  ///< the repulsion kernel's work order
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

// Reads are non-blocking except the last of a batch: the queue is in order, so one wait covers all.
template <typename T>
void DeviceBackend::read(const cl::Buffer& b, std::vector<T>& out, const char* name, bool wait) {
  if (out.empty()) return;
  cl::Event e;
  check(queue_.enqueueReadBuffer(b, wait ? CL_TRUE : CL_FALSE, 0, sizeof(T) * out.size(), out.data(), nullptr, &e),
        std::string("clEnqueueReadBuffer(") + name + ")");
  pending_.push_back({&times_.transfer, e, nullptr});
}

template <typename T>
void DeviceBackend::read(const PlaneBuffer& b, int plane, std::vector<T>& out, bool wait) {
  if (out.empty()) return;
  pending_.push_back({&times_.transfer, b.read(queue_, plane, out, wait), nullptr});
}

}  // namespace animpak::opencl
