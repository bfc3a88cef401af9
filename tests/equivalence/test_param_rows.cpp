// Every parameter the step reads, one row of param_table() at a time: a world where the row takes a
// value other than its default that changes the step, compared bit for bit between the OpenCL backend and
// the reference (docs/architecture.md, "The twin rule") over several steps: the forces with every
// component, the gaps and the contacts before the first step and after the last, and the whole state
// after every step. The suite's other cases run mostly the default constants and the paper's; a branch
// that only another value takes (wall_repulsion above 0, growth_boost above 1, motion_curve 0) is
// compared here.
//
// Which rows: the step reads the groups "forces" (through step_params, and the collision grid's
// cell_size, grid_rebuild_interval and far_cells, which both backends take from Params) and "growth"
// (through step_params), and of the group "stop" only stop_gap (step_params: a boundary vertex whose
// wall gap is below stop_gap touches the wall, and its slice stops growing). Left out: the groups "art",
// "element" and "placement", read when a scene's world is built (the art import, the elements, the
// initial configuration of §4), never by a step; and the rest of "stop", read by the run's loop between
// steps (src/solver/run.cpp). The last case checks that: a row outside those groups that changes
// step_params or the reference's steps fails there, and then needs a world in row_cases().
//
// To extend (docs/architecture.md, "How to add a force"): a new row of the groups above needs an entry in
// row_cases() with a value in its range, not its default, not a power of two (so that products round), in
// a world where it changes the result; the first case fails, naming the row, until it has one. The
// stiffness of a force of AP_LOCAL_FORCES (kernels/shared_types.h) has one without being listed
// (local_force_case), unless it is. A row may have more entries, where another value takes another
// branch (wall_mirror 0: no mirror image).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#include "animpak/param_table.hpp"
#include "animpak/params.hpp"
#include "animpak/step_params.hpp"
#include "equivalence_support.hpp"

