#include "animpak/compare.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace animpak {

std::int64_t ulp_distance(float a, float b) {
  if (std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b)) return 0;
  if (std::isnan(a) || std::isnan(b)) return nan_ulp_distance;
  // Maps the bit patterns onto one ordered integer line: negative floats count down from −0.
  const auto ordered = [](float f) {
    const std::int32_t i = std::bit_cast<std::int32_t>(f);
    return i < 0 ? std::int64_t{INT32_MIN} - i : std::int64_t{i};
  };
  const std::int64_t d = ordered(a) - ordered(b);
  return d < 0 ? -d : (d == 0 ? 1 : d);
}

FloatDifference compare_floats(std::span<const float> expected, std::span<const float> actual) {
  if (expected.size() != actual.size())
    throw std::invalid_argument("compare_floats: " + std::to_string(expected.size()) + " expected values, " +
                                std::to_string(actual.size()) + " actual values");
  FloatDifference d;
  constexpr double inf = std::numeric_limits<double>::infinity();
  constexpr double tiny = std::numeric_limits<float>::min();
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const std::int64_t ulps = ulp_distance(expected[i], actual[i]);
    if (ulps == 0) continue;
    if (d.count++ == 0) d.first = i;
    const double a = expected[i], b = actual[i];
    // inf − inf is NaN: any non-finite pair that differs in bits is an unbounded error.
    const double abs = std::isfinite(a) && std::isfinite(b) ? std::fabs(a - b) : inf;
    const double rel = abs / std::max(std::fabs(a), tiny);
    if (abs > d.max_abs) d.max_abs = abs, d.max_abs_at = i;
    if (rel > d.max_rel) d.max_rel = rel, d.max_rel_at = i;
    if (ulps > d.max_ulp) d.max_ulp = ulps, d.max_ulp_at = i;
  }
  return d;
}

#define AP_NAMED_FORCE(name, ...) NamedForce{#name, &ForceBreakdown::name},
const std::array<NamedForce, AP_FORCE_COMPONENTS> breakdown_forces = {AP_FORCE_TERMS(AP_NAMED_FORCE)};
#undef AP_NAMED_FORCE

const std::array<NamedStateArray, 8> state_arrays = {{{"x", &SimState::x, "vertex"},
                                                      {"y", &SimState::y, "vertex"},
                                                      {"t", &SimState::t, "vertex"},
                                                      {"vx", &SimState::vx, "vertex"},
                                                      {"vy", &SimState::vy, "vertex"},
                                                      {"vt", &SimState::vt, "vertex"},
                                                      {"spring_rest", &SimState::spring_rest, "slot"},
                                                      {"growth", &SimState::growth, "slice"}}};

const std::array<NamedStateScalar, 8> state_scalars = {{{"iteration", &SimState::iteration},
                                                        {"settling_since", &SimState::settling_since},
                                                        {"secondary_since", &SimState::secondary_since},
                                                        {"mark_iteration", &SimState::mark_iteration},
                                                        {"mark_growth", &SimState::mark_growth},
                                                        {"mark_growth_1", &SimState::mark_growth_1},
                                                        {"mark_growth_2", &SimState::mark_growth_2},
                                                        {"mark_growth_3", &SimState::mark_growth_3}}};

// SimState's members are all 8-byte aligned, so it has no padding and its size is the sum of its
// members': a member added to it, and to neither table above, breaks this sum.
static_assert(sizeof(SimState) == std::tuple_size_v<decltype(state_arrays)> * sizeof(std::vector<float>) +
                                      std::tuple_size_v<decltype(state_scalars)> * sizeof(std::uint64_t),
              "a SimState member is missing from state_arrays or state_scalars");

std::uint64_t NamedStateScalar::bits(const SimState& s) const {
  return std::visit([&](auto member) { return std::bit_cast<std::uint64_t>(s.*member); }, field);
}

double NamedStateScalar::value(const SimState& s) const {
  return std::visit([&](auto member) { return static_cast<double>(s.*member); }, field);
}

}  // namespace animpak
