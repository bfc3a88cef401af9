// Finding and choosing devices by name, never by index (indices differ between machines).
#include <algorithm>
#include <cctype>

#include "animpak/error.hpp"
#include "cl_host.hpp"
#include "kernel_sources.hpp"

namespace animpak {
namespace opencl {
namespace {

template <typename T>
T device_info(const cl::Device& d, cl_device_info what, const char* name) {
  T value{};
  check(d.getInfo(what, &value), std::string("clGetDeviceInfo(") + name + ")");
  return value;
}

}  // namespace

static std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

static bool is_pocl(const DeviceInfo& d) {
  return lower(d.platform).find("portable computing language") != std::string::npos ||
         lower(d.platform_version).find("pocl") != std::string::npos;
}

bool is_simulator(const DeviceInfo& d) {
  // Oclgrind calls its device "Oclgrind Simulator"; Intel's FPGA platform says "Emulation".
  const std::string words = lower(d.platform + " " + d.platform_version + " " + d.name + " " + d.vendor);
  for (const char* word : {"oclgrind", "simulat", "emulat"})
    if (words.find(word) != std::string::npos) return true;
  return false;
}

DeviceChoice default_device(const std::vector<DeviceInfo>& devices) {
  DeviceChoice choice;
  if (devices.empty()) {
    choice.reason = "reference: no OpenCL platform found (install an ICD such as pocl-opencl-icd for OpenCL)";
    return choice;
  }
  // A simulator may call itself a GPU (Oclgrind does) yet runs kernels orders of magnitude slower:
  // whoever installs one to check kernels must not get every pack run in it, so only --device chooses one.
  std::string skipped;
  for (const DeviceInfo& d : devices)
    if (d.simulator) skipped += (skipped.empty() ? "" : ", ") + d.name;
  const std::string aside = skipped.empty() ? "" : " (" + skipped + " skipped: a simulator, chosen only by --device)";
  auto pick = [&](const DeviceInfo& d, const std::string& why) {
    choice.reference = false;
    choice.device = d;
    choice.reason = d.name + " (" + d.platform + "): " + why + aside;
    return choice;
  };
  for (const DeviceInfo& d : devices)
    if (d.gpu && !d.simulator) return pick(d, "the first GPU");
  for (const DeviceInfo& d : devices)
    if (is_pocl(d) && !d.simulator) return pick(d, "no GPU found; PoCL's CPU device");
  choice.reason =
      "reference: none of the " + std::to_string(devices.size()) + " OpenCL devices is a GPU or PoCL" + aside;
  return choice;
}

std::vector<FoundDevice> find_devices() {
  std::vector<cl::Platform> platforms;
  const cl_int err = cl::Platform::get(&platforms);
  // No ICD installed, or none that loads: no devices, which the caller reports in words.
  if (err == -1001 || err == CL_INVALID_VALUE || platforms.empty()) return {};
  check(err, "clGetPlatformIDs");
  std::vector<FoundDevice> found;
  for (const cl::Platform& p : platforms) {
    std::string platform_name, platform_version;
    check(p.getInfo(CL_PLATFORM_NAME, &platform_name), "clGetPlatformInfo(CL_PLATFORM_NAME)");
    check(p.getInfo(CL_PLATFORM_VERSION, &platform_version), "clGetPlatformInfo(CL_PLATFORM_VERSION)");
    std::vector<cl::Device> devices;
    const cl_int derr = p.getDevices(CL_DEVICE_TYPE_ALL, &devices);
    if (derr == CL_DEVICE_NOT_FOUND) continue;
    check(derr, "clGetDeviceIDs(" + platform_name + ")");
    for (const cl::Device& d : devices) {
      DeviceInfo info;
      info.platform = platform_name;
      info.platform_version = platform_version;
      info.name = device_info<std::string>(d, CL_DEVICE_NAME, "CL_DEVICE_NAME");
      info.vendor = device_info<std::string>(d, CL_DEVICE_VENDOR, "CL_DEVICE_VENDOR");
      info.driver = device_info<std::string>(d, CL_DRIVER_VERSION, "CL_DRIVER_VERSION");
      info.version = device_info<std::string>(d, CL_DEVICE_VERSION, "CL_DEVICE_VERSION");
      info.gpu = (device_info<cl_device_type>(d, CL_DEVICE_TYPE, "CL_DEVICE_TYPE") & CL_DEVICE_TYPE_GPU) != 0;
      info.compute_units = device_info<cl_uint>(d, CL_DEVICE_MAX_COMPUTE_UNITS, "CL_DEVICE_MAX_COMPUTE_UNITS");
      info.global_memory = device_info<cl_ulong>(d, CL_DEVICE_GLOBAL_MEM_SIZE, "CL_DEVICE_GLOBAL_MEM_SIZE");
      info.max_allocation = device_info<cl_ulong>(d, CL_DEVICE_MAX_MEM_ALLOC_SIZE, "CL_DEVICE_MAX_MEM_ALLOC_SIZE");
      // Strings from some drivers carry their C terminator inside the std::string.
      for (std::string* s :
           {&info.name, &info.vendor, &info.driver, &info.version, &info.platform, &info.platform_version})
        s->erase(std::find(s->begin(), s->end(), '\0'), s->end());
      info.simulator = is_simulator(info);
      found.push_back({d, info});
    }
  }
  return found;
}

cl::Device device_for(const DeviceInfo& info) {
  for (const FoundDevice& f : find_devices())
    if (f.info.platform == info.platform && f.info.name == info.name) return f.device;
  throw OpenclError("clGetDeviceIDs", CL_DEVICE_NOT_FOUND, "no device '" + info.name + "' on '" + info.platform + "'");
}

}  // namespace opencl

std::vector<DeviceInfo> list_devices() {
  std::vector<DeviceInfo> out;
  for (const opencl::FoundDevice& f : opencl::find_devices()) out.push_back(f.info);
  return out;
}

KernelBuild try_build_kernels(const DeviceInfo& info) {
  KernelBuild result;
  try {
    const cl::Device device = opencl::device_for(info);
    cl_int err = CL_SUCCESS;
    cl::Context context(device, nullptr, nullptr, nullptr, &err);
    opencl::check(err, "clCreateContext");
    const cl::Program program = opencl::build_program(context, device);
    std::string log;
    opencl::check(program.getBuildInfo(device, CL_PROGRAM_BUILD_LOG, &log), "clGetProgramBuildInfo");
    result.log = opencl::annotate_build_log(log, opencl::program_source());
    result.ok = true;
  } catch (const OpenclError& e) {
    result.log = e.build_log().empty() ? e.what() : e.build_log();
  }
  return result;
}

DeviceChoice choose_device(std::string_view request) {
  DeviceChoice choice;
  choice.explicit_request = !request.empty();
  if (request == "reference") {
    choice.reason = "reference: the scalar solver, as requested";
    return choice;
  }
  const std::vector<DeviceInfo> devices = list_devices();
  if (request.empty()) return opencl::default_device(devices);
  const std::string wanted = opencl::lower(request);
  std::vector<DeviceInfo> matches;
  for (const DeviceInfo& d : devices) {
    const std::string haystack = opencl::lower(d.platform + " " + d.platform_version + " " + d.name + " " + d.vendor);
    if (haystack.find(wanted) != std::string::npos) matches.push_back(d);
  }
  if (matches.size() != 1) {
    std::string names;
    for (const DeviceInfo& d : devices) names += (names.empty() ? "" : ", ") + d.name + " (" + d.platform + ")";
    throw UsageError("--device " + std::string(request) + ": " +
                     (matches.empty() ? "no OpenCL device matches" : "more than one OpenCL device matches") +
                     "; devices: " + (names.empty() ? "none" : names) + "; or use --device reference");
  }
  choice.reference = false;
  choice.device = matches.front();
  choice.reason = choice.device.name + " (" + choice.device.platform + "): matches --device " + std::string(request);
  return choice;
}

}  // namespace animpak
