// A scratch folder for one test: made under the system's temp folder (TMPDIR, else /tmp) with a name no
// other test or process has, and removed with everything in it when the object goes out of scope. Catch2
// ends a test on a failed REQUIRE or an exception by unwinding, so the folder goes then too: a test run
// leaves nothing behind in the temp folder, however often it is repeated.
#pragma once

#include <stdlib.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace animpak::test {

class TempDir {
 public:
  /// `prefix` starts the folder's name (say which test made it when one is left by a crash).
  explicit TempDir(const std::string& prefix = "animpak-test-") {
    // mkdtemp picks the unused name and creates the folder in one step, so two processes never share it.
    std::string name = (std::filesystem::temp_directory_path() / (prefix + "XXXXXX")).string();
    if (::mkdtemp(name.data()) == nullptr)
      throw std::runtime_error("cannot create a temporary folder " + name + ": " + std::strerror(errno));
    path_ = name;
  }
  ~TempDir() {
    std::error_code ignored;  // a destructor must not throw; a folder left behind fails no test
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

}  // namespace animpak::test
