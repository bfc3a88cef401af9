// OpenCL error codes as names, with the call that failed in release builds too, as an
// exception rather than an exit (docs/architecture.md, "OpenCL host conventions").
#include "cl_host.hpp"

namespace animpak {
namespace {

std::string describe(const std::string& call, int code, const std::string& detail, const std::string& log) {
  std::string s = call + " failed: " + opencl_error_name(code);
  if (!detail.empty()) s += " (" + detail + ")";
  if (!log.empty()) s += "\nbuild log:\n" + log;
  return s;
}

}  // namespace

OpenclError::OpenclError(std::string call, int code, std::string detail, std::string build_log)
    : std::runtime_error(describe(call, code, detail, build_log)),
      call_(std::move(call)),
      code_(code),
      build_log_(std::move(build_log)) {}

const char* OpenclError::code_name() const { return opencl_error_name(code_); }

const char* opencl_error_name(int code) {
  switch (code) {
#define AP_CL_ERROR(name) \
  case name:              \
    return #name;
    AP_CL_ERROR(CL_SUCCESS)
    AP_CL_ERROR(CL_DEVICE_NOT_FOUND)
    AP_CL_ERROR(CL_DEVICE_NOT_AVAILABLE)
    AP_CL_ERROR(CL_COMPILER_NOT_AVAILABLE)
    AP_CL_ERROR(CL_MEM_OBJECT_ALLOCATION_FAILURE)
    AP_CL_ERROR(CL_OUT_OF_RESOURCES)
    AP_CL_ERROR(CL_OUT_OF_HOST_MEMORY)
    AP_CL_ERROR(CL_PROFILING_INFO_NOT_AVAILABLE)
    AP_CL_ERROR(CL_MEM_COPY_OVERLAP)
    AP_CL_ERROR(CL_IMAGE_FORMAT_MISMATCH)
    AP_CL_ERROR(CL_IMAGE_FORMAT_NOT_SUPPORTED)
    AP_CL_ERROR(CL_BUILD_PROGRAM_FAILURE)
    AP_CL_ERROR(CL_MAP_FAILURE)
    AP_CL_ERROR(CL_MISALIGNED_SUB_BUFFER_OFFSET)
    AP_CL_ERROR(CL_EXEC_STATUS_ERROR_FOR_EVENTS_IN_WAIT_LIST)
    AP_CL_ERROR(CL_COMPILE_PROGRAM_FAILURE)
    AP_CL_ERROR(CL_LINKER_NOT_AVAILABLE)
    AP_CL_ERROR(CL_LINK_PROGRAM_FAILURE)
    AP_CL_ERROR(CL_DEVICE_PARTITION_FAILED)
    AP_CL_ERROR(CL_KERNEL_ARG_INFO_NOT_AVAILABLE)
    AP_CL_ERROR(CL_INVALID_VALUE)
    AP_CL_ERROR(CL_INVALID_DEVICE_TYPE)
    AP_CL_ERROR(CL_INVALID_PLATFORM)
    AP_CL_ERROR(CL_INVALID_DEVICE)
    AP_CL_ERROR(CL_INVALID_CONTEXT)
    AP_CL_ERROR(CL_INVALID_QUEUE_PROPERTIES)
    AP_CL_ERROR(CL_INVALID_COMMAND_QUEUE)
    AP_CL_ERROR(CL_INVALID_HOST_PTR)
    AP_CL_ERROR(CL_INVALID_MEM_OBJECT)
    AP_CL_ERROR(CL_INVALID_IMAGE_FORMAT_DESCRIPTOR)
    AP_CL_ERROR(CL_INVALID_IMAGE_SIZE)
    AP_CL_ERROR(CL_INVALID_SAMPLER)
    AP_CL_ERROR(CL_INVALID_BINARY)
    AP_CL_ERROR(CL_INVALID_BUILD_OPTIONS)
    AP_CL_ERROR(CL_INVALID_PROGRAM)
    AP_CL_ERROR(CL_INVALID_PROGRAM_EXECUTABLE)
    AP_CL_ERROR(CL_INVALID_KERNEL_NAME)
    AP_CL_ERROR(CL_INVALID_KERNEL_DEFINITION)
    AP_CL_ERROR(CL_INVALID_KERNEL)
    AP_CL_ERROR(CL_INVALID_ARG_INDEX)
    AP_CL_ERROR(CL_INVALID_ARG_VALUE)
    AP_CL_ERROR(CL_INVALID_ARG_SIZE)
    AP_CL_ERROR(CL_INVALID_KERNEL_ARGS)
    AP_CL_ERROR(CL_INVALID_WORK_DIMENSION)
    AP_CL_ERROR(CL_INVALID_WORK_GROUP_SIZE)
    AP_CL_ERROR(CL_INVALID_WORK_ITEM_SIZE)
    AP_CL_ERROR(CL_INVALID_GLOBAL_OFFSET)
    AP_CL_ERROR(CL_INVALID_EVENT_WAIT_LIST)
    AP_CL_ERROR(CL_INVALID_EVENT)
    AP_CL_ERROR(CL_INVALID_OPERATION)
    AP_CL_ERROR(CL_INVALID_GL_OBJECT)
    AP_CL_ERROR(CL_INVALID_BUFFER_SIZE)
    AP_CL_ERROR(CL_INVALID_MIP_LEVEL)
    AP_CL_ERROR(CL_INVALID_GLOBAL_WORK_SIZE)
    AP_CL_ERROR(CL_INVALID_PROPERTY)
    AP_CL_ERROR(CL_INVALID_IMAGE_DESCRIPTOR)
    AP_CL_ERROR(CL_INVALID_COMPILER_OPTIONS)
    AP_CL_ERROR(CL_INVALID_LINKER_OPTIONS)
    AP_CL_ERROR(CL_INVALID_DEVICE_PARTITION_COUNT)
#undef AP_CL_ERROR
    // The ICD loader's own code for "no platform installed" (cl_khr_icd).
    case -1001:
      return "CL_PLATFORM_NOT_FOUND_KHR";
  }
  return "unknown OpenCL error";
}

namespace opencl {

void check(cl_int err, const std::string& call) {
  if (err != CL_SUCCESS) throw OpenclError(call, err);
}

cl::Buffer make_buffer(const cl::Context& context, cl_mem_flags flags, std::size_t bytes, const std::string& name) {
  cl_int err = CL_SUCCESS;
  const std::size_t size = bytes > 0 ? bytes : 1;
  cl::Buffer buffer(context, flags, size, nullptr, &err);
  if (err != CL_SUCCESS)
    throw OpenclError("clCreateBuffer", err, "buffer '" + name + "' of " + std::to_string(size) + " bytes");
  return buffer;
}

}  // namespace opencl
}  // namespace animpak
