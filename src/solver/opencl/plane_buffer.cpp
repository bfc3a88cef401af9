// Grouped buffers (plane_buffer.hpp).
#include "plane_buffer.hpp"

#include <algorithm>
#include <stdexcept>

namespace animpak::opencl {

std::int32_t plane_alignment(const cl::Device& device) {
  cl_uint bits = 0;
  check(device.getInfo(CL_DEVICE_MEM_BASE_ADDR_ALIGN, &bits), "clGetDeviceInfo(CL_DEVICE_MEM_BASE_ADDR_ALIGN)");
  return std::max<std::int32_t>(1, static_cast<std::int32_t>(bits / 8 / 4));
}

std::int32_t plane_stride(std::int64_t length, std::int32_t alignment) {
  const std::int64_t blocks = std::max<std::int64_t>(1, (length + alignment - 1) / alignment);
  return static_cast<std::int32_t>(blocks * alignment);
}

PlaneBuffer::PlaneBuffer(const cl::Context& context, cl_mem_flags flags, int planes, std::int32_t stride,
                         const std::string& name)
    : name_(name), planes_(planes), stride_(stride) {
  buffer_ = make_buffer(context, flags, std::size_t{4} * static_cast<std::size_t>(stride) * planes, name);
}

std::size_t PlaneBuffer::offset(int k, std::size_t length) const {
  if (k < 0 || k >= planes_ || length > static_cast<std::size_t>(stride_))
    throw std::out_of_range(name_ + ": plane " + std::to_string(k) + " of " + std::to_string(planes_) + " holds " +
                            std::to_string(stride_) + " elements, not " + std::to_string(length));
  return std::size_t{4} * static_cast<std::size_t>(stride_) * static_cast<std::size_t>(k);
}

}  // namespace animpak::opencl
