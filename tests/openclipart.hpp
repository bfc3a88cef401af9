// Where the tests find the openclipart collection (Debian's openclipart-svg): ANIMPAK_OPENCLIPART_DIR
// when set, so that a run can point it elsewhere or at nothing (tests/skips/tools-hidden.sh), else the
// package's folder.
#pragma once

#include <cstdlib>
#include <filesystem>

namespace animpak::test {

inline std::filesystem::path openclipart_root() {
  const char* dir = std::getenv("ANIMPAK_OPENCLIPART_DIR");
  return dir != nullptr && *dir != '\0' ? std::filesystem::path(dir) : "/usr/share/openclipart/svg";
}

}  // namespace animpak::test
