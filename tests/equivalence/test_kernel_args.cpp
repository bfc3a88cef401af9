// The kernels' parameter table (src/solver/opencl/kernel_args.cpp) against the program itself: built
// with -cl-kernel-arg-info, every kernel reports its arguments' names, and they must be the table's row,
// in order and in number. Arguments are bound by those names (docs/architecture.md, "OpenCL host
// conventions"), so a kernel parameter renamed, reordered or added without the table fails here.
#include <set>
#include <string>
#include <vector>

#include "cl_host.hpp"
#include "equivalence_support.hpp"
#include "kernel.hpp"
#include "kernel_args.hpp"
#include "kernel_sources.hpp"

namespace animpak::test {

TEST_CASE("kernel arguments: every kernel's names and count are its row of the parameter table", "[opencl]") {
  const std::vector<DeviceChoice> devices = devices_under_test();
  if (skip_without_devices(devices)) return;
  for (const DeviceChoice& choice : devices) {
    INFO("device " << choice.device.name);
    const cl::Device device = opencl::device_for(choice.device);
    cl_int err = CL_SUCCESS;
    const cl::Context context(device, nullptr, nullptr, nullptr, &err);
    REQUIRE(err == CL_SUCCESS);
    cl::Program program(context, opencl::program_source(), false, &err);
    REQUIRE(err == CL_SUCCESS);
    const std::string options = opencl::device_build_options(device) + " -cl-kernel-arg-info";
    REQUIRE(program.build(std::vector<cl::Device>{device}, options.c_str()) == CL_SUCCESS);
    std::vector<cl::Kernel> kernels;
    REQUIRE(program.createKernels(&kernels) == CL_SUCCESS);

    std::set<std::string> in_program;
    for (cl::Kernel& kernel : kernels) {
      std::string name;
      REQUIRE(kernel.getInfo(CL_KERNEL_FUNCTION_NAME, &name) == CL_SUCCESS);
      name = name.c_str();  // drivers may count the terminating NUL in the string's length
      in_program.insert(name);
      INFO("kernel " << name);
      const opencl::KernelParameters* row = nullptr;
      for (const opencl::KernelParameters& r : opencl::kernel_parameters())
        if (r.kernel == name) row = &r;
      CHECK(row != nullptr);  // a kernel without a row in kernel_args.cpp
      if (row == nullptr) continue;
      cl_uint count = 0;
      REQUIRE(kernel.getInfo(CL_KERNEL_NUM_ARGS, &count) == CL_SUCCESS);
      std::vector<std::string> names;
      for (cl_uint i = 0; i < count; ++i) {
        std::string arg;
        REQUIRE(kernel.getArgInfo(i, CL_KERNEL_ARG_NAME, &arg) == CL_SUCCESS);
        names.push_back(arg.c_str());
      }
      const std::vector<std::string> table(row->names.begin(), row->names.end());
      CHECK(names == table);
      // The bound on a kernel's parameters (docs/architecture.md, "OpenCL host conventions").
      CHECK(count <= 20);
    }
    for (const opencl::KernelParameters& r : opencl::kernel_parameters()) {
      INFO("table row " << r.kernel);
      CHECK(in_program.count(std::string(r.kernel)) == 1);  // a row for a kernel the program lacks
    }
    CHECK(in_program.size() == opencl::kernel_parameters().size());  // one row per kernel, none twice
  }
}

TEST_CASE("kernel arguments: binding by name refuses a kernel without a row or a missing value", "[opencl]") {
  CHECK_THROWS_AS(opencl::kernel_parameters("no_such_kernel"), std::invalid_argument);
  const opencl::ArgValues values{{"world", WorldInfo{}}, {"count", 3}};
  REQUIRE(values.find("world") != nullptr);
  CHECK(values.find("count") != nullptr);
  CHECK(values.find("positions") == nullptr);
  const std::vector<DeviceChoice> devices = devices_under_test();
  if (skip_without_devices(devices)) return;
  const cl::Device device = opencl::device_for(devices.front().device);
  cl_int err = CL_SUCCESS;
  const cl::Context context(device, nullptr, nullptr, nullptr, &err);
  REQUIRE(err == CL_SUCCESS);
  const cl::Program program = opencl::build_program(context, device);
  opencl::Kernel kernel(program, "integrate");
  // integrate reads world, p, the forces, velocities and positions: with only world, p is missing.
  CHECK_THROWS_AS(kernel.bind(values), std::invalid_argument);
  CHECK_THROWS_AS(kernel.set("no_such_argument", 1), std::invalid_argument);
}

}  // namespace animpak::test
