// An output folder is one run, and it travels (docs/cli.md, "The output folder"): a render replaces every
// rendered file of the run before and nothing else, pack does not overwrite a packing unasked, a copied
// folder renders from its input/ copies, and a resume refuses what cannot apply and leaves a finished
// packing alone.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "console.hpp"
#include "pack_output.hpp"
#include "packed_folder.hpp"
#include "run_animpak.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;

namespace {

// A scene whose art sits beside it and one folder up (scenes/scene.json, art/, scenes/star.svg): references
// a copied output folder can no longer resolve once the art is gone.
class ArtBox {
 public:
  explicit ArtBox(const std::string& name, const std::string& params = "") : dir_("animpak-folder-" + name + "-") {
    fs::create_directories(dir_ / "scenes");
    fs::create_directories(dir_ / "art");
    fs::copy_file(std::string(ANIMPAK_SOURCE_DIR) + "/examples/default/star.svg", dir_ / "scenes/star.svg");
    fs::copy_file(shapes_dir() + "/heart-container.path", dir_ / "art/heart.path");
    std::ofstream(dir_ / "scenes/scene.json")
        << R"({"container": {"art": "../art/heart.path"}, "elements": [{"name": "star", "art": "star.svg",)"
        << R"( "count": 3}], "seed": 2, "slices": 5, "params": {)" << params << "}}";
  }
  std::string scene() const { return (dir_ / "scenes/scene.json").string(); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

 private:
  animpak::test::TempDir dir_;
};

std::string file_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int files_with_extension(const fs::path& dir, const std::string& extension) {
  int n = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) n += e.path().extension() == extension;
  return n;
}

}  // namespace

TEST_CASE("animpak render: replaces every rendered file of the run before, keeps the user's own") {
  const ArtBox box("render");
  const std::string out = box.path("out");
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + out +
                      " --device reference --max-iterations 20 --frames 6"
                      " --size 32 --format png,svg,gif,lottie,svg-anim")
              .code == 0);
  std::ofstream(out + "/notes.txt") << "mine";
  std::ofstream(out + "/frames/mine.txt") << "mine";
  const CommandResult rendered = run_animpak("render " + out + " --frames 3 --size 16 --format png");
  REQUIRE(rendered.code == 0);
  CHECK(files_with_extension(out + "/frames", ".png") == 3);
  CHECK(files_with_extension(out + "/frames", ".svg") == 0);
  for (const char* stale : {"animation.gif", "animation.json", "animation.svg", ".render-partial"})
    CHECK_FALSE(fs::exists(out + "/" + stale));
  CHECK(file_bytes(out + "/notes.txt") == "mine");
  CHECK(file_bytes(out + "/frames/mine.txt") == "mine");
  const nlohmann::json stats = nlohmann::json::parse(file_bytes(out + "/stats.json"));
  CHECK(stats["frames"].size() == 3);
}

TEST_CASE("animpak render and pack: list the files of the run before they removed, beside those they wrote") {
  const ArtBox box("removed");
  const std::string out = box.path("out");
  const CommandResult packed = run_animpak("pack " + box.scene() + " --out " + out +
                                           " --device reference --max-iterations 10 --frames 3 --size 16"
                                           " --format png,gif");
  REQUIRE(packed.code == 0);
  CHECK_THAT(packed.err, !Contains("removed:"));  // a fresh folder: nothing of a run before
  std::ofstream(out + "/notes.txt") << "mine";
  std::ofstream(out + "/frames/mine.txt") << "mine";
  // The formats of docs/animation-formats.md in place of the frames and the GIF: both named as gone.
  const CommandResult animated =
      run_animpak("render " + out + " --frames 2 --size 16 --format lottie,svg-anim,dotlottie");
  REQUIRE(animated.code == 0);
  CHECK_THAT(animated.err, Contains("animation.lottie  ") &&
                               Contains("\n  removed:          frames/ (3 PNG frames), animation.gif\n"));
  CHECK_THAT(animated.err, !Contains("notes.txt") && !Contains("mine.txt"));
  // A file written again under its name is listed as written, not as removed.
  const CommandResult lottie = run_animpak("render " + out + " --frames 2 --size 16 --format dotlottie");
  REQUIRE(lottie.code == 0);
  CHECK_THAT(lottie.err, Contains("\n  removed:          animation.json, animation.svg\n"));
  // A pack over the packing removes its rendered files with it, also when it renders nothing.
  const CommandResult again = run_animpak("pack " + box.scene() + " --out " + out +
                                          " --device reference --max-iterations 5 --no-render --force");
  REQUIRE(again.code == 0);
  CHECK_THAT(again.err, Contains("\n  removed:          animation.lottie\n"));
  CHECK(file_bytes(out + "/notes.txt") == "mine");
  CHECK(file_bytes(out + "/frames/mine.txt") == "mine");
}

