// The reference and an OpenCL device side by side (animpak/validation.hpp).
#include "animpak/validation.hpp"

#include <algorithm>
#include <memory>

#include "animpak/compare.hpp"
#include "animpak/reference/grid.hpp"
#include "animpak/reference/step.hpp"
#include "animpak/simulation.hpp"
#include "animpak/step_params.hpp"

namespace animpak {
namespace {

void record(WorstError& worst, double value, std::int64_t state, std::size_t vertex, char axis) {
  if (value > worst.value) worst = {value, state, static_cast<std::int32_t>(vertex), axis};
}

void compare_field(ForceComparison& c, const ForceField& ref, const ForceField& dev, std::int64_t state) {
  const std::pair<char, std::vector<float> ForceField::*> axes[] = {
      {'x', &ForceField::x}, {'y', &ForceField::y}, {'t', &ForceField::t}};
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
void compare_forces(DeviceValidation& v, const Topology& topology, const Params& params, const SimState& ref_state,
                    OpenclBackend& device) {
  const CollisionGrid grid = reference::build_collision_grid(topology, ref_state, params);
  ForceBreakdown ref_parts, dev_parts;
  const StepForces ref = reference::step_forces(topology, ref_state, step_params(params), grid, &ref_parts);
  const StepForces dev = device.evaluate_forces(&dev_parts);
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

}  // namespace

DeviceValidation validate_device(const Topology& topology, const SimState& initial, const Params& params,
                                 const DeviceInfo& info, int steps, GridSort sort) {
  DeviceValidation v;
  v.device = info;
  v.steps = steps;
  for (const NamedForce& f : breakdown_forces) v.forces.emplace_back().name = f.name;
  v.forces.emplace_back().name = "total";
  DeviceChoice choice;
  choice.reference = false;
  choice.explicit_request = true;
  choice.device = info;
  const std::unique_ptr<OpenclBackend> device = make_opencl_backend(topology, initial, params, choice, sort);
  const std::unique_ptr<Backend> ref = make_reference_backend(topology, initial, params);
  // evaluate_forces rebuilds the device's grid; between two scheduled rebuilds that would hand the device's
  // next step a fresher grid than the reference's. So forces are compared where both sides rebuild
  // anyway, and at the last state, after which nothing steps.
  const auto rebuild = static_cast<std::uint64_t>(params.forces.grid_rebuild_interval);
  SimState ref_state = initial;
  for (int k = 0;; ++k) {
    if (k == steps || ref_state.iteration % rebuild == 0) compare_forces(v, topology, params, ref_state, *device);
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

std::int64_t DeviceValidation::max_ulp() const {
  double worst = 0.0;
  for (const ForceComparison& f : forces) worst = std::max(worst, f.ulp.value);
  return static_cast<std::int64_t>(worst);  // at most 2^32 (compare.hpp), so exact
}

std::string DeviceValidation::verdict() const {
  if (!error.empty()) return "error: " + error;
  if (identical()) return "bit-identical";
  std::int64_t earliest = -1;
  for (const ForceComparison& f : forces)
    if (f.first_state >= 0 && (earliest < 0 || f.first_state < earliest)) earliest = f.first_state;
  if (earliest < 0) return "DIFFERS: state after step " + std::to_string(first_differing_step);
  std::string names;
  for (const ForceComparison& f : forces)
    if (f.first_state == earliest) names += (names.empty() ? "" : ", ") + f.name;
  return "DIFFERS: " + names + " (first at state " + std::to_string(earliest) + ")";
}

}  // namespace animpak
