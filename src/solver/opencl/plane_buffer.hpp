// A grouped buffer (kernels/shared_types.h, "Grouped buffers"; docs/architecture.md, "Layout shared by
// host and kernels"): one device buffer holding the planes of a group, all of one 4-byte type, plane k
// from element k * stride on. The stride is padded to the device's base-address alignment, so each plane
// (or a run of planes) is also a sub-buffer: a kernel that reads a single plane binds that view and
// never learns the group's layout.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cl_host.hpp"

namespace animpak::opencl {

/// Elements of 4 bytes per CL_DEVICE_MEM_BASE_ADDR_ALIGN of `device` (at least 1): every stride is a
/// multiple of it.
std::int32_t plane_alignment(const cl::Device& device);

/// The smallest multiple of `alignment` that holds `length` elements (at least one alignment).
std::int32_t plane_stride(std::int64_t length, std::int32_t alignment);

class PlaneBuffer {
 public:
  PlaneBuffer() = default;
  /// `planes` planes of `stride` elements (4 bytes each) in one buffer named `name` in errors.
  PlaneBuffer(const cl::Context& context, cl_mem_flags flags, int planes, std::int32_t stride, const std::string& name);

  const cl::Buffer& buffer() const { return buffer_; }
  std::int32_t stride() const { return stride_; }
  /// Planes first … first + count - 1 as one sub-buffer (each single plane's is made once).
  cl::Buffer view(int first, int count = 1) const;

  /// Writes `data` (4-byte elements, at most a stride) to plane k, blocking.
  template <typename T>
  void write(const cl::CommandQueue& queue, int k, const std::vector<T>& data) const {
    static_assert(sizeof(T) == 4);
    if (data.empty()) return;
    check(queue.enqueueWriteBuffer(buffer_, CL_TRUE, offset(k, data.size()), 4 * data.size(), data.data()),
          "clEnqueueWriteBuffer(" + name_ + " plane " + std::to_string(k) + ")");
  }
  /// Enqueues the read of the first out.size() elements of plane k (`wait`: blocking); the read's event.
  template <typename T>
  cl::Event read(const cl::CommandQueue& queue, int k, std::vector<T>& out, bool wait) const {
    static_assert(sizeof(T) == 4);
    cl::Event e;
    check(queue.enqueueReadBuffer(buffer_, wait ? CL_TRUE : CL_FALSE, offset(k, out.size()), 4 * out.size(), out.data(),
                                  nullptr, &e),
          "clEnqueueReadBuffer(" + name_ + " plane " + std::to_string(k) + ")");
    return e;
  }

 private:
  std::size_t offset(int k, std::size_t length) const;
  cl::Buffer make_view(int first, int planes) const;

  cl::Buffer buffer_;
  std::string name_;
  cl_mem_flags flags_ = 0;
  int planes_ = 0;
  std::int32_t stride_ = 0;
  std::vector<cl::Buffer> views_;  ///< one per plane
};

}  // namespace animpak::opencl
