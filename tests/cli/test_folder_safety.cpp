// What survives (docs/cli.md, "What survives"): a kill at any moment, a full disk, a second run on the same
// folder, links and special files planted in a copied folder, and states changed on purpose. Each case is
// the probe that found the defect, run as a user would.
#include <sys/stat.h>

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "animpak/checkpoint.hpp"
#include "animpak/sha256.hpp"
#include "packed_folder.hpp"
#include "run_animpak.hpp"
#include "scene/tiny_scenes.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;

namespace {

// A folder per test case holding scene.json: three stars growing ten times slower than by default, so a run
// is still going when the test signals or kills it, even on a fast machine.
class SlowBox {
 public:
  explicit SlowBox(const std::string& name) : dir_("animpak-safety-" + name + "-") {
    std::ofstream(dir_ / "scene.json") << animpak::test::star_scene(3, 5, 2, {"", R"("growth_rate": 0.001)"});
  }
  std::string scene() const { return (dir_ / "scene.json").string(); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

 private:
  animpak::test::TempDir dir_;
};

void overwrite(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

// The shell words that start `animpak pack` in the background, wait until `file` exists (at most 60 s) and
// then run `then` with the pack's pid in $p; the command's exit code is then's.
std::string while_packing(const std::string& pack_args, const std::string& file, const std::string& then) {
  return std::string("bash -c '") + ANIMPAK_EXE + " " + pack_args +
         " >/dev/null 2>&1 & p=$!; for i in $(seq 600); do " + "[ -s " + file + " ] && break; sleep 0.1; done; " +
         then + "'";
}

}  // namespace

TEST_CASE("animpak pack: killed outright after a checkpoint, --resume ends on the bytes of a run never stopped") {
  const SlowBox box("kill");
  const std::string killed = box.path("killed"), whole = box.path("whole");
  // A checkpoint at every statistics check; the kill comes as soon as the first is on disk.
  const CommandResult kill = run_command(while_packing(
      "pack " + box.scene() + " --out " + killed + " --device reference --no-render " + "--checkpoint-every 0",
      killed + "/.pack-new/state.bin", "kill -9 $p; wait $p; exit 0"));
  REQUIRE(kill.code == 0);
  // Nothing was swapped in: no state.bin of the folder's own, the killed run's state beside it.
  CHECK_FALSE(fs::exists(killed + "/state.bin"));
  REQUIRE(fs::exists(killed + "/.pack-new/state.bin"));
  const CommandResult resumed = run_animpak("pack --resume " + killed +
                                            " --device reference --no-render "
                                            "--max-iterations 3000");
  INFO(resumed.err);
  REQUIRE(resumed.code == 0);
  CHECK_THAT(resumed.err, Contains("resuming"));
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + whole +
                      " --device reference --no-render "
                      "--max-iterations 3000")
              .code == 0);
  const std::string a = read_text(killed + "/state.bin"), b = read_text(whole + "/state.bin");
  REQUIRE(a.size() > 1000);
  CHECK(a == b);
  CHECK_FALSE(fs::exists(killed + "/.pack-new"));
}

TEST_CASE("animpak pack: SIGTERM saves like Ctrl-C, and a second run on a busy folder is refused at once") {
  const SlowBox box("term");
  const std::string out = box.path("out");
  // While the first pack runs: a second pack, a render and a report are refused, naming the first.
  const CommandResult busy = run_command(while_packing(
      "pack " + box.scene() + " --out " + out + " --device reference --no-render",
      out + "/.pack-new/input/manifest.json",
      std::string(ANIMPAK_EXE) + " pack " + box.scene() + " --out " + out + " --force --no-render; a=$?; " +
          ANIMPAK_EXE + " render " + out + "; b=$?; kill -TERM $p; wait $p; c=$?; echo $a $b $c"));
  INFO(busy.err);
  CHECK(busy.out == "2 2 143\n");
  CHECK_THAT(busy.err,
             Contains(out + ": another animpak is using this folder (pid ") && Contains(": animpak pack " + out + ")"));
  // The terminated run saved its state and inputs, and resumes.
  CHECK(fs::exists(out + "/state.bin"));
  CHECK(fs::exists(out + "/input/manifest.json"));
  const CommandResult resumed =
      run_animpak("pack --resume " + out + " --device reference --no-render --max-iterations 20");
  INFO(resumed.err);
  CHECK(resumed.code == 0);
}

