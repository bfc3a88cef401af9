// animpak validate as a user runs it: PoCL matches the reference bit for bit on a tiny scene, the JSON
// of --all-devices holds one row per device, a kernel changed in one arithmetic line is caught and named
// with exit code 4, and wrong requests get their usage and input codes.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <fstream>

#include "animpak/compare.hpp"
#include "animpak/error.hpp"
#include "animpak/opencl.hpp"
#include "run_animpak.hpp"
#include "scene/tiny_scenes.hpp"
#include "skip.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;

namespace {

// Three stars, six slices and a coarse grid: a few hundred vertices, quick even under the sanitizers.
class Scene {
 public:
  Scene() : dir_("animpak-validate-") {
    std::ofstream(dir_ / "scene.json") << animpak::test::star_scene(3, 6, 1, {"", R"("cell_size": 0.1)"});
  }
  std::string file() const { return (dir_ / "scene.json").string(); }
  fs::path dir() const { return dir_.path(); }

 private:
  animpak::test::TempDir dir_;
};

constexpr const char* no_pocl = "PoCL is not installed (Debian package pocl-opencl-icd); validate is not tested on it";

bool have_pocl() {
  try {
    return !animpak::choose_device("pocl").reference;
  } catch (const animpak::UsageError&) {
    return false;
  }
}

}  // namespace

TEST_CASE("animpak validate --device pocl: identical to the reference, exit 0") {
  if (!have_pocl()) return animpak::test::skip(no_pocl);
  const Scene scene;
  const CommandResult r = run_animpak("validate " + scene.file() + " --device pocl --steps 5");
  INFO(r.out << r.err);
  CHECK(r.code == 0);
  CHECK_THAT(r.out, Contains("identical for 5 steps"));
  CHECK_THAT(r.out, Contains("verdict: bit-identical"));
  CHECK_THAT(r.out, Contains("springs"));
  CHECK_THAT(r.out, Contains("total"));
}

TEST_CASE("animpak validate --all-devices --json: one row per OpenCL device") {
  const auto devices = animpak::list_devices();
  if (devices.empty())
    return animpak::test::skip(
        "no OpenCL device (Debian package pocl-opencl-icd): --all-devices has nothing to "
        "validate");
  const Scene scene;
  const CommandResult r = run_animpak("validate " + scene.file() + " --all-devices --json --steps 2");
  INFO(r.out << r.err);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  REQUIRE(j.at("devices").size() == devices.size());
  for (std::size_t i = 0; i < devices.size(); ++i) {
    const nlohmann::json& row = j["devices"][i];
    CHECK(row.at("device") == devices[i].name);
    CHECK(row.at("driver") == devices[i].driver);
    CHECK(row.at("forces").size() == animpak::breakdown_forces.size() + 1);  // and the total
    if (row.at("platform") == "Portable Computing Language") {
      CHECK(row.at("verdict") == "bit-identical");
      CHECK(row.at("max_ulp") == 0);
      CHECK(row.at("first_differing_step").is_null());
    }
  }
}

TEST_CASE("animpak validate: a spring kernel reassociated in one line differs, exit 4, named springs") {
  if (!have_pocl()) return animpak::test::skip(no_pocl);
  const Scene scene;
  const fs::path kernels = scene.dir() / "kernels";
  fs::copy(fs::path(ANIMPAK_SOURCE_DIR) / "kernels", kernels);
  const std::string original = read_text(kernels / "springs.cl");
  const std::string line = "stiffness * inv_len * s * (stretch * stretch)";
  const auto at = original.find(line);
  REQUIRE(at != std::string::npos);
  std::string perturbed = original;
  // Same value in real arithmetic, different float rounding: exactly what validate must notice.
  perturbed.replace(at, line.size(), "stiffness * inv_len * (s * stretch) * stretch");
  std::ofstream(kernels / "springs.cl", std::ios::trunc) << perturbed;

  const CommandResult r =
      run_animpak("validate " + scene.file() + " --device pocl --steps 3", "ANIMPAK_KERNEL_DIR=" + kernels.string());
  INFO(r.out << r.err);
  CHECK(r.code == static_cast<int>(animpak::ExitCode::differs));
  CHECK_THAT(r.out, Contains("verdict: DIFFERS: springs"));
  CHECK_THAT(r.out, Contains("state: first differs after step "));
}

TEST_CASE(
    "animpak validate: --device reference and --device with --all-devices are usage errors, a bad scene is input") {
  const Scene scene;
  const CommandResult reference = run_animpak("validate " + scene.file() + " --device reference");
  CHECK(reference.code == 1);
  CHECK_THAT(reference.err, Contains("--device reference"));
  CHECK(run_animpak("validate " + scene.file() + " --device pocl --all-devices").code == 1);
  CHECK(run_animpak("validate " + scene.file() + " --device no-such-device-anywhere").code == 1);
  const CommandResult missing = run_animpak("validate " + (scene.dir() / "missing.json").string());
  CHECK(missing.code == 2);
  CHECK(run_animpak("validate " + scene.file() + " --steps 0").code == 1);
}
