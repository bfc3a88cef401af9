// `animpak validate`: which devices to compare on which scene, and the report; the comparison itself is
// the solver's (animpak/validation.hpp), so that a user can check a device and driver before trusting
// its packings.
#include <algorithm>
#include <cctype>
#include <iostream>
#include <stdexcept>

#include "animpak/error.hpp"
#include "animpak/scene.hpp"
#include "commands.hpp"
#include "validate_report.hpp"

namespace animpak::cli {
namespace {

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

bool is_reference(std::string request) {
  std::transform(request.begin(), request.end(), request.begin(), [](unsigned char c) { return std::tolower(c); });
  return request == "reference";
}

}  // namespace

int validate(const ValidateOptions& options) {
  if (options.device && options.all_devices) throw UsageError("give either --device or --all-devices, not both");
  const GridSort sort = parse_grid_sort(options.grid_sort, "--grid-sort");
  if (options.device && is_reference(*options.device))
    throw UsageError(
        "--device reference: validate compares an OpenCL device with the reference; name a device "
        "(see animpak devices) or use --all-devices");
  const SceneSpec scene = load_scene(options.scene);

  // Which devices: every one, the one named (UsageError when none or several match), or the one pack
  // would choose by default.
  std::vector<DeviceInfo> targets;
  std::string chosen;  // why the default rule chose what it did (the reference, when nothing to validate)
  if (options.all_devices) {
    targets = list_devices();
  } else {
    if (options.device && list_devices().empty())
      throw UsageError("--device " + *options.device + ": no OpenCL device found; nothing to validate");
    const DeviceChoice choice = choose_device(options.device.value_or(""));
    if (!choice.reference) targets.push_back(choice.device);
    chosen = choice.reason;
  }
  ValidationHeader header{options.scene.string(), 0, 0, options.steps, 1};
  if (targets.empty()) {
    const std::string nothing = options.all_devices ? "No OpenCL device found; nothing to validate."
                                                    : "Nothing to validate: the default device is the " + chosen;
    if (options.json) {
      std::cerr << "animpak: " << nothing << "\n";
      print_json(std::cout, header, {});
    } else {
      std::cout << nothing << "\n";
    }
    return 0;
  }

  const World world = make_world(scene);
  header.elements = world.elements.size();
  header.vertices = static_cast<std::size_t>(world.topology.vertex_count());
  header.grid_rebuild_interval = world.params.forces.grid_rebuild_interval;
  std::vector<DeviceValidation> results;
  for (const DeviceInfo& info : targets) {
    std::cerr << "animpak: validating " << info.name << " (" << info.platform << ") against the reference, "
              << options.steps << " steps\n";
    if (!options.all_devices) {
      results.push_back(validate_device(world.topology, world.state, world.params, info, options.steps, sort));
      continue;
    }
    // One device failing to build or run the kernels must not hide the others' results.
    try {
      results.push_back(validate_device(world.topology, world.state, world.params, info, options.steps, sort));
    } catch (const OpenclError& e) {
      results.push_back({info, first_line(e.what()), options.steps, {}, {}, -1, {}});
    } catch (const std::invalid_argument& e) {
      results.push_back({info, first_line(e.what()), options.steps, {}, {}, -1, {}});
    }
  }

  if (options.json)
    print_json(std::cout, header, results);
  else if (options.all_devices)
    print_summary(std::cout, header, results);
  else
    print_table(std::cout, header, results.front());
  const auto differs = [](const DeviceValidation& v) { return v.error.empty() && !v.identical(); };
  const auto failed = [](const DeviceValidation& v) { return !v.error.empty(); };
  if (std::any_of(results.begin(), results.end(), differs)) return static_cast<int>(ExitCode::differs);
  if (std::any_of(results.begin(), results.end(), failed)) return static_cast<int>(ExitCode::internal);
  return 0;
}

}  // namespace animpak::cli
