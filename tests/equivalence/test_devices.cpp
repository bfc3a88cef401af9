// Device discovery and selection, error names and build failures: the host layer's contract.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "animpak/error.hpp"
#include "cl_host.hpp"
#include "equivalence_support.hpp"
#include "kernel_sources.hpp"
#include "temp_dir.hpp"

namespace animpak::test {

TEST_CASE("choose_device: reference by name, unknown names refused", "[opencl]") {
  const DeviceChoice ref = choose_device("reference");
  CHECK(ref.reference);
  CHECK(ref.explicit_request);
  CHECK_THROWS_AS(choose_device("no-such-device-anywhere"), UsageError);
  const DeviceChoice def = choose_device("");
  CHECK_FALSE(def.explicit_request);
  CHECK_FALSE(def.reason.empty());
  // The default is a device exactly when one qualifies: a GPU, else PoCL, never a simulator.
  bool qualifies = false;
  for (const DeviceInfo& d : list_devices())
    qualifies =
        qualifies || (!d.simulator && (d.gpu || d.platform.find("Portable Computing Language") != std::string::npos));
  CHECK(def.reference == !qualifies);
  CHECK_FALSE(def.device.simulator);
}

TEST_CASE("default device: real GPUs, then PoCL, then the reference, never a simulator", "[opencl]") {
  // What the three implementations report (Oclgrind 21.10, PoCL 3.1, NVIDIA 580.159.04), and an emulator.
  auto device = [](const char* platform, const char* platform_version, const char* name, const char* vendor, bool gpu) {
    DeviceInfo d;
    d.platform = platform, d.platform_version = platform_version, d.name = name, d.vendor = vendor, d.gpu = gpu;
    return d;
  };
  DeviceInfo oclgrind = device("Oclgrind", "OpenCL 1.2 (Oclgrind 21.10)", "Oclgrind Simulator", "Oclgrind", true);
  DeviceInfo pocl = device("Portable Computing Language", "OpenCL 3.0 PoCL 3.1+debian",
                           "pthread-skylake-avx512-AMD EPYC", "AuthenticAMD", false);
  DeviceInfo nvidia = device("NVIDIA CUDA", "OpenCL 3.0 CUDA", "NVIDIA H100 80GB HBM3", "NVIDIA Corporation", true);
  const DeviceInfo emulator = device("Intel(R) FPGA Emulation Platform for OpenCL(TM)", "OpenCL 1.2 Intel(R) FPGA SDK",
                                     "Intel(R) FPGA Emulation Device", "Intel(R) Corporation", false);
  CHECK(opencl::is_simulator(oclgrind));
  CHECK(opencl::is_simulator(emulator));
  CHECK_FALSE(opencl::is_simulator(pocl));
  CHECK_FALSE(opencl::is_simulator(nvidia));
  for (DeviceInfo* d : {&oclgrind, &pocl, &nvidia}) d->simulator = opencl::is_simulator(*d);

  // Oclgrind says it is a GPU and comes first in platform order: PoCL is still the default.
  const DeviceChoice with_pocl = opencl::default_device({oclgrind, pocl});
  CHECK_FALSE(with_pocl.reference);
  CHECK(with_pocl.device.name == pocl.name);
  CHECK(with_pocl.reason.find("Oclgrind Simulator skipped") != std::string::npos);
  CHECK(opencl::default_device({oclgrind, pocl, nvidia}).device.name == nvidia.name);
  const DeviceChoice alone = opencl::default_device({oclgrind});
  CHECK(alone.reference);
  CHECK(alone.reason.find("Oclgrind Simulator skipped") != std::string::npos);
  CHECK(opencl::default_device({}).reference);
  CHECK(opencl::default_device({pocl}).reason.find("skipped") == std::string::npos);
}

TEST_CASE("opencl_error_name: codes become their names", "[opencl]") {
  CHECK(std::string(opencl_error_name(-5)) == "CL_OUT_OF_RESOURCES");
  CHECK(std::string(opencl_error_name(-4)) == "CL_MEM_OBJECT_ALLOCATION_FAILURE");
  CHECK(std::string(opencl_error_name(-11)) == "CL_BUILD_PROGRAM_FAILURE");
  CHECK(std::string(opencl_error_name(12345)) == "unknown OpenCL error");
  const OpenclError e("clCreateBuffer", -4, "buffer 'x' of 4 bytes");
  CHECK(std::string(e.what()).find("clCreateBuffer failed: CL_MEM_OBJECT_ALLOCATION_FAILURE (buffer 'x'") == 0);
}

TEST_CASE("try_build_kernels: every device builds, a broken kernel reports its log", "[opencl]") {
  const std::vector<DeviceChoice> devices = devices_under_test();
  if (skip_without_devices(devices)) return;
  for (const DeviceChoice& d : devices) {
    const KernelBuild ok = try_build_kernels(d.device);
    INFO(d.device.name << "\n" << ok.log);
    CHECK(ok.ok);
  }
  // A copy of the kernels with one syntax error, loaded through ANIMPAK_KERNEL_DIR.
  const TempDir temp("animpak-broken-kernels-");
  const std::filesystem::path& dir = temp.path();
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(ANIMPAK_SOURCE_DIR) / "kernels"))
    std::filesystem::copy_file(entry.path(), dir / entry.path().filename(),
                               std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir / "temporal.cl", std::ios::app) << "\nthis is not OpenCL C;\n";
  // The caller's own kernel folder, if any, is put back: the tests after this one check those kernels.
  const char* before = std::getenv("ANIMPAK_KERNEL_DIR");
  const std::string caller_kernels = before != nullptr ? before : "";
  ::setenv("ANIMPAK_KERNEL_DIR", dir.c_str(), 1);
  const KernelBuild broken = try_build_kernels(devices.front().device);
  if (before != nullptr)
    ::setenv("ANIMPAK_KERNEL_DIR", caller_kernels.c_str(), 1);
  else
    ::unsetenv("ANIMPAK_KERNEL_DIR");
  CHECK_FALSE(broken.ok);
  INFO(broken.log);
  CHECK(broken.log.find("temporal.cl") != std::string::npos);
}

