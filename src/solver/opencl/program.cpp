// Assembling and building the kernels' program in one place (style-anchors §8.12).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "animpak/error.hpp"
#include "cl_host.hpp"
#include "kernel_sources.hpp"

namespace animpak::opencl {
namespace {

// Dependency order: each file uses only functions of the files before it.
constexpr const char* kernel_files[] = {"closest_point.cl", "grid.cl",     "overlap.cl",  "repulsion.cl",
                                        "springs.cl",       "target.cl",   "boundary.cl", "torsion.cl",
                                        "temporal.cl",      "forces.cl",   "integrate.cl", "constraints.cl",
                                        "growth.cl",        "stats.cl"};

std::string kernel_text(const char* name) {
  if (const char* dir = std::getenv("ANIMPAK_KERNEL_DIR"); dir != nullptr && *dir != '\0') {
    const std::filesystem::path file = std::filesystem::path(dir) / name;
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(file.string() + ": cannot read this kernel file (ANIMPAK_KERNEL_DIR is set)");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  return std::string(embedded_kernel_source(name));
}

}  // namespace

std::string program_source() {
  // FP_CONTRACT OFF: no fused multiply-adds, so every product and sum rounds as in the reference.
  std::string source = "#pragma OPENCL FP_CONTRACT OFF\n#line 1 \"shared_types.h\"\n" + kernel_text("shared_types.h");
  for (const char* name : kernel_files) source += "\n#line 1 \"" + std::string(name) + "\"\n" + kernel_text(name);
  return source;
}

cl::Program build_program(const cl::Context& context, const cl::Device& device) {
  cl_int err = CL_SUCCESS;
  cl::Program program(context, program_source(), false, &err);
  check(err, "clCreateProgramWithSource");
  const cl_int built = program.build(std::vector<cl::Device>{device}, build_options);
  if (built != CL_SUCCESS) {
    std::string log, name;
    device.getInfo(CL_DEVICE_NAME, &name);
    program.getBuildInfo(device, CL_PROGRAM_BUILD_LOG, &log);
    throw OpenclError("clBuildProgram", built, "device " + name + ", options " + build_options, log);
  }
  return program;
}

}  // namespace animpak::opencl
