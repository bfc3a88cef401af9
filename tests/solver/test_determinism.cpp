// The reference solver is deterministic and resumable bit for bit: two runs of one scene agree byte
// for byte, and a state written to state.bin, read back and continued equals the uninterrupted run.
#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "animpak/checkpoint.hpp"
#include "animpak/scene.hpp"
#include "animpak/sha256.hpp"
#include "animpak/simulation.hpp"
#include "scene/tiny_scenes.hpp"
#include "temp_dir.hpp"

using namespace animpak;

namespace {

// Growth fast enough that elements touch within the run, so repulsion, overlap and paused growth
// take part in what must repeat exactly.
World tiny_world() {
  return make_world(parse_scene(animpak::test::star_scene(3, 5, 9, {"", R"("growth_rate": 2)"}), "tiny.json", "/"));
}

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

void require_identical(const SimState& a, const SimState& b) {
  CHECK(a.iteration == b.iteration);
  CHECK(a.settling_since == b.settling_since);
  CHECK(a.mark_iteration == b.mark_iteration);
  CHECK(a.mark_growth == b.mark_growth);
  CHECK(same_bytes(a.x, b.x));
  CHECK(same_bytes(a.y, b.y));
  CHECK(same_bytes(a.t, b.t));
  CHECK(same_bytes(a.vx, b.vx));
  CHECK(same_bytes(a.vy, b.vy));
  CHECK(same_bytes(a.vt, b.vt));
  CHECK(same_bytes(a.spring_rest, b.spring_rest));
  CHECK(same_bytes(a.growth, b.growth));
}

SimState run_steps(Backend& backend, int steps) {
  for (int i = 0; i < steps; ++i) backend.step();
  return backend.state();
}

}  // namespace

TEST_CASE("reference solver: two runs of the same scene give identical states") {
  const World a = tiny_world(), b = tiny_world();
  auto first = make_reference_backend(a.topology, a.state, a.params);
  auto second = make_reference_backend(b.topology, b.state, b.params);
  const SimState sa = run_steps(*first, 60), sb = run_steps(*second, 60);
  require_identical(sa, sb);
  // Not vacuous: the elements moved and grew.
  CHECK_FALSE(same_bytes(sa.x, a.state.x));
  CHECK(sa.growth[0] > 1.0f);
}

TEST_CASE("reference solver: N steps, state.bin, read back, M more steps equals N + M steps") {
  const World w = tiny_world();
  const int n = 40, m = 35;
  auto whole = make_reference_backend(w.topology, w.state, w.params);
  const SimState uninterrupted = run_steps(*whole, n + m);

  auto before = make_reference_backend(w.topology, w.state, w.params);
  Checkpoint saved;
  saved.scene_text = "{}";
  saved.scene_file = "tiny.json";
  saved.seed = w.seed;
  saved.stop_reason = "running";
  saved.state = run_steps(*before, n);
  const test::TempDir temp("animpak-resume-");
  write_checkpoint(temp / "state.bin", saved);
  const Checkpoint loaded = read_checkpoint(temp / "state.bin");
  require_identical(loaded.state, saved.state);
  CHECK(loaded.seed == w.seed);
  CHECK(loaded.stop_reason == "running");

  auto after = make_reference_backend(w.topology, loaded.state, w.params);
  require_identical(run_steps(*after, m), uninterrupted);
}

TEST_CASE("reference solver: a run resumed in its settling phase stays settling and equals the uninterrupted run") {
  const World w = tiny_world();
  auto whole = make_reference_backend(w.topology, w.state, w.params);
  run_steps(*whole, 30);
  whole->stop_growth();
  const SimState uninterrupted = run_steps(*whole, 40);
  CHECK(uninterrupted.settling_since == 30);

  auto before = make_reference_backend(w.topology, w.state, w.params);
  run_steps(*before, 30);
  before->stop_growth();
  Checkpoint saved;
  saved.scene_text = "{}";
  saved.scene_file = "tiny.json";
  saved.stop_reason = "interrupted";
  saved.state = run_steps(*before, 15);
  const test::TempDir temp("animpak-settle-");
  write_checkpoint(temp / "state.bin", saved);
  const Checkpoint loaded = read_checkpoint(temp / "state.bin");
  CHECK(loaded.state.settling_since == 30);
  auto after = make_reference_backend(w.topology, loaded.state, w.params);
  const SimState resumed = run_steps(*after, 25);
  require_identical(resumed, uninterrupted);
  // Not vacuous: while settling nothing grows.
  for (std::size_t s = 0; s < resumed.growth.size(); ++s) CHECK(resumed.growth[s] <= saved.state.growth[s]);
}

TEST_CASE("state.bin: every counter and mark round-trips, and files of versions 2 to 4 (an FNV checksum) are refused") {
  const World w = tiny_world();
  Checkpoint saved;
  saved.scene_text = "{}";
  saved.scene_file = "tiny.json";
  saved.stop_reason = "gap";
  saved.level_slices = 26;
  saved.state = w.state;
  saved.state.iteration = 700077;
  saved.state.settling_since = 700070;  // values no earlier field holds
  saved.state.secondary_since = 500050;
  saved.state.mark_iteration = 700000;
  saved.state.mark_growth = 2.25;
  saved.state.mark_growth_1 = 2.125, saved.state.mark_growth_2 = 2.0625, saved.state.mark_growth_3 = 2.03125;
  const test::TempDir temp("animpak-version-");
  write_checkpoint(temp / "state.bin", saved);
  const Checkpoint now = read_checkpoint(temp / "state.bin");
  CHECK(now.state.settling_since == 700070);
  CHECK(now.state.secondary_since == 500050);
  CHECK(now.state.mark_growth_1 == 2.125);
  CHECK(now.state.mark_growth_2 == 2.0625);
  CHECK(now.state.mark_growth_3 == 2.03125);
  CHECK(now.level_slices == 26);

  std::ifstream in(temp / "state.bin", std::ios::binary);
  const std::string current((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  {
    // Version 5 (animpak 0.16 to 0.18) has no level: the same bytes without it read at the scene's slices.
    const std::size_t level_at = current.find("gap") + 3;
    std::string v5 = current.substr(0, level_at) + current.substr(level_at + 4, current.size() - 64 - level_at - 4);
    v5[8] = 5;
    v5 += sha256_hex(v5);
    const std::filesystem::path file = temp / "v5.bin";
    std::ofstream(file, std::ios::binary) << v5;
    const Checkpoint old = read_checkpoint(file);
    CHECK(old.level_slices == 0);
    CHECK(old.state.iteration == 700077);
    CHECK(old.state.mark_growth_3 == 2.03125);
  }
  // The same body under an older version number with the FNV-1a checksum those versions ended in: a
  // checksum anyone can recompute after changing a value, so these files are no longer trusted.
  for (const int version : {2, 3, 4}) {
    INFO("version " << version);
    std::string bytes = current.substr(0, current.size() - 64);
    bytes[8] = static_cast<char>(version);
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (const unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ull;
    bytes.append(reinterpret_cast<const char*>(&h), sizeof h);
    const std::filesystem::path file = temp / ("v" + std::to_string(version) + ".bin");
    std::ofstream(file, std::ios::binary) << bytes;
    CHECK_THROWS_WITH(read_checkpoint(file),
                      Catch::Matchers::Contains("state format version " + std::to_string(version) + " (animpak 0.15") &&
                          Catch::Matchers::Contains("pack the scene again"));
  }
}
