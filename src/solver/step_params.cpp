// Params to the step's float block (include/animpak/step_params.hpp), the one place either backend's
// constants come from. Each product is formed in double, left to right as written, and converted once.
#include "animpak/step_params.hpp"

namespace animpak {

// k_spring is indexed by SpringClass.
static_assert(AP_SPRING_CLASSES == spring_class_count);

ForceParams step_params(const Params& params) {
  const Params::Forces& f = params.forces;
  const Params::Growth& g = params.growth;
  ForceParams p{};
  p.k_repulsion = static_cast<float>(f.k_repulsion);
  p.repulsion_epsilon = static_cast<float>(f.repulsion_epsilon);
  p.k_wall = static_cast<float>(f.wall_repulsion * f.k_repulsion);
  p.k_spring[static_cast<int>(SpringClass::edge)] = static_cast<float>(f.k_edge);
  p.k_spring[static_cast<int>(SpringClass::shear)] = static_cast<float>(f.k_shear);
  p.k_spring[static_cast<int>(SpringClass::negative_space)] = static_cast<float>(f.k_negative_space);
  p.k_spring[static_cast<int>(SpringClass::time)] = static_cast<float>(f.k_time);
  p.k_spring[static_cast<int>(SpringClass::target)] = static_cast<float>(f.k_target);
  p.k_target = static_cast<float>(f.k_target);
  p.k_overlap = static_cast<float>(f.k_overlap);
  p.k_overlap_depth = static_cast<float>(f.k_overlap_depth);
  p.k_boundary = static_cast<float>(f.k_boundary);
  p.k_torsion = static_cast<float>(f.k_torsion);
#define AP_SET_STIFFNESS(name, stiffness, ...) p.stiffness = static_cast<float>(f.stiffness);
  AP_LOCAL_FORCES(AP_SET_STIFFNESS)
#undef AP_SET_STIFFNESS
  p.dt = static_cast<float>(f.dt);
  p.velocity_cap = static_cast<float>(f.velocity_cap * f.dt);
  p.growth_step = static_cast<float>(g.growth_rate * f.dt);
  p.shrink_step = static_cast<float>(g.shrink_rate * f.dt);
  p.settle_shrink_step = static_cast<float>(g.settle_shrink_rate * f.dt);
  p.growth_ratio = static_cast<float>(g.growth_ratio);
  p.neighbour_growth_ratio = static_cast<float>(g.neighbour_growth_ratio);
  p.max_growth = static_cast<float>(g.max_growth);
  p.stop_gap = static_cast<float>(params.stop.stop_gap);
  p.k_target_angle = static_cast<float>(f.k_target_angle);
  p.wall_range2 = static_cast<float>(f.wall_range * f.wall_range);
  p.interval_points = f.interval_points;
  p.motion_curve = f.motion_curve;
  p.k_mirror = static_cast<float>(f.wall_mirror * f.k_repulsion);
  p.k_fold = static_cast<float>(f.k_fold);
  p.fold_area = static_cast<float>(f.fold_area);
  p.growth_boost = static_cast<float>(g.growth_boost);
  p.boost_gap = static_cast<float>(g.boost_gap);
  p.boost_step = static_cast<float>(g.boost_speed * f.velocity_cap * f.dt * f.dt);
  return p;
}

}  // namespace animpak
