// state_difference, which the step tests trust to find any difference between the reference's state and
// a device's: each array and scalar of the tables (compare.hpp) changed alone is reported, under its
// own name and no other, so that no member is compared twice while another is left out. compare.cpp's
// static_assert covers a member added to SimState but to neither table. No device is needed.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <variant>

#include "equivalence_support.hpp"

using namespace animpak;
using animpak::test::state_difference;

namespace {

SimState sample_state() {
  SimState s;
  for (const NamedStateArray& a : state_arrays) s.*a.array = {0.25f, 0.5f, 0.75f};
  s.iteration = 40;
  s.settling_since = 30;
  s.secondary_since = 20;
  s.mark_iteration = 10;
  s.mark_growth = 0.5;
  return s;
}

// True when the difference is one line, and about `name`.
bool reports_only(const std::string& difference, const std::string& name) {
  const bool one_line = difference.find('\n') == difference.size() - 1;
  return one_line && difference.rfind(name + ":", 0) == 0;
}

}  // namespace

TEST_CASE("state difference: each array of the state, one entry changed by one ulp, is reported alone",
          "[equivalence]") {
  const SimState base = sample_state();
  CHECK(state_difference(base, base).empty());
  for (const NamedStateArray& a : state_arrays) {
    SimState changed = base;
    float& entry = (changed.*a.array)[1];
    entry = std::nextafter(entry, 1.0f);
    const std::string difference = state_difference(base, changed);
    INFO(a.name << ":\n" << difference);
    CHECK(reports_only(difference, a.name));
  }
}

TEST_CASE("state difference: each scalar of the state is reported alone, a double's sign of zero too",
          "[equivalence]") {
  const SimState base = sample_state();
  for (const NamedStateScalar& s : state_scalars) {
    SimState changed = base;
    std::visit([&](auto member) { changed.*member += 1; }, s.field);
    const std::string difference = state_difference(base, changed);
    INFO(s.name << ":\n" << difference);
    CHECK(reports_only(difference, s.name));
  }
  SimState zero = base, negative_zero = base;
  zero.mark_growth = 0.0;
  negative_zero.mark_growth = -0.0;
  CHECK(reports_only(state_difference(zero, negative_zero), "mark_growth"));
  SimState nan = base;
  nan.mark_growth = std::numeric_limits<double>::quiet_NaN();
  CHECK(state_difference(nan, nan).empty());
}
