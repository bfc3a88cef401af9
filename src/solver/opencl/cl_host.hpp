// The thin layer over CL/opencl.hpp (docs/architecture.md, "OpenCL host conventions"): the bindings are used
// without their exceptions, every returned cl_int goes through check(), which throws OpenclError with
// the call's text and the error's name.
#pragma once

#define CL_HPP_TARGET_OPENCL_VERSION 120
#define CL_HPP_MINIMUM_OPENCL_VERSION 120
#include <CL/opencl.hpp>

#include <string>
#include <vector>

#include "animpak/opencl.hpp"
#include "shared_types.h"

namespace animpak::opencl {

/// Throws OpenclError(call, err) unless err is CL_SUCCESS.
void check(cl_int err, const std::string& call);

/// A buffer of `bytes` (at least 1: OpenCL refuses empty buffers) named in every error about it.
cl::Buffer make_buffer(const cl::Context& context, cl_mem_flags flags, std::size_t bytes, const std::string& name);

struct FoundDevice {
  cl::Device device;
  DeviceInfo info;
};

/// Every device of every platform; empty (not an error) when the ICD loader finds no platform.
std::vector<FoundDevice> find_devices();

/// Whether `d` simulates or emulates a device (Oclgrind, an FPGA emulator) by its names and vendor.
bool is_simulator(const DeviceInfo& d);

/// The default rule of choose_device("") over `devices`, in their order.
DeviceChoice default_device(const std::vector<DeviceInfo>& devices);

/// The cl::Device described by `info` (same platform and device name). OpenclError when gone.
cl::Device device_for(const DeviceInfo& info);

/// The options for one device: build_options, and on a CPU device (not also a GPU) the near block in 16 lanes
/// (AP_NEAR_LANES, kernels/repulsion.cl; docs/architecture.md, "The near block in lanes").
std::string device_build_options(const cl::Device& device);

/// Builds program_source() for `device`; OpenclError carrying the device name and full log on failure.
cl::Program build_program(const cl::Context& context, const cl::Device& device);

/// The grid description for `triangles` envelope triangles (cells per axis as reference::grid_cells_per_axis).
GridInfo grid_info(const Params& params, std::int32_t triangles);

/// The container index's sizes and offsets for the kernels (its lists go in one int buffer).
ContainerIndexInfo container_index_info(const ContainerIndex& index);

}  // namespace animpak::opencl