namespace animpak::test {
namespace {

/// Steps each row's world takes on both backends; a grid rebuilt every third step is rebuilt twice.
constexpr int row_steps = 6;
/// A settling case stops growth before this step, so that its slices grow first and then settle.
constexpr int row_settle_step = 3;

enum class RowWorld {
  crowded,  ///< random ring elements that overlap, cross the container and its hole, with targets
  folded,   ///< fewer of them, with folded and squeezed slice triangles (the fold guard acts)
  sparse,   ///< small elements far apart at g 1: gaps above boost_gap, where the room's boost acts
};

/// One row's world and value.
struct RowCase {
  std::string_view row;  ///< the name in param_table()
  double value;          ///< in the row's range, not its default
  RowWorld world;
  /// Other rows set in the world (by name, through param_table()) so that this one acts; never the row
  /// itself, which keeps its default there.
  std::vector<std::pair<std::string_view, double>> base = {};
  bool settle = false;  ///< growth stopped before row_settle_step (the settling phase)
};

/// The case of a force of AP_LOCAL_FORCES that row_cases() does not list: the crowded world, where every
/// vertex has a force of its own, at 0.73 of its default (0.37 for a default of 0, or 0.73 of a lower
/// maximum): in its range, not its default, not a power of two.
RowCase local_force_case(std::string_view row, double default_value, double max) {
  const double value = default_value != 0.0 ? 0.73 * default_value : std::min(0.37, 0.73 * max);
  return {row, value, RowWorld::crowded};
}

/// The cases written out, row by row.
const std::vector<RowCase>& listed_cases() {
  static const std::vector<RowCase> cases = {
      // "forces"
      {"k_repulsion", 1.37e-7, RowWorld::crowded},
      {"repulsion_epsilon", 7.3e-6, RowWorld::crowded},
      {"wall_repulsion", 3.7, RowWorld::crowded},
      {"wall_range", 0.13, RowWorld::crowded},
      {"wall_mirror", 2.3, RowWorld::crowded},
      {"wall_mirror", 0, RowWorld::crowded, {{"wall_repulsion", 3.7}}},  // off: the wall's point force alone
      {"k_edge", 3700.0, RowWorld::crowded},
      {"k_shear", 6100.0, RowWorld::crowded},
      {"k_negative_space", 37.0, RowWorld::crowded},
      {"k_time", 7.3, RowWorld::crowded},
      {"k_target", 370.0, RowWorld::crowded},
      {"k_fold", 310.0, RowWorld::folded},
      {"fold_area", 0.37, RowWorld::folded},
      {"k_overlap", 3.7, RowWorld::crowded},
      {"k_overlap_depth", 6.3, RowWorld::crowded},
      {"k_boundary", 3.7, RowWorld::crowded},
      {"k_torsion", 3.1e-4, RowWorld::crowded},
      {"k_target_angle", 2.9e-3, RowWorld::crowded},
      {"dt", 0.037, RowWorld::crowded},
      {"velocity_cap", 0.013, RowWorld::crowded},
      {"cell_size", 0.057, RowWorld::crowded},
      {"grid_rebuild_interval", 3, RowWorld::crowded},
      {"far_cells", 0, RowWorld::crowded},
      {"interval_points", 3, RowWorld::crowded},
      {"motion_curve", 0, RowWorld::crowded},
      // "growth"
      {"growth_rate", 0.017, RowWorld::crowded},
      // The room's boost, clamp(gap / boost_gap, 1, growth_boost) below the speed limit: with gaps from
      // 0.02 to past 0.5 and outlines from 0.006 to 0.036 across, each of the three bounds the growth of
      // some slice.
      {"growth_boost", 3.7, RowWorld::sparse, {{"boost_gap", 0.1}}},
      {"boost_gap", 0.063, RowWorld::sparse, {{"growth_boost", 3.7}}},
      {"boost_speed", 0.83, RowWorld::sparse, {{"growth_boost", 3.7}, {"boost_gap", 0.1}}},
      {"shrink_rate", 0.023, RowWorld::crowded},
      {"growth_ratio", 1.37, RowWorld::crowded},
      {"neighbour_growth_ratio", 1.07, RowWorld::crowded},
      {"settle_shrink_rate", 0.061, RowWorld::crowded, {}, true},
      {"max_growth", 1.3, RowWorld::crowded},
      // "stop", the one row the step reads
      {"stop_gap", 0.13, RowWorld::sparse},
  };
  return cases;
}

/// listed_cases(), and local_force_case for every force of AP_LOCAL_FORCES that it does not list.
const std::vector<RowCase>& row_cases() {
  static const std::vector<RowCase> cases = [] {
    std::vector<RowCase> all = listed_cases();
    const auto add_local = [&](std::string_view row, double default_value, double max) {
      if (std::none_of(all.begin(), all.end(), [&](const RowCase& c) { return c.row == row; }))
        all.push_back(local_force_case(row, default_value, max));
    };
    [[maybe_unused]] constexpr double inf = std::numeric_limits<double>::infinity();
#define AP_LOCAL_FORCE_CASE(name, stiffness, default_value, max, ...) add_local(#stiffness, default_value, max);
    AP_LOCAL_FORCES(AP_LOCAL_FORCE_CASE)
#undef AP_LOCAL_FORCE_CASE
    return all;
  }();
  return cases;
}

/// The row's cases, in table order: one, or more where another value takes another branch.
std::vector<const RowCase*> row_cases_of(std::string_view row) {
  std::vector<const RowCase*> out;
  for (const RowCase& c : row_cases())
    if (c.row == row) out.push_back(&c);
  return out;
}

const ParamInfo* row_info(std::string_view row) {
  for (const ParamInfo& info : param_table())
    if (info.name == row) return &info;
  return nullptr;
}

void set_row(Params& params, const ParamInfo& info, double value) {
  std::visit(
      [&](auto field) {
        auto& member = field(params);
        member = static_cast<std::remove_reference_t<decltype(member)>>(value);
      },
      info.field);
}

/// Another valid value of a row than its default, for the rows the table leaves out.
double row_probe_value(const ParamInfo& info) {
  const double d = param_value(Params{}, info);
  if (param_is_integer(info)) return d + 1.0 <= info.max ? d + 1.0 : d - 1.0;
  double v = d != 0.0 ? d * 1.37 : info.min + 0.37 * (std::min(info.max, info.min + 1.0) - info.min);
  if (v > info.max) v = 0.5 * (info.min + d);
  return v;
}

/// Whether the step reads the row: its group is one the step reads, or it changes step_params.
bool row_reaches_step(const ParamInfo& info) {
  if (info.group == "forces" || info.group == "growth") return true;
  Params changed;
  set_row(changed, info, row_probe_value(info));
  const ForceParams a = step_params(Params{}), b = step_params(changed);
  return std::memcmp(&a, &b, sizeof a) != 0;  // 4-byte scalars only (kernels/shared_types.h): no padding
}

TinyWorld row_world(RowWorld kind) {
  if (kind == RowWorld::sparse) {
    RandomWorldShape shape;
    shape.elements = 10;
    shape.min_radius = 0.01f;
    shape.max_radius = 0.03f;
    shape.hole = false;
    shape.targets = false;
    TinyWorld w = random_world(43, shape);
    for (float& g : w.state.growth) g = 1.0f;
    return w;
  }
  RandomWorldShape shape;
  shape.elements = kind == RowWorld::crowded ? 5 : 3;
  shape.max_radius = 0.15f;
  TinyWorld w = random_world(kind == RowWorld::crowded ? 41 : 11, shape);
  if (kind == RowWorld::folded) {
    // Every third boundary vertex mirrored halfway through its slice's centroid (its fan triangles fold
    // over), every other slice's rest squeezed to 0.6 of its size about its centroid.
    std::vector<float> cx, cy;
    reference::slice_centroids(w.topo, w.state, cx, cy);
    for (std::int32_t v = 0; v < w.topo.vertex_count(); ++v) {
      const std::int32_t s = w.topo.slice[v];
      const float scale = v % 3 == 0 ? -0.5f : (s % 2 == 1 ? 0.6f : 1.0f);
      w.state.x[v] = cx[s] + scale * (w.state.x[v] - cx[s]);
      w.state.y[v] = cy[s] + scale * (w.state.y[v] - cy[s]);
    }
  }
  return w;
}

/// The world's constants: the defaults with the case's base rows, and with the row at `value`.
Params row_params(const RowCase& c, const ParamInfo& info, double value) {
  Params p;
  for (const auto& [name, v] : c.base)
    if (const ParamInfo* other = row_info(name)) set_row(p, *other, v);
  set_row(p, info, value);
  return p;
}

StepForces row_reference_forces(const TinyWorld& w, const SimState& state, const Params& params,
                                ForceBreakdown& parts) {
  const CollisionGrid grid = reference::build_collision_grid(w.topo, state, params);
  return reference::step_forces(w.topo, state, step_params(params), grid, &parts);
}

/// Every force component, the totals, the gaps and the contacts; empty when all match bit for bit.
std::string row_forces_difference(const StepForces& ref, const ForceBreakdown& ref_parts, const StepForces& dev,
                                  const ForceBreakdown& dev_parts) {
  return breakdown_difference(ref_parts, dev_parts) + bit_difference("total.x", ref.total.x, dev.total.x) +
         bit_difference("total.y", ref.total.y, dev.total.y) + bit_difference("total.t", ref.total.t, dev.total.t) +
         bit_difference("closest", ref.closest, dev.closest) + bit_difference("contact", ref.contact, dev.contact);
}

/// What the reference makes of a world: the forces before the first step and the state after the last.
struct RowOutcome {
  StepForces forces;
  ForceBreakdown parts;
  SimState state;
};

RowOutcome row_reference_outcome(const TinyWorld& w, const Params& params, bool settle) {
  RowOutcome o;
  o.forces = row_reference_forces(w, w.state, params, o.parts);
  auto ref = make_reference_backend(w.topo, w.state, params);
  for (int step = 1; step <= row_steps; ++step) {
    if (settle && step == row_settle_step) ref->stop_growth();
    ref->step();
  }
  o.state = ref->state();
  return o;
}

std::string row_label(const ParamInfo& info, double value) {
  std::ostringstream s;
  s.precision(9);
  s << info.name << " = " << value << " (default " << param_value(Params{}, info) << ")";
  return s.str();
}

/// The row's world on every device with each grid sort, against the reference: forces before the first
/// step, the state after every step, forces after the last; the first difference is reported.
void compare_row(const RowCase& c, const ParamInfo& info, const std::vector<DeviceChoice>& devices) {
  const TinyWorld w = row_world(c.world);
  const Params params = row_params(c, info, c.value);
  for (const DeviceChoice& d : devices)
    for (const GridSort sort : grid_sorts) {
      auto ref = make_reference_backend(w.topo, w.state, params);
      auto dev = make_opencl_backend(w.topo, w.state, params, d, sort);
      ForceBreakdown ref_parts, dev_parts;
      std::string diff = row_forces_difference(row_reference_forces(w, w.state, params, ref_parts), ref_parts,
                                               dev->evaluate_forces(&dev_parts), dev_parts);
      if (!diff.empty()) diff = "forces before the first step:\n" + diff;
      for (int step = 1; step <= row_steps && diff.empty(); ++step) {
        if (c.settle && step == row_settle_step) ref->stop_growth(), dev->stop_growth();
        ref->step();
        dev->step();
        diff = state_difference(ref->state(), dev->state());
        if (!diff.empty()) diff = "state after step " + std::to_string(step) + ":\n" + diff;
      }
      if (diff.empty()) {
        const SimState last = ref->state();
        ForceBreakdown ref_last, dev_last;
        diff = row_forces_difference(row_reference_forces(w, last, params, ref_last), ref_last,
                                     dev->evaluate_forces(&dev_last), dev_last);
        if (!diff.empty()) diff = "forces after the last step:\n" + diff;
      }
      INFO(row_label(info, c.value) << " on " << d.device.name << " (grid sorted on the " << grid_sort_name(sort)
                                    << ")\n"
                                    << diff);
      CHECK(diff.empty());
    }
}

/// One case of a row: its value valid, not the default, rounding in products; its base other rows; and
/// the value changing the reference's forces or state against the default, without which the comparison
/// proves nothing. Fails naming the parameter.
void check_row_case(const ParamInfo& info, const RowCase& c) {
  const double fallback = param_value(Params{}, info);
  INFO(row_label(info, c.value));
  CHECK(c.value >= info.min);
  CHECK(c.value <= info.max);
  CHECK(c.value != fallback);
  if (param_is_integer(info)) {
    CHECK(c.value == std::round(c.value));
  } else if (c.value != 0.0) {
    int exponent = 0;
    CHECK(std::frexp(c.value, &exponent) != 0.5);  // not a power of two: products with it round
  }
  for (const auto& [name, v] : c.base)
    if (row_info(name) == nullptr || name == info.name) {
      FAIL_CHECK("parameter " << info.name << ": its world sets " << name
                              << ", which is not another row of param_table()");
      return;
    }
  const TinyWorld w = row_world(c.world);
  const RowOutcome on = row_reference_outcome(w, row_params(c, info, c.value), c.settle);
  const RowOutcome off = row_reference_outcome(w, row_params(c, info, fallback), c.settle);
  const bool changes = !row_forces_difference(off.forces, off.parts, on.forces, on.parts).empty() ||
                       !state_difference(off.state, on.state).empty();
  if (!changes)
    FAIL_CHECK("parameter " << info.name << " = " << c.value
                            << " changes neither the forces nor the state of its world against its default: "
                               "choose a value or world in row_cases() where it acts");
}

/// Compares every row the step reads whose group `wanted` accepts; a row without a case fails.
template <typename Wanted>
void compare_rows(Wanted wanted) {
  const std::vector<DeviceChoice> devices = devices_under_test();
  if (skip_without_devices(devices)) return;
  int compared = 0;
  for (const ParamInfo& info : param_table()) {
    if (!row_reaches_step(info) || !wanted(info)) continue;
    const std::vector<const RowCase*> cases = row_cases_of(info.name);
    if (cases.empty())
      FAIL_CHECK("parameter " << info.name << " has no world in row_cases() (tests/equivalence/test_param_rows.cpp)");
    for (const RowCase* c : cases) compare_row(*c, info, devices), ++compared;
  }
  CHECK(compared > 0);
}

}  // namespace

TEST_CASE("param rows: every parameter the step reads has a world and a value that changes the step", "[equivalence]") {
  for (const ParamInfo& info : param_table()) {
    if (!row_reaches_step(info)) continue;
    const std::vector<const RowCase*> cases = row_cases_of(info.name);
    if (cases.empty())
      FAIL_CHECK("parameter " << info.name << " (group " << info.group
                              << ") reaches the step but has no world in row_cases() "
                                 "(tests/equivalence/test_param_rows.cpp): add one with a value that changes the "
                                 "step (docs/architecture.md, \"How to add a force\", step 7)");
    for (const RowCase* c : cases) check_row_case(info, *c);
  }
  for (const RowCase& c : row_cases()) {
    const ParamInfo* info = row_info(c.row);
    if (info == nullptr)
      FAIL_CHECK("row_cases() names " << c.row << ", which param_table() does not have");
    else if (!row_reaches_step(*info))
      FAIL_CHECK("row_cases() names " << c.row << ", which the step does not read (group " << info->group << ")");
  }
}

TEST_CASE("param rows: in the sparse world each bound of the room's boost sets the growth of some slice",
          "[equivalence]") {
  // Not vacuous: where one bound sets the boost of every slice, the arithmetic of the others goes
  // uncompared.
  const ParamInfo* info = row_info("growth_boost");
  REQUIRE(info != nullptr);
  REQUIRE(!row_cases_of("growth_boost").empty());
  const RowCase* c = row_cases_of("growth_boost").front();
  const TinyWorld w = row_world(c->world);
  const Params params = row_params(*c, *info, c->value);
  const ForceParams p = step_params(params);
  ForceBreakdown parts;
  const StepForces forces = row_reference_forces(w, w.state, params, parts);
  int by_gap = 0, by_boost = 0, by_speed = 0;
  for (std::int32_t s = 0; s < w.topo.slice_count(); ++s) {
    std::uint8_t bits = 0;
    float gap = std::numeric_limits<float>::infinity(), radius2 = 0.0f;
    for (std::int32_t v = w.topo.slice_begin[s]; v < w.topo.slice_begin[s + 1]; ++v) {
      bits |= forces.contact[v];
      gap = std::min(gap, forces.closest[v]);
      const float dx = w.topo.rest_copy_x[v] - w.topo.slice_rest_copy_cx[s],
                  dy = w.topo.rest_copy_y[v] - w.topo.slice_rest_copy_cy[s];
      radius2 = std::max(radius2, dx * dx + dy * dy);
    }
    const float ratio = gap / p.boost_gap, limit = p.boost_step / (std::sqrt(radius2) * p.growth_step);
    if (bits != 0 || !(ratio > 1.0f) || !(limit > 1.0f)) continue;  // not growing, or at the paper's rate
    if (ratio < p.growth_boost && ratio < limit)
      ++by_gap;
    else if (p.growth_boost <= limit)
      ++by_boost;
    else
      ++by_speed;
  }
  INFO("slices whose boost the gap sets: " << by_gap << ", growth_boost: " << by_boost
                                           << ", the speed limit: " << by_speed);
  CHECK(by_gap > 0);
  CHECK(by_boost > 0);
  CHECK(by_speed > 0);
}

TEST_CASE("param rows: the forces group, row by row, gives identical forces and states", "[equivalence][opencl]") {
  compare_rows([](const ParamInfo& info) { return info.group == "forces"; });
}

TEST_CASE("param rows: the growth group and stop_gap, row by row, give identical forces and states",
          "[equivalence][opencl]") {
  compare_rows([](const ParamInfo& info) { return info.group != "forces"; });
}

TEST_CASE("param rows: the rows left out change neither step_params nor the reference's steps", "[equivalence]") {
  const TinyWorld w = row_world(RowWorld::crowded);
  const RowOutcome fallback = row_reference_outcome(w, Params{}, false);
  int left_out = 0;
  for (const ParamInfo& info : param_table()) {
    if (row_reaches_step(info)) continue;
    ++left_out;
    Params changed;
    set_row(changed, info, row_probe_value(info));
    const RowOutcome probe = row_reference_outcome(w, changed, false);
    const std::string diff = row_forces_difference(fallback.forces, fallback.parts, probe.forces, probe.parts) +
                             state_difference(fallback.state, probe.state);
    INFO(row_label(info, row_probe_value(info)) << "\n" << diff);
    if (!diff.empty())
      FAIL_CHECK("parameter " << info.name << " (group " << info.group
                              << ") changes the step, but test_param_rows.cpp leaves its group out: add its group "
                                 "and a world in row_cases()");
  }
  CHECK(left_out > 0);
}

}  // namespace animpak::test
