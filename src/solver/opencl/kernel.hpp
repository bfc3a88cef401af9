// A named kernel: arguments bound by name through the parameter table (kernel_args.hpp), launches at
// the one fixed local size with the global size padded (the kernels guard `if (i >= n) return;`), each
// launch's event kept for timing.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "cl_host.hpp"
#include "kernel_args.hpp"

namespace animpak::opencl {

class Kernel {
 public:
  Kernel() = default;
  /// `label`, when given, names it in the profile (pack --profile) in place of its OpenCL name: one
  /// kernel bound twice, to different buffers, then shows as two rows.
  Kernel(const cl::Program& program, const char* name, const char* label = nullptr)
      : name_(label != nullptr ? label : name), parameters_(&kernel_parameters(name)) {
    cl_int err = CL_SUCCESS;
    kernel_ = cl::Kernel(program, name, &err);
    check(err, std::string("clCreateKernel(") + name + ")");
  }

  /// Sets every argument from the value of its parameter's name in `values` (the table's row);
  /// std::invalid_argument naming the kernel and parameter when `values` has none.
  void bind(const ArgValues& values) {
    for (std::size_t i = 0; i < parameters_->names.size(); ++i) {
      const std::string_view name = parameters_->names[i];
      const Arg* arg = values.find(name);
      if (arg == nullptr)
        throw std::invalid_argument("kernel " + std::string(parameters_->kernel) + ": no value for its argument '" +
                                    std::string(name) + "' where it is bound; add one of that name");
      arg->apply(kernel_, static_cast<cl_uint>(i), describe(name));
    }
  }

  /// Sets the argument `name` (a parameter of the table's row) to `value`.
  template <typename T>
  void set(std::string_view name, const T& value) {
    Arg(name, value).apply(kernel_, index(name), describe(name));
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
  cl_uint index(std::string_view name) const {
    for (std::size_t i = 0; i < parameters_->names.size(); ++i)
      if (parameters_->names[i] == name) return static_cast<cl_uint>(i);
    throw std::invalid_argument("kernel " + std::string(parameters_->kernel) + " has no argument '" +
                                std::string(name) + "' (src/solver/opencl/kernel_args.cpp)");
  }
  std::string describe(std::string_view name) const { return name_ + ", " + std::string(name); }

  std::string name_;
  const KernelParameters* parameters_ = nullptr;
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
