// A named kernel: arguments bound once by position, launches at the one fixed local size with the
// global size padded (the kernels guard `if (i >= n) return;`), each launch's event kept for timing.
#pragma once

#include <cstdint>
#include <string>

#include "cl_host.hpp"

namespace animpak::opencl {

class Kernel {
 public:
  Kernel() = default;
  /// `label`, when given, names it in the profile (pack --profile) in place of its OpenCL name: one
  /// kernel bound twice, to different buffers, then shows as two rows.
  Kernel(const cl::Program& program, const char* name, const char* label = nullptr)
      : name_(label != nullptr ? label : name) {
    cl_int err = CL_SUCCESS;
    kernel_ = cl::Kernel(program, name, &err);
    check(err, std::string("clCreateKernel(") + name + ")");
  }

  /// Sets arguments 0, 1, ... in order; returns how many were set.
  template <typename... Args>
  cl_uint bind(const Args&... args) {
    cl_uint index = 0;
    (set(index++, args), ...);
    return index;
  }

  template <typename T>
  void set(cl_uint index, const T& value) {
    check(kernel_.setArg(index, value), "clSetKernelArg(" + name_ + ", " + std::to_string(index) + ")");
  }

  /// Enqueues `items` work-items (nothing for 0) and returns the launch's event.
  cl::Event run(const cl::CommandQueue& queue, std::int32_t items) {
    cl::Event event;
    if (items <= 0) return event;
    const std::size_t global = (static_cast<std::size_t>(items) + AP_LOCAL_SIZE - 1) / AP_LOCAL_SIZE * AP_LOCAL_SIZE;
    check(queue.enqueueNDRangeKernel(kernel_, cl::NullRange, cl::NDRange(global), cl::NDRange(AP_LOCAL_SIZE), nullptr,
                                     &event),
          "clEnqueueNDRangeKernel(" + name_ + ")");
    return event;
  }

  const std::string& name() const { return name_; }
  /// Device time of the launches timed so far (OpenclBackend::settle_times) and how many there were.
  void add_time(double seconds) { seconds_ += seconds, ++launches_; }
  double seconds() const { return seconds_; }
  std::uint64_t launches() const { return launches_; }
  /// The phase of PhaseTimes its time counts towards (null until its first timed launch).
  const char* phase() const { return phase_; }
  void set_phase(const char* phase) { phase_ = phase; }

 private:
  std::string name_;
  cl::Kernel kernel_;
  double seconds_ = 0.0;
  std::uint64_t launches_ = 0;
  const char* phase_ = nullptr;
};

/// One launch of a fixed sequence (a device build of a grid): the kernel and its work-items.
struct Launch {
  Kernel* kernel;
  std::int32_t items;
};

}  // namespace animpak::opencl
