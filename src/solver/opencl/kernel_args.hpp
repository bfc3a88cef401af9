// The host–kernel interface in one table (docs/architecture.md, "OpenCL host conventions"): every
// kernel of the program with its parameters' names in their order. A kernel's arguments are bound by
// those names (Kernel::bind, Kernel::set) from an ArgValues, the buffers and values a binding site
// offers under the same names. tests/equivalence/test_kernel_args.cpp builds the program with
// -cl-kernel-arg-info and checks every kernel's argument names and count against this table, so a
// parameter renamed, reordered or added without its row fails there, not at run time.
#pragma once

#include <cstddef>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "cl_host.hpp"

namespace animpak::opencl {

struct KernelParameters {
  std::string_view kernel;
  std::vector<std::string_view> names;  ///< in the kernel's parameter order
};

/// Every kernel of program_source(), in the program's order.
const std::vector<KernelParameters>& kernel_parameters();

/// The row of `kernel`; std::invalid_argument naming the table when it has none.
const KernelParameters& kernel_parameters(std::string_view kernel);

/// One named argument value: a buffer, or a value passed by copy (a struct of shared_types.h, an int).
class Arg {
 public:
  Arg(std::string_view name, const cl::Buffer& buffer) : name_(name), buffer_(buffer), is_buffer_(true) {}
  template <typename T>
  requires(!std::is_same_v<T, cl::Buffer> && std::is_trivially_copyable_v<T>) Arg(std::string_view name, const T& value)
      : name_(name), bytes_(sizeof(T)) {
    std::memcpy(bytes_.data(), &value, sizeof(T));
  }

  const std::string& name() const { return name_; }
  /// clSetKernelArg(kernel, index, …) with this value; `what` names the kernel and argument in errors.
  void apply(const cl::Kernel& kernel, cl_uint index, const std::string& what) const;

 private:
  std::string name_;
  cl::Buffer buffer_;  ///< held: clSetKernelArg does not retain a buffer
  std::vector<unsigned char> bytes_;
  bool is_buffer_ = false;
};

/// The values one binding site offers, by name; a later value of a name replaces the earlier one.
class ArgValues {
 public:
  ArgValues() = default;
  ArgValues(std::initializer_list<Arg> args) {
    for (const Arg& a : args) add(a);
  }
  void add(const Arg& arg);
  /// The value of `name`, or null.
  const Arg* find(std::string_view name) const;

 private:
  std::vector<Arg> args_;
};

}  // namespace animpak::opencl