TEST_CASE("animpak pack --force: killed midway leaves the packing before whole, and the new one resumes") {
  const SlowBox box("force");
  const std::string out = box.path("out");
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + out +
                      " --max-iterations 30 --frames 2 --size 16 "
                      "--format png --device reference")
              .code == 0);
  const std::string state = read_text(out + "/state.bin"), manifest = read_text(out + "/input/manifest.json");
  const std::string frame = read_text(out + "/frames/frame_0000.png");
  REQUIRE(run_command(while_packing("pack " + box.scene() + " --out " + out +
                                        " --force --seed 7 --device reference --no-render --checkpoint-every 0",
                                    out + "/.pack-new/state.bin", "kill -9 $p; wait $p; exit 0"))
              .code == 0);
  CHECK(read_text(out + "/state.bin") == state);
  CHECK(read_text(out + "/input/manifest.json") == manifest);
  CHECK(read_text(out + "/frames/frame_0000.png") == frame);
  const CommandResult render = run_animpak("render " + out + " --frames 2 --size 16 --format png");
  CHECK(render.code == 0);
  // The new packing, not the one before, is what --resume continues; then it replaces the one before.
  const CommandResult resumed =
      run_animpak("pack --resume " + out + " --device reference --no-render --max-iterations 40");
  INFO(resumed.err);
  REQUIRE(resumed.code == 0);
  CHECK(read_text(out + "/state.bin") != state);
  CHECK_FALSE(fs::exists(out + "/frames/frame_0000.png"));
  CHECK_FALSE(fs::exists(out + "/.pack-new"));
}

TEST_CASE("recover_folder: a swap cut short by a kill is finished, one not yet marked whole is undone") {
  const animpak::test::TempDir dir("animpak-safety-swap-");
  const auto make = [](const fs::path& folder, const std::string& tag) {
    fs::create_directories(folder / "input");
    overwrite(folder / "state.bin", tag);
    overwrite(folder / "input/manifest.json", tag);
  };
  // Killed with the old input/ already moved aside and the new state not yet in place.
  make(dir.path(), "old");
  fs::create_directories(dir / "frames");
  overwrite(dir / "frames/frame_0000.png", "old");
  overwrite(dir / "stats.json", "old");
  make(dir / ".pack-new", "new");
  overwrite(dir / ".pack-new/complete", "");
  fs::create_directories(dir / ".pack-old");
  fs::rename(dir / "input", dir / ".pack-old/input");
  overwrite(dir / "stats.json.partial", "cut");  // a write killed midway
  overwrite(dir / "notes.partial", "mine");
  CHECK(animpak::cli::recover_folder(dir.path()));
  CHECK_FALSE(fs::exists(dir / "stats.json.partial"));
  CHECK(read_text(dir / "notes.partial") == "mine");
  CHECK(read_text(dir / "state.bin") == "new");
  CHECK(read_text(dir / "input/manifest.json") == "new");
  CHECK_FALSE(fs::exists(dir / "frames/frame_0000.png"));  // the old packing's frames
  CHECK_FALSE(fs::exists(dir / "stats.json"));
  CHECK_FALSE(fs::exists(dir / ".pack-new"));
  CHECK_FALSE(fs::exists(dir / ".pack-old"));
  CHECK_FALSE(animpak::cli::recover_folder(dir.path()));

  // Not marked whole: the packing before stays, the unfinished one waits for --resume.
  make(dir / ".pack-new", "newer");
  CHECK_FALSE(animpak::cli::recover_folder(dir.path()));
  CHECK(read_text(dir / "state.bin") == "new");
  CHECK(animpak::cli::has_unfinished_pack(dir.path()));
}

