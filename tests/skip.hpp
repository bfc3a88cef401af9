// How a test says it could not run because something it needs is absent (an optional tool, a data
// package, an OpenCL device): it prints one line that starts with skip_marker and returns. Every stage's
// ctest tests look for that line (SKIP_REGULAR_EXPRESSION, tests/CMakeLists.txt), so ctest lists the
// test as skipped instead of passed. CI installs everything, so there (CI=true) a skip fails the test
// instead: a missing install step cannot hide in the list of skipped tests (docs/testing.md).
#pragma once

#include <catch2/catch.hpp>

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

namespace animpak::test {

/// The start of the skip line; ANIMPAK_SKIP_MARKER in tests/CMakeLists.txt is the same text.
inline constexpr const char* skip_marker = "animpak-test skipped: ";

/// CI=true: the environment CI services set, where a skip is a failure.
inline bool skips_fail() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::strcmp(ci, "true") == 0;
}

/// Reports the test as skipped, `why` naming what is absent and where it comes from; the caller
/// returns at once (`return skip(...)`). Under CI=true it fails the test with the same reason, in
/// words that do not contain the marker (ctest would count the failure as a skip).
inline void skip(const std::string& why) {
  if (skips_fail()) FAIL("CI=true, where nothing may skip, and this test cannot run: " << why);
  std::cout << skip_marker << why << std::endl;
}

}  // namespace animpak::test
