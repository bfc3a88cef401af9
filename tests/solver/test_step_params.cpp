// The one conversion of Params into the step's float block (include/animpak/step_params.hpp). Both
// backends read this block, so the equivalence suite cannot see an error in it: each field is checked
// here against the expression ForceParams documents, written out again.
#include <catch2/catch.hpp>

#include <algorithm>
#include <initializer_list>
#include <string_view>
#include <variant>
#include <vector>

#include "animpak/param_table.hpp"
#include "animpak/step_params.hpp"

using namespace animpak;

namespace {

// Distinct constants, none a round number, whose products (velocity_cap · Δt, wall_range², ...) each round
// differently when formed in float: a field read from the wrong member, or a product formed after the
// conversion, shows.
Params odd_params() {
  Params p;
  Params::Forces& f = p.forces;
  f.k_repulsion = 3.1e-7;
  f.repulsion_epsilon = 7.3e-6;
  f.wall_repulsion = 0.43;
  f.wall_range = 0.071;
  f.wall_mirror = 0.83;
  f.k_edge = 4321.7;
  f.k_shear = 1234.3;
  f.k_negative_space = 47.1;
  f.k_time = 5.3;
  f.k_target = 511.9;
  f.k_fold = 201.7;
  f.fold_area = 0.23;
  f.k_overlap = 5.7;
  f.k_overlap_depth = 6.1;
  f.k_boundary = 4.9;
  f.k_torsion = 2.3e-4;
  f.k_target_angle = 2.9e-3;
  f.dt = 0.043;
  f.velocity_cap = 0.022;
  f.interval_points = 5;
  f.motion_curve = 1;
  Params::Growth& g = p.growth;
  g.growth_rate = 0.011;
  g.shrink_rate = 0.012;
  g.settle_shrink_rate = 0.041;
  g.growth_ratio = 1.07;
  g.neighbour_growth_ratio = 1.031;
  g.max_growth = 14.3;
  g.growth_boost = 2.7;
  g.boost_gap = 0.0093;
  g.boost_speed = 0.47;
  p.stop.stop_gap = 0.0061;
  return p;
}

// The product of the constants' floats, the wrong way to form a derived constant.
float float_product(std::initializer_list<double> factors) {
  float r = 1.0f;
  for (const double x : factors) r = r * static_cast<float>(x);
  return r;
}

}  // namespace

TEST_CASE("step_params: every constant converted once, products formed in double first") {
  const Params params = odd_params();
  const Params::Forces& f = params.forces;
  const Params::Growth& g = params.growth;
  const ForceParams p = step_params(params);
  CHECK(p.k_repulsion == static_cast<float>(f.k_repulsion));
  CHECK(p.repulsion_epsilon == static_cast<float>(f.repulsion_epsilon));
  CHECK(p.k_wall == static_cast<float>(f.wall_repulsion * f.k_repulsion));
  CHECK(p.k_target == static_cast<float>(f.k_target));
  CHECK(p.k_overlap == static_cast<float>(f.k_overlap));
  CHECK(p.k_overlap_depth == static_cast<float>(f.k_overlap_depth));
  CHECK(p.k_boundary == static_cast<float>(f.k_boundary));
  CHECK(p.k_torsion == static_cast<float>(f.k_torsion));
  CHECK(p.dt == static_cast<float>(f.dt));
  CHECK(p.velocity_cap == static_cast<float>(f.velocity_cap * f.dt));
  CHECK(p.growth_step == static_cast<float>(g.growth_rate * f.dt));
  CHECK(p.shrink_step == static_cast<float>(g.shrink_rate * f.dt));
  CHECK(p.settle_shrink_step == static_cast<float>(g.settle_shrink_rate * f.dt));
  CHECK(p.growth_ratio == static_cast<float>(g.growth_ratio));
  CHECK(p.neighbour_growth_ratio == static_cast<float>(g.neighbour_growth_ratio));
  CHECK(p.max_growth == static_cast<float>(g.max_growth));
  CHECK(p.stop_gap == static_cast<float>(params.stop.stop_gap));
  CHECK(p.k_target_angle == static_cast<float>(f.k_target_angle));
  CHECK(p.wall_range2 == static_cast<float>(f.wall_range * f.wall_range));
  CHECK(p.interval_points == 5);
  CHECK(p.motion_curve == 1);
  CHECK(p.k_mirror == static_cast<float>(f.wall_mirror * f.k_repulsion));
  CHECK(p.k_fold == static_cast<float>(f.k_fold));
  CHECK(p.fold_area == static_cast<float>(f.fold_area));
  CHECK(p.growth_boost == static_cast<float>(g.growth_boost));
  CHECK(p.boost_gap == static_cast<float>(g.boost_gap));
  CHECK(p.boost_step == static_cast<float>(g.boost_speed * f.velocity_cap * f.dt * f.dt));
  for (const float pad : p.pad) CHECK(pad == 0.0f);
}

