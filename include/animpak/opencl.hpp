// The OpenCL backend (docs/architecture.md, "OpenCL host conventions"): devices found and chosen by name, the
// kernels of kernels/*.cl built for them, and a Backend that runs the same step as the reference with
// the state kept on the device. Every failed OpenCL call throws OpenclError.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "animpak/simulation.hpp"
#include "animpak/solver/grids.hpp"
#include "animpak/solver/step.hpp"

namespace animpak {

/// A failed OpenCL call: which call, its error name (CL_OUT_OF_RESOURCES, ...) and, for a program
/// build, the device and its full build log. what() holds all of it.
class OpenclError : public std::runtime_error {
 public:
  OpenclError(std::string call, int code, std::string detail = {}, std::string build_log = {});
  const std::string& call() const { return call_; }
  int code() const { return code_; }
  const char* code_name() const;
  const std::string& build_log() const { return build_log_; }

 private:
  std::string call_;
  int code_;
  std::string build_log_;
};

/// The symbolic name of an OpenCL error code ("CL_INVALID_VALUE"), or "unknown OpenCL error".
const char* opencl_error_name(int code);

/// One OpenCL device as its platform reports it.
struct DeviceInfo {
  std::string platform;          ///< platform name ("Portable Computing Language", "NVIDIA CUDA")
  std::string platform_version;  ///< e.g. "OpenCL 3.0 PoCL 3.1 ..."
  std::string name;              ///< device name
  std::string vendor;            ///< device vendor
  std::string driver;            ///< driver version
  std::string version;           ///< device OpenCL version
  bool gpu = false;
  bool simulator = false;  ///< simulates or emulates a device (Oclgrind): correct, but far too slow to pack on
  std::uint32_t compute_units = 0;
  std::uint64_t global_memory = 0;   ///< bytes
  std::uint64_t max_allocation = 0;  ///< bytes, largest single buffer
};

/// Every device of every platform, in platform order; empty when no platform is installed.
std::vector<DeviceInfo> list_devices();

struct KernelBuild {
  bool ok = false;
  std::string log;  ///< the compiler's build log (may be empty on success), or the error
};

/// Builds animpak's kernels for `device`; never throws for a failed build, reports it instead.
KernelBuild try_build_kernels(const DeviceInfo& device);

/// The device a simulation runs on: an OpenCL device, or the scalar reference.
struct DeviceChoice {
  bool reference = true;
  bool explicit_request = false;  ///< chosen by --device rather than by the default rule
  DeviceInfo device;              ///< when !reference
  std::string reason;             ///< one line: which device and why
};

/// `request` empty: the default rule (first GPU, else PoCL, else the reference; never a simulator,
/// which only a request by name chooses). "reference": the
/// scalar reference. Anything else: the one device whose platform, device name or vendor contains
/// `request` (case-insensitive). UsageError when nothing or more than one device matches.
DeviceChoice choose_device(std::string_view request);

/// Where the two grids are built: the collision grid's stable counting sort and the overlap test's
/// broadphase. `automatic`: on the device for GPUs (a step then never waits for the host: reading the
/// cell ids or slice boxes back stops the queue), on the host for CPU devices such as PoCL (no atomics,
/// and the host's single pass is cheap). Both give the same forces, bit for bit.
enum class GridSort { automatic, host, device };

/// "auto", "host" or "device"; UsageError naming `option` for anything else.
GridSort parse_grid_sort(std::string_view text, std::string_view option);
const char* grid_sort_name(GridSort sort);

/// The OpenCL backend, with two entry points that compare single phases with the reference: `animpak
/// validate` and the equivalence tests use them.
class OpenclBackend : public Backend {
 public:
  /// Builds the grid from the current state and computes Eq. 7 with every force apart, without
  /// advancing the state (as reference::build_collision_grid then reference::step_forces); the grid is
  /// left rebuilt.
  virtual StepForces evaluate_forces(ForceBreakdown* out) = 0;
  /// The collision grid built on the device from the current state.
  virtual CollisionGrid build_and_read_grid() = 0;
  virtual const DeviceInfo& device() const = 0;
  /// Where this backend builds the grids: host or device, never automatic.
  virtual GridSort grid_sort() const = 0;
  /// The overlap test's broadphase as the repulsion kernel reads it, built from the current state (its
  /// tangents and slice boxes first), on the host or the device as grid_sort() says.
  virtual OverlapGrid build_and_read_overlap_grid() = 0;
  /// Room for `entries` entries in a device-built broadphase's lists from now on. A build that outgrows
  /// its room drops the grid for that step (every query tries every element: the same forces, slower)
  /// and the room grows at the next statistics; the tests shrink it to reach that path. No effect on a
  /// host build.
  virtual void set_overlap_room(std::size_t entries) = 0;
  /// The repulsion kernel's work order refreshed from the current state (on the host or the device as
  /// grid_sort() says) and read back: the boundary vertices sorted by grid cell.
  virtual std::vector<std::int32_t> refresh_and_read_boundary_order() = 0;
};

/// Copies topology and state to `choice.device` and builds the kernels. OpenclError on any failure
/// (the build log included); std::invalid_argument for a reference choice or a topology the kernels
/// cannot run (a vertex in two loop pairs, slices not covering the vertices in order).
std::unique_ptr<OpenclBackend> make_opencl_backend(const Topology& topology, SimState initial, const Params& params,
                                                   const DeviceChoice& choice, GridSort sort = GridSort::automatic);

}  // namespace animpak