TEST_CASE("animpak pack: refuses a folder holding a packing, --force replaces it with its frames") {
  const ArtBox box("force");
  const std::string out = box.path("out");
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + out +
                      " --device reference --max-iterations 20 --frames 2"
                      " --size 16 --format png")
              .code == 0);
  const std::string state = file_bytes(out + "/state.bin");
  const CommandResult again = run_animpak("pack " + box.scene() + " --out " + out + " --max-iterations 10 --no-render");
  CHECK(again.code == 1);
  CHECK_THAT(again.err, Contains(out) && Contains("--force") && Contains("--resume"));
  CHECK(file_bytes(out + "/state.bin") == state);
  CHECK(fs::exists(out + "/frames/frame_0000.png"));
  // Overwriting without rendering must not leave the old frames beside the new state.
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + out +
                      " --device reference --max-iterations 10 --no-render"
                      " --force")
              .code == 0);
  CHECK(file_bytes(out + "/state.bin") != state);
  CHECK_FALSE(fs::exists(out + "/frames"));
}

TEST_CASE("animpak render: a copied folder renders from input/ after its art is gone, and --scene is checked") {
  const ArtBox box("travel");
  const std::string out = box.path("out");
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + out + " --device reference --max-iterations 10 --no-render")
              .code == 0);
  CHECK(fs::exists(out + "/input/manifest.json"));
  fs::copy(out, box.path("copy"), fs::copy_options::recursive);
  fs::rename(box.path("scenes"), box.path("moved-scenes"));
  fs::rename(box.path("art"), box.path("moved-art"));
  CHECK(run_animpak("render " + box.path("copy") + " --frames 1 --size 16 --format png").code == 0);
  // A folder without input/ (packed before it existed) says how to point at the scene.
  fs::copy(out, box.path("old"), fs::copy_options::recursive);
  fs::remove_all(box.path("old") + "/input");
  const CommandResult old = run_animpak("render " + box.path("old") + " --frames 1 --size 16 --format png");
  CHECK(old.code == 2);
  CHECK_THAT(old.err, Contains("heart.path") && Contains("--scene FILE"));

  // --scene: the moved scene with its art beside it renders; an edited art file is refused unless forced.
  fs::rename(box.path("moved-art"), box.path("art"));
  const std::string moved = box.path("moved-scenes") + "/scene.json";
  CHECK(run_animpak("render " + out + " --scene " + moved + " --frames 1 --size 16 --format png").code == 0);
  std::ofstream(box.path("moved-scenes") + "/star.svg", std::ios::app) << "<!-- edited -->\n";
  const CommandResult edited =
      run_animpak("render " + out + " --scene " + moved + " --frames 1 --size 16 --format png");
  CHECK(edited.code == 2);
  CHECK_THAT(edited.err, Contains("star.svg") && Contains("SHA-256") && Contains("--force"));
  CHECK(run_animpak("render " + out + " --scene " + moved + " --force --frames 1 --size 16 --format png").code == 0);
}

TEST_CASE("animpak pack --resume: a finished packing is left alone, --seed and SCENE are refused") {
  const ArtBox box("finished", R"("stop_growth": 1.2)");
  const std::string out = box.path("out");
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + out + " --device reference --no-render").code == 0);
  const std::string state = file_bytes(out + "/state.bin"), stats = file_bytes(out + "/stats.json");
  const CommandResult resumed = run_animpak("pack --resume " + out + " --device reference --no-render");
  CHECK(resumed.code == 0);
  CHECK_THAT(resumed.err, Contains("finished") && Contains("growth"));
  CHECK(file_bytes(out + "/state.bin") == state);
  CHECK(file_bytes(out + "/stats.json") == stats);

  const CommandResult seeded = run_animpak("pack --resume " + out + " --seed 99 --no-render");
  CHECK(seeded.code == 1);
  CHECK_THAT(seeded.err, Contains("--seed"));
  const CommandResult scene = run_animpak("pack " + box.scene() + " --resume " + out + " --no-render");
  CHECK(scene.code == 1);
  CHECK_THAT(scene.err, Contains("SCENE"));
  CHECK(file_bytes(out + "/state.bin") == state);
}

