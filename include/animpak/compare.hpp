// Comparing the reference with a device, number by number: the ULP distance and worst errors of two
// float arrays, and the named arrays of a ForceBreakdown and the named arrays and scalars of a SimState,
// listed once so that the equivalence suite and `animpak validate` walk the same ones in the same order.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <variant>
#include <vector>

#include "animpak/solver/step.hpp"
#include "animpak/state.hpp"

namespace animpak {

/// The ULP distance of NaN from anything else: 2^32, more than any two other floats are apart, and
/// exact as a double.
inline constexpr std::int64_t nan_ulp_distance = std::int64_t{1} << 32;

/// Distance in units in the last place between two floats (0 when the bits match). +0 and −0 count as
/// one step apart, so that any difference in bits is at least 1.
std::int64_t ulp_distance(float a, float b);

/// How two float arrays of the same length differ; every "at" is an index into them.
struct FloatDifference {
  std::size_t count = 0;  ///< entries whose bits differ
  std::size_t first = 0;  ///< the first of them, when count > 0
  double max_abs = 0.0;   ///< largest |expected − actual|
  std::size_t max_abs_at = 0;
  double max_rel = 0.0;  ///< largest |expected − actual| / max(|expected|, FLT_MIN)
  std::size_t max_rel_at = 0;
  std::int64_t max_ulp = 0;
  std::size_t max_ulp_at = 0;
};

/// Compares entry by entry; errors involving NaN or infinity count as infinite. std::invalid_argument
/// when the lengths differ.
FloatDifference compare_floats(std::span<const float> expected, std::span<const float> actual);

/// One force of Eq. 7 in a ForceBreakdown.
struct NamedForce {
  const char* name;
  ForceField ForceBreakdown::*field;
};

/// The forces of Eq. 7 in their sum's order, one per row of AP_FORCE_TERMS (kernels/shared_types.h), named
/// as it names them (the total is StepForces::total).
extern const std::array<NamedForce, AP_FORCE_COMPONENTS> breakdown_forces;

/// One per-element array of a SimState and what its index counts.
struct NamedStateArray {
  const char* name;
  std::vector<float> SimState::*array;
  const char* index;  ///< "vertex", "slot" (CSR spring slot) or "slice"
};

/// Every float array of a SimState: x, y, t, vx, vy, vt, spring_rest, growth.
extern const std::array<NamedStateArray, 8> state_arrays;

/// One scalar of a SimState: a counter of the run, or its progress mark's mean g.
struct NamedStateScalar {
  const char* name;
  std::variant<std::uint64_t SimState::*, double SimState::*> field;

  /// The field's bits: two states agree on it when these are equal, the test the float arrays get
  /// (so a double's -0 and +0 differ, and a NaN equals the same NaN).
  std::uint64_t bits(const SimState& s) const;
  /// Its value, for a report.
  double value(const SimState& s) const;
};

/// Every scalar of a SimState: iteration, settling_since, secondary_since, mark_iteration, mark_growth,
/// mark_growth_1 … 3. With state_arrays it covers every member: compare.cpp fails to compile when one is
/// added to SimState but to neither table.
extern const std::array<NamedStateScalar, 8> state_scalars;

}  // namespace animpak
