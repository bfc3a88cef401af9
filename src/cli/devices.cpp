// `animpak devices`: every OpenCL platform and device, whether animpak's kernels build on it, and
// which one `pack` would choose by default.
#include <iomanip>
#include <iostream>

#include "animpak/opencl.hpp"
#include "commands.hpp"

namespace animpak::cli {

int devices(const DevicesOptions& options) {
  const std::vector<DeviceInfo> all = list_devices();
  if (all.empty()) std::cout << "No OpenCL platform found; animpak packs with the scalar reference solver.\n";
  std::string platform;
  for (const DeviceInfo& d : all) {
    if (d.platform != platform) {
      platform = d.platform;
      std::cout << "Platform: " << d.platform << " (" << d.platform_version << ")\n";
    }
    const KernelBuild build = try_build_kernels(d);
    std::cout << "  Device: " << d.name << "\n    vendor " << d.vendor << ", driver " << d.driver << ", " << d.version
              << ", " << (d.gpu ? "GPU" : "not a GPU") << (d.simulator ? " (a simulator: never the default)" : "")
              << ", " << d.compute_units << " compute units, " << std::fixed << std::setprecision(1)
              << double(d.global_memory) / (1u << 30) << " GiB (largest buffer "
              << double(d.max_allocation) / (1u << 30)
              << " GiB)\n    kernels: " << (build.ok ? "build OK" : "FAIL to build") << "\n";
    if (options.verbose || !build.ok)
      std::cout << "    build log:\n" << (build.log.empty() ? "(empty)" : build.log) << "\n";
  }
  std::cout << "Default for pack: " << choose_device("").reason << "\n";
  return 0;
}

}  // namespace animpak::cli