TEST_CASE("animpak render: on a full disk the render before stays whole and the error names the file") {
  const SlowBox box("full");
  const std::string out = box.path("out");
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + out +
                      " --max-iterations 20 --frames 3 --size 48 "
                      "--format png,gif,lottie")
              .code == 0);
  const std::string frame = read_text(out + "/frames/frame_0000.png"), gif = read_text(out + "/animation.gif"),
                    lottie = read_text(out + "/animation.json"), stats = read_text(out + "/stats.json");
  // A file size limit fails every write past it as a full disk does (EFBIG, with SIGXFSZ ignored).
  for (const char* const limit : {"4", "40"}) {
    INFO("ulimit -f " << limit);
    const CommandResult full =
        run_command("bash -c \"trap '' XFSZ; ulimit -f " + std::string(limit) + "; " + ANIMPAK_EXE + " render " + out +
                    " --frames 5 --size 256 --format png,gif,lottie\"");
    CHECK(full.code == 2);
    CHECK_THAT(full.err, Contains("cannot write it: File too large") && Contains("free disk space"));
    CHECK(read_text(out + "/frames/frame_0000.png") == frame);
    CHECK(read_text(out + "/animation.gif") == gif);
    CHECK(read_text(out + "/animation.json") == lottie);
    CHECK(read_text(out + "/stats.json") == stats);
    CHECK_FALSE(fs::exists(out + "/frames/frame_0004.png"));
  }
}

TEST_CASE("animpak render: links, FIFOs and a missing manifest entry in a folder are refused, not followed") {
  const SlowBox box("links");
  const std::string out = box.path("out");
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + out + " --max-iterations 10 --no-render").code == 0);
  const fs::path art = fs::path(out) / "input/art/star.svg";
  const std::string original = read_text(art);
  const auto render = [&] { return run_animpak("render " + out + " --frames 1 --size 16 --format png"); };

  // An art file linked to a file outside the folder.
  overwrite(box.path("outside.svg"), original);
  fs::remove(art);
  fs::create_symlink(box.path("outside.svg"), art);
  CommandResult r = render();
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains(art.string() + ": is a symbolic link"));
  fs::remove(art);

  // A FIFO in its place: refused at once, not waited on (timeout's 124 would mean a hang).
  REQUIRE(::mkfifo(art.c_str(), 0644) == 0);
  r = run_command("timeout 60 " + std::string(ANIMPAK_EXE) + " render " + out + " --frames 1 --size 16 --format png");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("not a regular file"));
  fs::remove(art);
  overwrite(art, original);

  // state.bin as a FIFO.
  const std::string state = read_text(out + "/state.bin");
  fs::remove(out + "/state.bin");
  REQUIRE(::mkfifo((out + "/state.bin").c_str(), 0644) == 0);
  r = run_command("timeout 60 " + std::string(ANIMPAK_EXE) + " render " + out + " --frames 1 --size 16 --format png");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("state.bin: not a regular file"));
  fs::remove(out + "/state.bin");
  overwrite(out + "/state.bin", state);

  // frames/ linked to another folder: nothing written there.
  fs::create_directories(box.path("elsewhere"));
  overwrite(box.path("elsewhere/frame_0000.png"), "mine");
  fs::create_directory_symlink(box.path("elsewhere"), fs::path(out) / "frames");
  r = render();
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("frames: is a symbolic link"));
  CHECK(read_text(box.path("elsewhere/frame_0000.png")) == "mine");
  // Nor does a resume, which removes the frames of the state it continues from.
  CHECK(run_animpak("pack --resume " + out + " --no-render --max-iterations 20").code == 0);
  CHECK(read_text(box.path("elsewhere/frame_0000.png")) == "mine");
  fs::remove(fs::path(out) / "frames");

  // A manifest entry deleted: the art is not read from the scene's original place.
  const fs::path manifest = fs::path(out) / "input/manifest.json";
  const std::string with_entry = read_text(manifest);
  nlohmann::json m = nlohmann::json::parse(with_entry);
  m["art"] = nlohmann::json::array();
  overwrite(manifest, m.dump());
  r = render();
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("names no copy of art"));
  overwrite(manifest, with_entry);
  CHECK(render().code == 0);
}

