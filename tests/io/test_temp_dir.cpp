// The tests' scratch folder (tests/temp_dir.hpp): every test that writes files relies on it to leave
// nothing behind in the system's temp folder.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "temp_dir.hpp"

namespace fs = std::filesystem;
using animpak::test::TempDir;

TEST_CASE("TempDir: a fresh folder of its own under the temp folder, gone with its contents after") {
  fs::path kept;
  {
    const TempDir a("animpak-tempdir-"), b("animpak-tempdir-");
    kept = a.path();
    REQUIRE(fs::is_directory(a.path()));
    CHECK(fs::is_empty(a.path()));
    CHECK(a.path().parent_path() == fs::temp_directory_path());
    CHECK(a.path().filename().string().rfind("animpak-tempdir-", 0) == 0);
    CHECK(a.path() != b.path());
    fs::create_directories(a / "frames" / "deeper");
    std::ofstream(a / "frames" / "deeper" / "frame.png") << "not empty";
    std::ofstream(a / "stats.json") << "{}";
  }
  CHECK_FALSE(fs::exists(kept));
}

TEST_CASE("TempDir: the folder goes also when the test ends early by an exception, as a failed REQUIRE does") {
  fs::path kept;
  try {
    const TempDir dir("animpak-tempdir-");
    kept = dir.path();
    std::ofstream(dir / "half-written.txt") << "x";
    throw std::runtime_error("the test gave up here");
  } catch (const std::runtime_error&) {
  }
  REQUIRE_FALSE(kept.empty());
  CHECK_FALSE(fs::exists(kept));
}