TEST_CASE("step_params: the constants of these tests tell a product formed in double from one in float") {
  const Params params = odd_params();
  const Params::Forces& f = params.forces;
  const Params::Growth& g = params.growth;
  const ForceParams p = step_params(params);
  CHECK(p.k_wall != float_product({f.wall_repulsion, f.k_repulsion}));
  CHECK(p.k_mirror != float_product({f.wall_mirror, f.k_repulsion}));
  CHECK(p.velocity_cap != float_product({f.velocity_cap, f.dt}));
  CHECK(p.growth_step != float_product({g.growth_rate, f.dt}));
  CHECK(p.shrink_step != float_product({g.shrink_rate, f.dt}));
  CHECK(p.settle_shrink_step != float_product({g.settle_shrink_rate, f.dt}));
  CHECK(p.wall_range2 != float_product({f.wall_range, f.wall_range}));
  CHECK(p.boost_step != float_product({g.boost_speed, f.velocity_cap, f.dt, f.dt}));
}

TEST_CASE("step_params: the spring stiffnesses by SpringClass") {
  const Params params = odd_params();
  const ForceParams p = step_params(params);
  CHECK(p.k_spring[static_cast<int>(SpringClass::edge)] == static_cast<float>(params.forces.k_edge));
  CHECK(p.k_spring[static_cast<int>(SpringClass::shear)] == static_cast<float>(params.forces.k_shear));
  CHECK(p.k_spring[static_cast<int>(SpringClass::negative_space)] ==
        static_cast<float>(params.forces.k_negative_space));
  CHECK(p.k_spring[static_cast<int>(SpringClass::time)] == static_cast<float>(params.forces.k_time));
  CHECK(p.k_spring[static_cast<int>(SpringClass::target)] == static_cast<float>(params.forces.k_target));
}

TEST_CASE("step_params: the stiffness of every force of AP_LOCAL_FORCES, from its row of the parameter table") {
  // Each row's Params member set through param_table() to a value of its own, none a round number.
  struct Local {
    std::string_view row;
    float ForceParams::*field;
  };
#define AP_LOCAL_FORCE_FIELD(name, stiffness, ...) Local{#stiffness, &ForceParams::stiffness},
  const Local locals[] = {AP_LOCAL_FORCES(AP_LOCAL_FORCE_FIELD)};
#undef AP_LOCAL_FORCE_FIELD
  Params params = odd_params();
  std::vector<double> values;
  for (const Local& local : locals) {
    const auto row = std::find_if(param_table().begin(), param_table().end(),
                                  [&](const ParamInfo& info) { return info.name == local.row; });
    REQUIRE(row != param_table().end());
    CHECK(row->group == "forces");
    values.push_back(1.37 + 0.113 * static_cast<double>(values.size()));
    std::get<double& (*)(Params&)>(row->field)(params) = values.back();
  }
  const ForceParams p = step_params(params);
  for (std::size_t i = 0; i < values.size(); ++i) {
    INFO(locals[i].row);
    CHECK(p.*locals[i].field == static_cast<float>(values[i]));
  }
}