TEST_CASE("animpak pack: Ctrl-C prints the resume command, and the resumed run continues the count and the clock") {
  // Growing ten times slower than by default, so that it cannot reach its stop within the two runs below
  // on an idle machine either (at the default rate, with 0.6.0's wall, the resumed run finished within its
  // four seconds once).
  const ArtBox box("interrupt", R"("growth_rate": 0.001)");
  const std::string out = box.path("out");
  // SIGINT after four seconds, well into the simulation of this tiny scene on the reference solver even on
  // a loaded machine.
  const std::string interrupt = "timeout --preserve-status -s INT 4 ";
  const CommandResult first = run_command(interrupt + ANIMPAK_EXE + " pack " + box.scene() + " --out " + out +
                                          " --device reference --no-render");
  REQUIRE(first.code == 130);
  CHECK_THAT(first.err, Contains("animpak pack --resume " + out));
  const nlohmann::json before = nlohmann::json::parse(file_bytes(out + "/stats.json"));
  const CommandResult second = run_command(interrupt + ANIMPAK_EXE + " pack --resume " + out +
                                           " --device reference"
                                           " --no-render");
  REQUIRE(second.code == 130);
  CHECK_THAT(second.err, Contains("resuming"));
  CHECK_THAT(second.err, !Contains("seeded"));
  const nlohmann::json after = nlohmann::json::parse(file_bytes(out + "/stats.json"));
  CHECK(after["iterations"].get<int>() > before["iterations"].get<int>());
  CHECK(after["seconds"]["simulation"].get<double>() > before["seconds"]["simulation"].get<double>() + 1.0);
}

TEST_CASE("install_rendered: an interrupted render leaves the one before whole, a complete one replaces it") {
  const animpak::test::TempDir dir("animpak-folder-swap-");
  fs::create_directories(dir / "frames");
  for (const char* name : {"frames/frame_0000.png", "frames/frame_0001.png", "frames/frame_0001.svg", "animation.gif",
                           "animation.json", "frames/mine.png", "notes.txt"})
    std::ofstream(dir / name) << "old";
  // A render cut off midway: what it wrote stays in the scratch folder, the next one starts it afresh.
  fs::path scratch = animpak::cli::render_scratch(dir.path());
  fs::create_directories(scratch / "frames");
  std::ofstream(scratch / "frames/frame_0000.png") << "cut";
  CHECK(file_bytes(dir / "frames/frame_0001.png") == "old");
  scratch = animpak::cli::render_scratch(dir.path());
  CHECK(fs::is_empty(scratch));
  fs::create_directories(scratch / "frames");
  std::ofstream(scratch / "frames/frame_0000.png") << "new";
  std::ofstream(scratch / "animation.mp4") << "new";
  const std::vector<fs::path> removed = animpak::cli::install_rendered(scratch, dir.path());
  // What it removed, the frame it wrote again included; never the user's own files.
  CHECK(removed == std::vector<fs::path>{"frames/frame_0000.png", "frames/frame_0001.png", "frames/frame_0001.svg",
                                         "animation.gif", "animation.json"});
  CHECK(file_bytes(dir / "frames/frame_0000.png") == "new");
  CHECK(file_bytes(dir / "animation.mp4") == "new");
  for (const char* stale : {"frames/frame_0001.png", "frames/frame_0001.svg", "animation.gif", "animation.json"})
    CHECK_FALSE(fs::exists(dir / stale));
  CHECK(file_bytes(dir / "frames/mine.png") == "old");
  CHECK(file_bytes(dir / "notes.txt") == "old");
  CHECK_FALSE(fs::exists(scratch));
  CHECK_THAT(animpak::cli::written_files(dir.path(), animpak::cli::WrittenBy::render, removed),
             Contains("\n  removed:          frames/ (1 PNG and 1 SVG frames), animation.gif,\n"
                      "                    animation.json\n"));
}

TEST_CASE("animpak --help: lists exit code 130") { CHECK_THAT(run_animpak("--help").out, Contains("130")); }

TEST_CASE("animpak pack: slips in the frame options or an input/ in the way fail before any packing") {
  const ArtBox box("early");
  const std::string out = box.path("out");
  const CommandResult colour =
      run_animpak("pack " + box.scene() + " --out " + out + " --device reference --max-iterations 10 --background red");
  CHECK(colour.code == 1);
  CHECK_THAT(colour.err, Contains("--background"));
  const CommandResult mp4 = run_animpak("pack " + box.scene() + " --out " + out +
                                        " --device reference --max-iterations 10 --background none --format mp4");
  CHECK(mp4.code == 1);
  CHECK_THAT(mp4.err, Contains("MP4"));
  CHECK_FALSE(fs::exists(out + "/state.bin"));
  fs::create_directories(out + "/input");
  std::ofstream(out + "/input/mine.svg") << "<svg/>";
  const CommandResult in_the_way =
      run_animpak("pack " + box.scene() + " --out " + out + " --device reference --max-iterations 10 --no-render");
  CHECK(in_the_way.code == 2);
  CHECK_THAT(in_the_way.err, Contains(out + "/input"));
  CHECK_FALSE(fs::exists(out + "/state.bin"));
  CHECK(file_bytes(out + "/input/mine.svg") == "<svg/>");
}

