// Real-world SVGs: the first files (sorted) of every openclipart category must import, or fail with
// an InputError that names the file. Times are reported, never asserted (machines differ).
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "animpak/error.hpp"
#include "animpak/io.hpp"
#include "openclipart.hpp"
#include "skip.hpp"

namespace fs = std::filesystem;

namespace {

constexpr int kFilesPerCategory = 3;
// The share of the sample that must import: nearly all of it, so that a change that refuses more than a
// few files fails, naming them.
constexpr double kMinImported = 0.95;

std::vector<fs::path> sample_files(const fs::path& root) {
  std::vector<fs::path> categories, picked;
  for (const auto& entry : fs::directory_iterator(root))
    if (entry.is_directory()) categories.push_back(entry.path());
  std::sort(categories.begin(), categories.end());
  for (const auto& category : categories) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(category))
      if (entry.is_regular_file() && entry.path().extension() == ".svg") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    files.resize(std::min<size_t>(files.size(), kFilesPerCategory));
    picked.insert(picked.end(), files.begin(), files.end());
  }
  return picked;
}

}  // namespace

TEST_CASE("openclipart: a sample from every category imports or is refused by name", "[svg][openclipart]") {
  const fs::path root = animpak::test::openclipart_root();
  if (!fs::is_directory(root))
    return animpak::test::skip(root.string() +
                               " is absent (Debian package openclipart-svg); no openclipart file "
                               "was tried");
  const auto files = sample_files(root);
  REQUIRE(files.size() >= 40);
  int imported = 0;
  std::map<std::string, int> refusals;
  std::vector<std::pair<double, std::string>> times;
  std::ostringstream report, refused;
  for (const auto& file : files) {
    const auto start = std::chrono::steady_clock::now();
    try {
      const auto art = animpak::load_svg(file);
      CHECK(!art.paths.empty());
      CHECK(!art.bounds().empty());
      ++imported;
    } catch (const animpak::InputError& e) {
      const std::string what = e.what();
      INFO(what);
      CHECK(what.find(file.string()) == 0);
      // The reason, without the file and element, so equal reasons tally together.
      const auto colon = what.find(": ", what.find(": ") + 2);
      const std::string reason = what.substr(colon == std::string::npos ? 0 : colon + 2);
      ++refusals[reason.substr(0, reason.find(';'))];
      report << "  refused " << file.string() << ": " << what << "\n";
      refused << "  " << what << "\n";
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    times.emplace_back(ms, file.string());
  }
  std::sort(times.rbegin(), times.rend());
  report << imported << " of " << files.size() << " imported, " << files.size() - imported << " refused\n";
  for (const auto& [reason, count] : refusals) report << "  " << count << " x " << reason << "\n";
  report << "slowest:";
  for (size_t i = 0; i < std::min<size_t>(3, times.size()); ++i)
    report << " " << times[i].second << " (" << times[i].first << " ms)";
  WARN(report.str());
  INFO("fewer than " << kMinImported * 100 << " % of the files imported; refused:\n" << refused.str());
  CHECK(imported >= kMinImported * static_cast<double>(files.size()));
}
