// The float constants of one step (paper §5), converted from Params once, in one place that belongs to
// neither backend (docs/architecture.md, "One block of step constants"): the reference reads its constants
// from this block and the OpenCL host passes the same block to the kernels by value. It is the C struct
// ForceParams of kernels/shared_types.h, so the kernels read it in the same layout.
#pragma once

#include "animpak/params.hpp"
#include "animpak/spring_class.hpp"
#include "shared_types.h"

namespace animpak {

/// Every constant the step's float arithmetic reads: each double of Params converted once with
/// static_cast<float>, each product (velocity_cap · Δt, growth_rate · Δt, wall_mirror · k_rpl, wall_range²,
/// boost_speed · velocity_cap · Δt², ...) formed in double first and then converted once; and the integer
/// settings of the step (interval_points, motion_curve), copied. ForceParams's comments say which is which.
ForceParams step_params(const Params& params);

}  // namespace animpak