TEST_CASE("animpak render: a state whose values a packing cannot hold is refused though its checksum is valid") {
  const SlowBox box("values");
  const std::string out = box.path("out");
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + out + " --max-iterations 10 --no-render").code == 0);
  const std::string good = read_text(out + "/state.bin");
  // The layout (include/animpak/checkpoint.hpp): magic, version, three strings, the level and the counters,
  // then x.
  std::size_t at = 8 + 4;
  const auto skip_string = [&] {
    std::uint64_t n;
    std::memcpy(&n, good.data() + at, 8);
    at += 8 + n;
  };
  skip_string();        // the scene
  skip_string();        // its path
  at += 8;              // the seed
  skip_string();        // the stop reason
  at += 4;              // the level
  at += 4 * 8 + 4 * 8;  // iteration, settling, secondary, mark; four growth marks
  at += 8;              // x's length
  const auto with_x = [&](float value) {
    std::string state = good.substr(0, good.size() - 64);
    std::memcpy(state.data() + at, &value, sizeof value);
    return state + animpak::sha256_hex(state);
  };
  REQUIRE(with_x([&] {
            float x;
            std::memcpy(&x, good.data() + at, 4);
            return x;
          }()) == good);  // the offset is x's first value: rewriting it unchanged gives the same file
  for (const float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(), 3e30f}) {
    INFO(bad);
    overwrite(out + "/state.bin", with_x(bad));
    const CommandResult r = run_animpak("render " + out + " --frames 1 --size 16 --format png");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains("its x value 0 is") && Contains("not a finite number of a packing"));
    const CommandResult resume = run_animpak("pack --resume " + out + " --no-render --max-iterations 20");
    CHECK(resume.code == 2);
  }

  // Arrays of the wrong size, checksummed as animpak writes them: the message names the array and both sizes.
  overwrite(out + "/state.bin", good);
  animpak::Checkpoint cut = animpak::read_checkpoint(out + "/state.bin");
  const std::size_t ends = cut.state.spring_rest.size();
  cut.state.spring_rest.resize(ends - 2);
  animpak::write_checkpoint(out + "/state.bin", cut);
  const CommandResult r = run_animpak("render " + out + " --frames 1 --size 16 --format png");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("builds " + std::to_string(ends) + " spring ends but the state holds " +
                             std::to_string(ends - 2)));
}

TEST_CASE("animpak pack: a file in place of --out, a folder in place of state.bin, a blown-up step exit 2") {
  const SlowBox box("codes");
  overwrite(box.path("a-file"), "mine");
  CommandResult r = run_animpak("pack " + box.scene() + " --out " + box.path("a-file") + " --no-render");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains(box.path("a-file")));
  CHECK(read_text(box.path("a-file")) == "mine");

  fs::create_directories(box.path("dir/state.bin"));
  r = run_animpak("render " + box.path("dir"));
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("state.bin: not a regular file"));

  // A stiffness in range that makes the first steps blow up: the scene's fault, said with its file.
  overwrite(box.path("stiff.json"), animpak::test::star_scene(3, 5, 2, {"", R"("k_edge": 1e300)"}));
  r = run_animpak("pack " + box.path("stiff.json") + " --out " + box.path("stiff") +
                  " --device reference --no-render --max-iterations 200");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("stiff.json: the simulation produced NaN/Inf"));

  overwrite(box.path("huge.json"), animpak::test::star_scene(3, 5, 2, {"", R"("k_edge": 1e999)"}));
  r = run_animpak("check " + box.path("huge.json"));
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("huge.json: number overflow") && Contains("1e999"));
}
