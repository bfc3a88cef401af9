// A grouped buffer (kernels/shared_types.h, "Grouped buffers"; docs/architecture.md, "Layout shared by
// host and kernels"): one device buffer holding the planes of a group, all of one 4-byte type, plane k
// from element k * stride on. The stride is padded to the device's base-address alignment, so every
// plane starts as aligned as a buffer of its own. Kernels only ever get the whole buffer and form their
// planes from the stride; the host reads a plane at its offset and writes the whole buffer (write).
// There are no sub-buffers: a tool that checks initialization or races per buffer (Oclgrind) sees every
// access to a group as one buffer's, and no driver has to keep a parent buffer and its sub-buffers
// coherent.
#pragma once

#include <cstdint>
#include <cstring>
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

  /// Puts `data` (4-byte elements, at most a stride) in plane k of the host's copy of the group and
  /// writes the whole copy, from the buffer's start (`wait`: blocking; otherwise the copy must stay
  /// untouched until the queue has run the write, as the next write to this group waits on it). The
  /// other planes get what the host last put there, zeros at first: a group the kernels also write
  /// takes host writes only where the kernels rewrite its other planes after (grid_index's cell
  /// ranges). One write of the whole buffer is what Oclgrind's initialization check follows: it
  /// replaces its record of a buffer with the range of each host write, counted from the buffer's
  /// start (docs/testing.md, "On Oclgrind").
  template <typename T>
  void write(const cl::CommandQueue& queue, int k, const std::vector<T>& data, bool wait = true) {
    static_assert(sizeof(T) == 4);
    const std::size_t at = offset(k, data.size()) / 4;
    if (host_.empty()) host_.assign(static_cast<std::size_t>(planes_) * static_cast<std::size_t>(stride_), 0);
    if (!data.empty()) std::memcpy(host_.data() + at, data.data(), 4 * data.size());
    check(queue.enqueueWriteBuffer(buffer_, wait ? CL_TRUE : CL_FALSE, 0, 4 * host_.size(), host_.data()),
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

  cl::Buffer buffer_;
  std::string name_;
  int planes_ = 0;
  std::int32_t stride_ = 0;
  std::vector<std::uint32_t> host_;  ///< the host's copy, planes_ * stride_ elements once written
};

}  // namespace animpak::opencl