TEST_CASE("animpak pack: a fresh --out keeps the user's own files of rendered names, and stats.json is this run's") {
  const ArtBox box("fresh");
  const std::string out = box.path("out");
  fs::create_directories(out + "/frames");
  std::ofstream(out + "/animation.gif") << "mine";
  std::ofstream(out + "/frames/frame_0000.png") << "mine";
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + out + " --device reference --max-iterations 10 --no-render")
              .code == 0);
  CHECK(file_bytes(out + "/animation.gif") == "mine");
  CHECK(file_bytes(out + "/frames/frame_0000.png") == "mine");
  CHECK(nlohmann::json::parse(file_bytes(out + "/stats.json"))["iterations"] == 10);
}

TEST_CASE("animpak render: a manifest naming a file outside input/art is refused, not read") {
  const ArtBox box("manifest");
  const std::string out = box.path("out");
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + out + " --device reference --max-iterations 10 --no-render")
              .code == 0);
  const fs::path manifest_file = out + "/input/manifest.json";
  for (const std::string& outside : {std::string("../../scenes/star.svg"), box.path("scenes/star.svg")}) {
    nlohmann::json manifest = nlohmann::json::parse(file_bytes(manifest_file));
    for (nlohmann::json& a : manifest["art"]) a["file"] = outside;
    std::ofstream(manifest_file) << manifest.dump(2);
    const CommandResult r = run_animpak("render " + out + " --frames 1 --size 16 --format png");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains("not a manifest this animpak reads"));
  }
}

TEST_CASE(
    "packed_motion_curve: a folder packed by 0.4.0 to 0.7.0 renders on its monotone cubic, an older one on "
    "straight lines, unless its scene names the curve") {
  const animpak::test::TempDir dir("animpak-folder-curve-");
  const fs::path stats = dir / "stats.json";
  const auto packed_by = [&](const std::string& version) {
    std::ofstream(stats) << R"({"animpak": ")" << version << R"("})";
  };
  const std::string plain = R"({"elements": [], "params": {"offset": 0.02}})";
  CHECK_FALSE(animpak::cli::packed_motion_curve(stats, plain).has_value());  // no stats.json
  packed_by("0.7.0");
  CHECK(animpak::cli::packed_motion_curve(stats, plain) == 1);
  packed_by("0.4.0");
  CHECK(animpak::cli::packed_motion_curve(stats, plain) == 1);
  packed_by("0.3.0");
  CHECK(animpak::cli::packed_motion_curve(stats, plain) == 0);
  packed_by("0.8.0");
  CHECK_FALSE(animpak::cli::packed_motion_curve(stats, plain).has_value());
  packed_by("1.0.0");
  CHECK_FALSE(animpak::cli::packed_motion_curve(stats, plain).has_value());
  packed_by("0.7.0");
  CHECK_FALSE(animpak::cli::packed_motion_curve(stats, R"({"params": {"motion_curve": 2}})").has_value());
}

TEST_CASE("animpak render: says when it renders an older folder on the curve it was packed on") {
  const ArtBox box("older");
  const std::string out = box.path("out");
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + out +
                      " --device reference --max-iterations 5 --frames 2"
                      " --size 16 --format png")
              .code == 0);
  const CommandResult today = run_animpak("render " + out + " --frames 2 --size 16 --format png");
  REQUIRE(today.code == 0);
  CHECK_FALSE(today.err.find("older animpak") != std::string::npos);
  nlohmann::json stats = nlohmann::json::parse(file_bytes(out + "/stats.json"));
  stats["animpak"] = "0.7.0";
  std::ofstream(out + "/stats.json") << stats.dump();
  const CommandResult older = run_animpak("render " + out + " --frames 2 --size 16 --format png");
  REQUIRE(older.code == 0);
  CHECK_THAT(older.err, Contains("older animpak packed this folder, on the monotone cubic"));
  CHECK_THAT(older.err, Contains("\"motion_curve\": 1"));
}
