// `animpak validate`: the reference and an OpenCL device stepped side by side on one scene, every force
// and every state array compared bit for bit, so that a user can check a device and driver before
// trusting its packings (the kernels promise the reference's exact numbers: docs/architecture.md, "The twin rule").
#include <algorithm>
#include <cctype>
#include <iostream>
#include <stdexcept>

#include "animpak/compare.hpp"
#include "animpak/error.hpp"
#include "animpak/scene.hpp"
#include "commands.hpp"
#include "validate_report.hpp"

namespace animpak::cli {
namespace {

void record(WorstError& worst, double value, std::int64_t state, std::size_t vertex, char axis) {
  if (value > worst.value) worst = {value, state, static_cast<std::int32_t>(vertex), axis};
}

void compare_field(ForceComparison& c, const reference::ForceField& ref, const reference::ForceField& dev,
                   std::int64_t state) {
  const std::pair<char, std::vector<float> reference::ForceField::*> axes[] = {
      {'x', &reference::ForceField::x}, {'y', &reference::ForceField::y}, {'t', &reference::ForceField::t}};
  for (const auto& [axis, member] : axes) {
    const FloatDifference d = compare_floats(ref.*member, dev.*member);
    c.differing += d.count;
    if (d.count > 0 && c.first_state < 0) c.first_state = state;
    record(c.abs, d.max_abs, state, d.max_abs_at, axis);
    record(c.rel, d.max_rel, state, d.max_rel_at, axis);
    record(c.ulp, static_cast<double>(d.max_ulp), state, d.max_ulp_at, axis);
  }
}

// Eq. 7 force by force on each side's own current state: the reference from scratch, the device
// through evaluate_forces (its grid rebuilt from its state, nothing advanced).
void compare_forces(DeviceValidation& v, const World& world, const SimState& ref_state, OpenclBackend& device) {
  const reference::CollisionGrid grid = reference::build_collision_grid(world.topology, ref_state, world.params);
  reference::ForceBreakdown ref_parts, dev_parts;
  const reference::StepForces ref = reference::step_forces(world.topology, ref_state, world.params, grid, &ref_parts);
  const reference::StepForces dev = device.evaluate_forces(&dev_parts);
  const auto state = static_cast<std::int64_t>(ref_state.iteration);
  for (std::size_t i = 0; i < breakdown_forces.size(); ++i)
    compare_field(v.forces[i], ref_parts.*breakdown_forces[i].field, dev_parts.*breakdown_forces[i].field, state);
  compare_field(v.forces.back(), ref.total, dev.total, state);
  v.checked_states.push_back(state);
}

std::vector<StateMismatch> compare_states(const SimState& ref, const SimState& dev) {
  std::vector<StateMismatch> out;
  for (const NamedStateArray& a : state_arrays) {
    const std::vector<float>&r = ref.*a.array, &d = dev.*a.array;
    const FloatDifference diff = compare_floats(r, d);
    if (diff.count == 0) continue;
    out.push_back({a.name, a.index, diff.count, r.size(), diff.first, r[diff.first], d[diff.first],
                   ulp_distance(r[diff.first], d[diff.first])});
  }
  for (const NamedStateScalar& s : state_scalars)
    if (s.bits(ref) != s.bits(dev)) out.push_back({s.name, "scalar", 1, 1, 0, s.value(ref), s.value(dev), 0});
  return out;
}

// OpenclError and std::invalid_argument (a topology the kernels cannot run) come through unchanged.
DeviceValidation validate_device(const World& world, const DeviceInfo& info, int steps, GridSort sort) {
  DeviceValidation v;
  v.device = info;
  v.steps = steps;
  for (const NamedForce& f : breakdown_forces) v.forces.emplace_back().name = f.name;
  v.forces.emplace_back().name = "total";
  DeviceChoice choice;
  choice.reference = false;
  choice.explicit_request = true;
  choice.device = info;
  const std::unique_ptr<OpenclBackend> device =
      make_opencl_backend(world.topology, world.state, world.params, choice, sort);
  const std::unique_ptr<Backend> ref = make_reference_backend(world.topology, world.state, world.params);
  // evaluate_forces rebuilds the device's grid; between two scheduled rebuilds that would hand the device's
  // next step a fresher grid than the reference's. So forces are compared where both sides rebuild
  // anyway, and at the last state, after which nothing steps.
  const auto rebuild = static_cast<std::uint64_t>(world.params.grid_rebuild_interval);
  SimState ref_state = world.state;
  for (int k = 0;; ++k) {
    if (k == steps || ref_state.iteration % rebuild == 0) compare_forces(v, world, ref_state, *device);
    if (k == steps) break;
    ref->step();
    device->step();
    ref_state = ref->state();
    if (v.first_differing_step < 0) {
      v.mismatches = compare_states(ref_state, device->state());
      if (!v.mismatches.empty()) v.first_differing_step = k + 1;
    }
  }
  return v;
}

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
    throw UsageError("--device reference: validate compares an OpenCL device with the reference; name a device "
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
  header.grid_rebuild_interval = world.params.grid_rebuild_interval;
  std::vector<DeviceValidation> results;
  for (const DeviceInfo& info : targets) {
    std::cerr << "animpak: validating " << info.name << " (" << info.platform << ") against the reference, "
              << options.steps << " steps\n";
    if (!options.all_devices) {
      results.push_back(validate_device(world, info, options.steps, sort));
      continue;
    }
    // One device failing to build or run the kernels must not hide the others' results.
    try {
      results.push_back(validate_device(world, info, options.steps, sort));
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