TEST_CASE("device_build_options: CPU devices take the near block in 16 lanes, GPUs (and Oclgrind) one slot at a time",
          "[opencl]") {
  const std::vector<DeviceChoice> devices = devices_under_test();
  if (skip_without_devices(devices)) return;
  for (const DeviceChoice& d : devices) {
    const cl::Device device = opencl::device_for(d.device);
    cl_device_type type = 0;
    device.getInfo(CL_DEVICE_TYPE, &type);
    const std::string options = opencl::device_build_options(device);
    INFO(d.device.name << ": " << options);
    CHECK(options.rfind(opencl::build_options, 0) == 0);
    const bool cpu_only = (type & CL_DEVICE_TYPE_CPU) != 0 && (type & CL_DEVICE_TYPE_GPU) == 0;
    CHECK((options.find("-DAP_NEAR_LANES=16") != std::string::npos) == cpu_only);
  }
}

TEST_CASE("annotate_build_log: whole-program line numbers become kernel file and line") {
  // NVIDIA's compiler ignores #line and reports "<kernel>:LINE" over the whole program; the host turns
  // that into the file and line a developer edits. Find where temporal.cl starts in the program.
  const std::string source = opencl::program_source();
  const std::string directive = "#line 1 \"temporal.cl\"";
  const std::size_t at = source.find(directive);
  REQUIRE(at != std::string::npos);
  const int directive_line = 1 + static_cast<int>(std::count(source.begin(), source.begin() + at, '\n'));
  const int third = directive_line + 3;  // the third line of temporal.cl
  CHECK(opencl::program_location(source, third) == "temporal.cl:3");
  CHECK(opencl::program_location(source, 1) == "program line 1");
  const std::string log = "<kernel>:" + std::to_string(third) +
                          ":1: error: unknown type name 'this'\n"
                          "<kernel>:" +
                          std::to_string(directive_line + 1) + ":8: note: here\nno location\n";
  CHECK(opencl::annotate_build_log(log, source) ==
        "temporal.cl:3:1: error: unknown type name 'this'\ntemporal.cl:1:8: note: here\nno location\n");
  // Oclgrind's compiler names the program "input.cl" and counts lines in all of it, as NVIDIA's does.
  CHECK(opencl::annotate_build_log("input.cl:" + std::to_string(third) + ":1: error: x\n", source) ==
        "temporal.cl:3:1: error: x\n");
  // Compilers that honour #line already name the file; their logs pass through unchanged.
  CHECK(opencl::annotate_build_log("temporal.cl:5:1: error: x\n", source) == "temporal.cl:5:1: error: x\n");
  // Another file whose name ends in "input.cl", a name without a number after it, and a number no int
  // holds pass through too; a location at the very end of the log is still translated.
  CHECK(opencl::annotate_build_log("myinput.cl:3:1: x\n<source>: y\n<kernel>:99999999999:1: z\n", source) ==
        "myinput.cl:3:1: x\n<source>: y\n<kernel>:99999999999:1: z\n");
  CHECK(opencl::annotate_build_log("see <source>:" + std::to_string(third), source) == "see temporal.cl:3");
}

}  // namespace animpak::test
