// animpak pack / render as a user runs them: resume equals an uninterrupted run byte for byte, every
// damaged or missing state and an impossible scene is refused with its own message and exit code 2,
// and a rendered pack writes exactly the frames and statistics it promises.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <fstream>
#include <iterator>
#include <regex>

#include "animpak/checkpoint.hpp"
#include "animpak/stats.hpp"
#include "evenness_output.hpp"
#include "run_animpak.hpp"
#include "scene/tiny_scenes.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;

namespace {

// A fresh folder per test case, holding scene.json (three stars, five slices).
class Sandbox {
 public:
  explicit Sandbox(const std::string& name, const std::string& scene = animpak::test::star_scene(3, 5, 2))
      : dir_("animpak-pack-" + name + "-") {
    std::ofstream(dir_ / "scene.json") << scene;
  }
  std::string scene() const { return (dir_ / "scene.json").string(); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

 private:
  animpak::test::TempDir dir_;
};

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

/// `render` of a folder holding `state` as its state.bin: exit code 2 and the message on stderr.
CommandResult render_state(const Sandbox& box, const std::string& state) {
  fs::create_directories(box.path("damaged"));
  write_bytes(box.path("damaged") + "/state.bin", state);
  return run_animpak("render " + box.path("damaged") + " --frames 1 --size 16 --format svg");
}

}  // namespace

TEST_CASE("animpak pack --resume: 60 + 60 iterations equal 120 uninterrupted, state.bin byte for byte") {
  const Sandbox box("resume");
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + box.path("d1") + " --max-iterations 60 --no-render").code ==
          0);
  const std::string halfway = bytes_of(box.path("d1") + "/state.bin");
  const CommandResult resumed = run_animpak("pack --resume " + box.path("d1") + " --max-iterations 120 --no-render");
  INFO(resumed.err);
  REQUIRE(resumed.code == 0);
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + box.path("d2") + " --max-iterations 120 --no-render").code ==
          0);
  const std::string a = bytes_of(box.path("d1") + "/state.bin"), b = bytes_of(box.path("d2") + "/state.bin");
  REQUIRE(a.size() > 1000);
  CHECK(a != halfway);  // the resumed run did continue
  CHECK(a == b);
}

TEST_CASE("animpak pack/render: missing, foreign, truncated, modified and newer states exit 2 with their message") {
  const Sandbox box("damaged");
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + box.path("good") + " --max-iterations 10 --no-render").code ==
          0);
  const std::string good = bytes_of(box.path("good") + "/state.bin");
  REQUIRE(good.size() > 100);

  fs::create_directories(box.path("empty"));
  for (const std::string& args : {"pack --resume " + box.path("empty"), "render " + box.path("empty")}) {
    INFO(args);
    const CommandResult r = run_animpak(args);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains(box.path("empty") + "/state.bin") && Contains("cannot read the state file"));
  }

  std::string foreign = good;
  foreign[0] = 'X';
  const CommandResult magic = render_state(box, foreign);
  CHECK(magic.code == 2);
  CHECK_THAT(magic.err, Contains("wrong magic bytes"));

  for (const std::size_t length : {good.size() / 2, good.size() - 1, std::size_t{16}}) {
    INFO("cut to " << length << " bytes");
    const CommandResult cut = render_state(box, good.substr(0, length));
    CHECK(cut.code == 2);
    CHECK_THAT(cut.err, Contains("truncated"));
  }

  std::string flipped = good;
  flipped[good.size() / 2] ^= 0x20;
  const CommandResult checksum = render_state(box, flipped);
  CHECK(checksum.code == 2);
  CHECK_THAT(checksum.err, Contains("checksum mismatch"));

  std::string newer = good;
  newer[8] = 7;  // the little-endian u32 version right after the 8 magic bytes
  const CommandResult version = render_state(box, newer);
  CHECK(version.code == 2);
  CHECK_THAT(version.err, Contains("state format version 7") && Contains("reads version 6"));

  // Version 4 ended in an FNV checksum anyone can recompute: refused, not trusted.
  std::string older = good;
  older[8] = 4;
  const CommandResult old_version = render_state(box, older);
  CHECK(old_version.code == 2);
  CHECK_THAT(old_version.err, Contains("state format version 4") && Contains("pack the scene again"));
}

TEST_CASE("animpak pack: elements overlapping after shrinking exit 2 naming them, no SCENE nor --resume exits 1") {
  const Sandbox box("overlap", animpak::test::star_scene(0, 5, 1,
                                                         {R"(, "guided": [
      {"name": "left-star", "element": "star", "targets": [{"x": 230, "y": 280, "t": 0}, {"x": 230, "y": 280, "t": 1}]},
      {"name": "right-star", "element": "star", "targets": [{"x": 270, "y": 280, "t": 0}, {"x": 270, "y": 280, "t": 1}]}])",
                                                          R"("initial_scale": 0.3)"}));
  const CommandResult overlap = run_animpak("pack " + box.scene() + " --out " + box.path("out") + " --no-render");
  CHECK(overlap.code == 2);
  CHECK_THAT(overlap.err, Contains("elements left-star and right-star overlap") && Contains("initial_scale"));

  const CommandResult nothing = run_animpak("pack --out " + box.path("out"));
  CHECK(nothing.code == 1);
  CHECK_THAT(nothing.err, Contains("pack needs SCENE"));
}

TEST_CASE("animpak pack: renders exactly --frames PNG and SVG frames and a complete stats.json") {
  const Sandbox box("render");
  const CommandResult r = run_animpak("pack " + box.scene() + " --out " + box.path("out") +
                                      " --max-iterations 20 --frames 4 --format png,svg --size 64");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const fs::path frames = box.path("out") + "/frames";
  for (int i = 0; i < 4; ++i)
    for (const char* ext : {".png", ".svg"}) {
      const fs::path file = frames / ("frame_000" + std::to_string(i) + ext);
      INFO(file);
      CHECK(fs::is_regular_file(file));
      CHECK(fs::file_size(file) > 50);
    }
  CHECK_FALSE(fs::exists(frames / "frame_0004.png"));
  CHECK_FALSE(fs::exists(frames / "frame_0004.svg"));

  const std::string stats_text = read_text(box.path("out") + "/stats.json");
  // The typed model (animpak/stats.hpp) reads every field pack wrote and writes the same bytes back.
  CHECK(animpak::stats_json_text(animpak::parse_stats(stats_text, "stats.json")) == stats_text);
  CHECK(animpak::parse_stats(stats_text, "stats.json").kept.empty());
  const nlohmann::json stats = nlohmann::json::parse(stats_text);
  CHECK(stats["format_version"] == 1);
  CHECK(stats["iterations"] == 20);
  CHECK(stats["stop_reason"] == "max_iterations");
  // The commit that --version names, so that the run can be reproduced from it.
  CHECK_THAT(run_animpak("--version").out, Contains("(commit " + stats["commit"].get<std::string>() + ")"));
  for (const char* phase : {"setup", "simulation", "grid", "forces", "integrate", "constraints", "loop", "growth"}) {
    INFO(phase);
    REQUIRE(stats["seconds"].contains(phase));
    CHECK(stats["seconds"][phase].get<double>() >= 0.0);
  }
  REQUIRE(stats["final_growth"].size() == 3);
  for (const auto& g : stats["final_growth"]) {
    CHECK_THAT(g["element"].get<std::string>(), Contains("star#"));
    // 20 free steps at the default rate (the room's boost off by default) add at most 20 · 0.01 · 0.05
    // to g = 1.
    CHECK(g["min"].get<double>() >= 1.0);
    CHECK(g["max"].get<double>() <= 1.0 + 20 * 0.01 * 0.05 + 1e-6);
    CHECK(g["mean"].get<double>() >= g["min"].get<double>());
  }
  // The progress rows with what the time-left model needs to replay them (scripts/progress-trace.py).
  const auto& progress = stats["progress"];
  CHECK(progress["rows"].size() == 2);  // a check every check_interval (10) steps
  CHECK(progress["unit_mesh_density"].get<double>() > 0.0);
  CHECK(progress["unit_mesh_density"].get<double>() < 1.0);
  CHECK(progress["stall"]["window"] == 400);
  CHECK(progress["stall"]["tests"] == 4);
  CHECK(progress["secondary"] == false);
  // The scene loops, so frame 4 would repeat frame 0: the 4 frames sit at i / 4.
  REQUIRE(stats["frames"].size() == 4);
  for (int i = 0; i < 4; ++i) {
    const auto& f = stats["frames"][i];
    INFO("frame " << i);
    CHECK(f["t"].get<double>() == Approx(i / 4.0));
    CHECK(f["coverage"].get<double>() > 0.0);
    CHECK(f["coverage"].get<double>() < 0.2);  // 3 stars at 7 % of full size
    CHECK(f["min_gap"].get<double>() > 0.0);
    CHECK(f["mean_gap"].get<double>() >= f["min_gap"].get<double>());
    CHECK(f["overlapping_pairs"] == 0);
    CHECK(f["channel_cv"].get<double>() > 0.0);
    CHECK(f["elements_outside"].empty());
    CHECK(f["overlaps"].empty());
    // Three stars well inside the heart: a disc of free space larger than a star, a contact function from
    // 1 − coverage to 0.
    CHECK(f["element_radius"].get<double>() > 0.0);
    CHECK(f["empty_disc"].get<double>() > 1.0);
    CHECK(f["empty_disc_radius"].get<double>() ==
          Approx(f["empty_disc"].get<double>() * f["element_radius"].get<double>()));
    REQUIRE(f["contact"].size() >= 2);
    CHECK(f["contact"][0].get<double>() == Approx(1 - f["coverage"].get<double>()).margin(0.01));
    CHECK(f["contact"].back() == 0.0);
    CHECK(f.contains("wall_ratio"));
  }
  // Five slices: eight points of each of the four intervals.
  REQUIRE(stats["between_slices"].size() == 32);
  CHECK(stats["between_slices"][0]["t"].get<double>() == Approx(0.25 / 9));
  CHECK(stats["between_slices"][1]["t"].get<double>() == Approx(0.5 / 9));
  CHECK(stats["between_slices"][31]["t"].get<double>() == Approx(0.75 + 0.25 * 8 / 9));
  for (const char* times : {"frames", "between_slices"}) {
    INFO(times);
    const auto& q = stats["quality"][times];
    CHECK(q["element_frames"] == 3 * stats[times].size());
    CHECK(q["element_frames_outside"] == 0);
    CHECK(q["overlapping_pair_frames"] == 0);
    CHECK(q["coverage"]["min"].get<double>() <= q["coverage"]["mean"].get<double>());
    CHECK(q["coverage"]["mean"].get<double>() <= q["coverage"]["max"].get<double>());
  }
  // Evenness is measured at the frames, not between slices.
  const auto& even = stats["quality"]["frames"];
  CHECK(even["empty_disc"]["median"].get<double>() <= even["empty_disc"]["worst"].get<double>());
  CHECK(even["contact"]["step"] == 0.05);
  CHECK(even["contact"]["mean"].size() >= 2);
  CHECK(even["wall_ratio"]["times"].get<int>() <= 4);
  CHECK_FALSE(stats["quality"]["between_slices"].contains("empty_disc"));
  CHECK_FALSE(stats["between_slices"][0].contains("contact"));
  CHECK_THAT(r.out, Contains("quality: 0 of 12 element-frames outside") &&
                        Contains("between slices: 0 of 96 element-frames outside") &&
                        Contains("\nevenness: wall ratio ") && Contains(" element radii (worst "));
  // The motion line and its figures (docs/quality.md, "Motion").
  CHECK_THAT(r.out, Contains("\nmotion: kink ") && Contains(" (acceleration next to a slice over elsewhere), "));
  CHECK(stats["motion"]["acceleration"]["p99"].get<double>() >=
        stats["motion"]["acceleration"]["median"].get<double>());
  CHECK(stats["motion"]["size_over_script"].size() == 3);
  for (const auto& e : stats["motion"]["size_over_script"]) CHECK(e["ratio"].get<double>() >= 1.0);
  // How far each element moves, and no dip: nothing travels here, so the line says nothing of it.
  REQUIRE(stats["motion"]["movement"].size() == 3);
  for (const auto& e : stats["motion"]["movement"]) {
    CHECK(e["detour"].get<double>() >= 0.0);
    CHECK(e["path_length"].get<double>() >= 2.0 * e["detour"].get<double>() - 1e-12);
    CHECK(e["dip"].get<double>() == 1.0);
    CHECK_FALSE(e["guided"].get<bool>());
  }
  CHECK_THAT(r.out, !Contains("unguided elements stray"));
}

TEST_CASE("animpak pack: the evenness line of a sparse packing says so and names what fills it") {
  // Three stars grown for 5 steps: pockets of the heart far wider than a star.
  const Sandbox box("sparse");
  const CommandResult r = run_animpak("pack " + box.scene() + " --out " + box.path("out") +
                                      " --device reference --max-iterations 5 --frames 2 --format png --size 32");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const nlohmann::json stats = nlohmann::json::parse(read_text(box.path("out") + "/stats.json"));
  REQUIRE(stats["quality"]["frames"]["empty_disc"]["median"].get<double>() > 1.0);
  const std::regex line(R"(\nevenness: [^\n]* element radii \(worst [0-9.]+\); sparse: try a smaller params\.offset, )"
                        R"(higher counts \("count": "fill"\) or secondary elements\n)");
  CHECK(std::regex_search(r.out, line));
}

TEST_CASE("evenness_line: names what fills a packing only when its median frame leaves a disc over one radius") {
  animpak::EvennessSummary e;
  e.wall_ratio_median = e.wall_ratio_min = 0.5;
  e.wall_ratio_max = 0.6;
  e.empty_disc_median = 0.8;
  e.empty_disc_worst = 1.4;  // the worst frame alone does not make a packing sparse
  CHECK(animpak::cli::evenness_line(e) ==
        "evenness: wall ratio 0.50 (0.50–0.60), largest empty disc 0.80 element radii (worst 1.40)");
  e.empty_disc_median = 1.0;
  CHECK_THAT(animpak::cli::evenness_line(e), !Contains("sparse"));
  e.empty_disc_median = 1.2;
  CHECK_THAT(animpak::cli::evenness_line(e),
             Contains("(worst 1.40); sparse: try a smaller params.offset, higher counts (\"count\": \"fill\") or "
                      "secondary elements"));
  CHECK_THAT(animpak::cli::evenness_line(animpak::EvennessSummary{}), !Contains("sparse"));  // no art
}

TEST_CASE("animpak pack: with a traveller, the motion line and stats.json say how far the others move and dip") {
  const std::string guided = R"(, "guided": [{"name": "traveller", "element": "star", "targets": [
    {"x": 110, "y": 235, "t": 0}, {"x": 390, "y": 235, "t": 0.5}, {"x": 110, "y": 235, "t": 1}]}])";
  const Sandbox box("traveller", animpak::test::star_scene(8, 9, 5, {guided, R"("make_way": 0.2)"}));
  const CommandResult r =
      run_animpak("pack " + box.scene() + " --out " + box.path("out") + " --max-iterations 10 --frames 8 --size 64");
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.err, Contains("unguided element(s) start on paths that step aside"));
  CHECK_THAT(r.out, Contains("unguided elements stray ") && Contains(" a loop (median; longest ") &&
                        Contains(" scripts give way to a traveller, down to "));
  const nlohmann::json stats = nlohmann::json::parse(read_text(box.path("out") + "/stats.json"));
  const auto& moves = stats["motion"]["movement"];
  REQUIRE(moves.size() == 9);
  CHECK(moves[0]["element"] == "traveller");
  CHECK(moves[0]["guided"].get<bool>());
  // The traveller crosses most of the heart and back: its path is the longest.
  for (std::size_t e = 1; e < moves.size(); ++e)
    CHECK(moves[0]["path_length"].get<double>() > moves[e]["path_length"].get<double>());
  double least = 1.0;
  for (const auto& e : moves) least = std::min(least, e["dip"].get<double>());
  CHECK(least < 1.0);
  CHECK(least >= 1.0 / 1.3 - 1e-9);
}

TEST_CASE("animpak render: a packed folder moved together with its scene still renders") {
  const Sandbox box("moved");
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + box.path("out") + " --max-iterations 10 --no-render").code ==
          0);
  // Move the scene and the output folder together; nothing is left at the old place.
  const fs::path moved = fs::path(box.path("elsewhere"));
  fs::create_directories(moved);
  fs::rename(box.scene(), moved / "scene.json");
  fs::rename(box.path("out"), moved / "out");
  const CommandResult r = run_animpak("render " + (moved / "out").string() + " --frames 1 --size 32 --format png");
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK(fs::exists(moved / "out" / "frames" / "frame_0000.png"));
  CHECK_THAT(r.out, Contains("quality: ") && Contains("between slices: "));
}

TEST_CASE("animpak render: stats.json gets the metrics of the frames just rendered and keeps the run's own fields") {
  const Sandbox box("restats");
  const std::string out = box.path("out");
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + out + " --max-iterations 10 --no-render").code == 0);
  const nlohmann::json packed = nlohmann::json::parse(read_text(out + "/stats.json"));
  CHECK(packed["frames"].empty());  // nothing rendered yet, as animpak-solve writes it

  CommandResult r = run_animpak("render " + out + " --frames 3 --size 16 --format svg --contact-plot");
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(fs::file_size(out + "/contact.png") > 1000);
  const std::string rendered_text = read_text(out + "/stats.json");
  CHECK(animpak::stats_json_text(animpak::parse_stats(rendered_text, "stats.json")) == rendered_text);
  nlohmann::json stats = nlohmann::json::parse(rendered_text);
  CHECK(stats["frames"].size() == 3);
  CHECK(stats["between_slices"].size() == 32);  // eight points of each of four slice intervals
  CHECK(stats["quality"]["frames"]["element_frames"] == 9);
  CHECK(stats["iterations"] == 10);
  CHECK(stats["seconds"] == packed["seconds"]);
  CHECK(stats["final_growth"] == packed["final_growth"]);
  CHECK(stats["format_version"] == packed["format_version"]);
  CHECK_FALSE(fs::exists(out + "/stats.json.tmp"));

  // Without stats.json, render writes what the state knows.
  fs::remove(out + "/stats.json");
  REQUIRE(run_animpak("render " + out + " --frames 2 --size 16 --format svg").code == 0);
  stats = nlohmann::json::parse(read_text(out + "/stats.json"));
  CHECK(stats["frames"].size() == 2);
  CHECK(stats["iterations"] == 10);
  CHECK(stats["stop_reason"] == "max_iterations");
  CHECK(stats["format_version"] == 1);

  // A stats.json that is not this packing's (not JSON, or another packing's element count) is kept aside
  // as stats.foreign.json and a new one written, so that `report`, which refuses it, has a way out.
  write_bytes(out + "/stats.json", "{ not json");
  r = run_animpak("render " + out + " --frames 2 --size 16 --format svg");
  CHECK(r.code == 0);
  CHECK_THAT(r.err, Contains("was not this packing's statistics; kept as stats.foreign.json"));
  CHECK(bytes_of(out + "/stats.foreign.json") == "{ not json");
  stats = nlohmann::json::parse(read_text(out + "/stats.json"));
  CHECK(stats["frames"].size() == 2);
  CHECK(stats["iterations"] == 10);
  stats["elements"] = 99;
  stats["final_growth"] = nlohmann::json::array({1, 2});
  write_bytes(out + "/stats.json", stats.dump());
  const CommandResult refused = run_animpak("report " + out);
  CHECK(refused.code == 2);
  CHECK_THAT(refused.err, Contains("another packing's"));
  r = run_animpak("render " + out + " --frames 2 --size 16 --format svg");
  CHECK(r.code == 0);
  CHECK_THAT(r.err, Contains("kept as stats.foreign.json"));
  CHECK(nlohmann::json::parse(read_text(out + "/stats.json"))["elements"] == packed["elements"]);
  const CommandResult reported = run_animpak("report " + out);
  INFO(reported.err);
  CHECK(reported.code == 0);
}

TEST_CASE(
    "animpak pack/render --format lottie,svg-anim: animation.json and animation.svg listed with their sizes, no PNG") {
  const Sandbox box("animated");
  const CommandResult packed = run_animpak("pack " + box.scene() + " --out " + box.path("out") +
                                           " --max-iterations 10 --frames 4 --size 48 --format lottie,svg-anim");
  INFO(packed.err);
  REQUIRE(packed.code == 0);
  const fs::path out = box.path("out");
  for (const char* name : {"animation.json", "animation.svg"}) {
    INFO(name);
    REQUIRE(fs::is_regular_file(out / name));
    CHECK_THAT(packed.err, Contains("\n  " + std::string(name)) && Contains(" KiB\n"));
  }
  CHECK_FALSE(fs::exists(out / "frames"));  // no PNG or SVG frames, and no empty folder for them
  const nlohmann::json lottie = nlohmann::json::parse(read_text(out / "animation.json"));
  CHECK(lottie["op"] == 4);
  CHECK(lottie["h"] == 48);

  // render again: held keys, whole pixels.
  const CommandResult rendered = run_animpak(
      "render " + out.string() + " --frames 3 --size 48 --format lottie --interpolation hold --precision 0");
  INFO(rendered.err);
  REQUIRE(rendered.code == 0);
  const std::string text = read_text(out / "animation.json");
  CHECK_THAT(text, Contains("\"h\":1"));
  // Every point ([x,y]; colours have four numbers) in whole pixels.
  const std::regex point("\\[-?[0-9.]+,-?[0-9.]+\\]");
  std::size_t points = 0, fractional = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), point); it != std::sregex_iterator(); ++it)
    ++points, fractional += it->str().find('.') != std::string::npos;
  CHECK(points > 0);
  CHECK(fractional == 0);
  CHECK(run_animpak("render " + out.string() + " --format lottie --interpolation smooth").code != 0);
}

TEST_CASE("animpak pack/render --format: spaces around the items do not count, an empty item is refused") {
  const Sandbox box("format-list");
  const fs::path out = box.path("out");
  const CommandResult packed = run_animpak("pack " + box.scene() + " --out " + out.string() +
                                           " --max-iterations 10 --frames 2 --size 32 --format 'svg, lottie'");
  INFO(packed.err);
  REQUIRE(packed.code == 0);
  CHECK(fs::is_regular_file(out / "animation.json"));
  CHECK(fs::is_regular_file(out / "frames" / "frame_0000.svg"));
  fs::remove(out / "animation.json");
  const CommandResult rendered =
      run_animpak("render " + out.string() + " --frames 2 --size 32 --format ' lottie ,svg-anim '");
  INFO(rendered.err);
  REQUIRE(rendered.code == 0);
  CHECK(fs::is_regular_file(out / "animation.json"));
  CHECK(fs::is_regular_file(out / "animation.svg"));

  for (const char* list : {"'svg,,lottie'", "'svg, '", "'svg, ,lottie'"}) {
    const CommandResult empty = run_animpak("render " + out.string() + " --frames 2 --size 32 --format " + list);
    INFO(list << ": " << empty.err);
    CHECK(empty.code == 1);
    CHECK_THAT(empty.err, Contains("an empty item (a comma too many)") && Contains("e.g. --format gif,mp4"));
  }
  // A lone comma names no format (it used to take the next option, --frames, for one).
  const CommandResult none = run_animpak("render " + out.string() + " --format , --frames 2 --size 32");
  CHECK(none.code == 1);
  CHECK_THAT(none.err, Contains("--format: \",\": no format given"));
  const CommandResult unknown = run_animpak("render " + out.string() + " --format 'svg, mp5'");
  CHECK(unknown.code == 1);
  CHECK_THAT(unknown.err, Contains("mp5: expected png, gif, mp4"));
}

TEST_CASE("animpak render --background, --container and --format dotlottie, and --no-container is --container none") {
  const Sandbox box("background");
  const fs::path out = box.path("out");
  REQUIRE(run_animpak("pack " + box.scene() + " --out " + out.string() + " --max-iterations 10 --no-render").code == 0);
  const CommandResult none = run_animpak("render " + out.string() +
                                         " --frames 2 --size 48 --format png,gif,lottie,dotlottie --background none");
  INFO(none.err);
  REQUIRE(none.code == 0);
  // The file listed with its size at the end, under the folder's line.
  CHECK_THAT(none.err,
             Contains("files in " + out.string()) && Contains("\n  animation.lottie  ") && Contains(" KiB\n"));
  CHECK(fs::is_regular_file(out / "animation.gif"));  // ffmpeg took the transparent palette
  CHECK_THAT(read_text(out / "animation.json"), !Contains("\"ty\":1,"));
  const CommandResult dark = run_animpak(
      "render " + out.string() + " --frames 2 --size 48 --format lottie --background '#1e1e1e' --container fill");
  INFO(dark.err);
  REQUIRE(dark.code == 0);
  CHECK_THAT(read_text(out / "animation.json"), Contains("\"sc\":\"#1e1e1e\""));
  REQUIRE(run_animpak("render " + out.string() + " --frames 2 --size 48 --format lottie --no-container").code == 0);
  CHECK_THAT(read_text(out / "animation.json"), !Contains("\"nm\":\"container\""));

  const CommandResult colour = run_animpak("render " + out.string() + " --format lottie --background red");
  CHECK(colour.code == 1);
  CHECK_THAT(colour.err, Contains("--background red: expected white, none or a colour #rrggbb"));
  const CommandResult mp4 = run_animpak("render " + out.string() + " --format mp4 --background none");
  CHECK(mp4.code == 1);
  CHECK_THAT(mp4.err, Contains("MP4 (H.264) has no transparency"));
  CHECK(run_animpak("render " + out.string() + " --format lottie --no-container --container fill").code == 1);
}

TEST_CASE("animpak pack --still: the still reference is the packing of the same scene written without animation") {
  // Three rotating stars and two guided ones swapping places, on 16 slices; by hand, its still
  // reference: five stars standing still, 12 slices, the same seed.
  const Sandbox box("still", animpak::test::star_scene(3, 16, 2, animpak::test::swapping_pair()));
  const std::string star = animpak::test::example_file("default/star.svg");
  write_bytes(box.path("by-hand.json"), R"({"container": {"art": ")" +
                                            animpak::test::example_file("shapes/heart-container.path") +
                                            R"("}, "elements": [{"name": "star", "art": ")" + star +
                                            R"(", "count": 5}], "seed": 2, "slices": 12, "params": {}})");
  const CommandResult still =
      run_animpak("pack " + box.scene() + " --still --out " + box.path("still") + " --max-iterations 40 --no-render");
  INFO(still.err);
  REQUIRE(still.code == 0);
  CHECK_THAT(still.err, Contains("still reference") && Contains("guided elements as ordinary copies") &&
                            Contains("12 slices") && Contains("5 elements"));
  REQUIRE(run_animpak("pack " + box.path("by-hand.json") + " --out " + box.path("hand") +
                      " --max-iterations 40 --no-render")
              .code == 0);
  const animpak::Checkpoint a = animpak::read_checkpoint(box.path("still") + "/state.bin");
  const animpak::Checkpoint b = animpak::read_checkpoint(box.path("hand") + "/state.bin");
  CHECK(a.state.iteration == 40);
  CHECK(a.state.x == b.state.x);
  CHECK(a.state.y == b.state.y);
  CHECK(a.state.t == b.state.t);
  CHECK(a.state.growth == b.state.growth);
  // The folder holds the still scene, so it renders and resumes as that scene.
  const nlohmann::json scene = nlohmann::json::parse(bytes_of(box.path("still") + "/input/scene.json"));
  CHECK_FALSE(scene.contains("guided"));
  CHECK_FALSE(scene["elements"][0].contains("animation"));
  CHECK(scene["elements"][0]["count"] == 5);
  CHECK(run_animpak("pack --resume " + box.path("still") + " --still").code == 1);
}

TEST_CASE("animpak pack: the wall settles at about half the channel, two discs in a circle") {
  // One channel lies between art and wall against two between two elements, so an even packing shows a
  // wall ratio (median art-to-wall gap over median art-to-art gap) of about 0.5 (docs/quality.md,
  // "Evenness"). The wall as the element's mirror image gives it by symmetry; the point wall of 0.4.0
  // (wall_repulsion 10, no mirror) left 1.2 here.
  const std::string scene = R"({"container": {"art": "circle.svg"},
    "elements": [{"name": "disc", "art": "disc.svg", "count": 2}],
    "seed": 1, "loop": true, "slices": 12, "params": {"offset": 0.04}})";
  const Sandbox box("wall", scene);
  write_bytes(box.path("disc.svg"), R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">)"
                                    R"(<circle cx="50" cy="50" r="50" fill="#c33"/></svg>)");
  write_bytes(box.path("circle.svg"), R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 200">)"
                                      R"(<circle cx="100" cy="100" r="100" fill="#eee"/></svg>)");
  const CommandResult r =
      run_animpak("pack " + box.scene() + " --out " + box.path("out") + " --frames 6 --format svg --size 100");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const nlohmann::json stats = nlohmann::json::parse(bytes_of(box.path("out") + "/stats.json"));
  const nlohmann::json& frames = stats["quality"]["frames"];
  CHECK(frames["overlapping_pairs"] == 0);
  CHECK(frames["element_frames_outside"] == 0);
  const double ratio = frames["wall_ratio"]["median"].get<double>();
  CHECK(ratio > 0.3);
  CHECK(ratio < 0.75);
}

TEST_CASE("animpak pack/render --still-reference: stats.json carries the still packing's coverage beside the frames'") {
  const Sandbox box("still-ref", animpak::test::star_scene(3, 8, 2));
  const std::string frames = " --max-iterations 30 --frames 4 --format svg --size 64";
  // A folder without a rendered still packing is refused before the packing starts, naming what to do.
  const CommandResult missing = run_animpak("pack " + box.scene() + " --out " + box.path("a") + frames +
                                            " --still-reference " + box.path("none"));
  CHECK(missing.code == 2);
  CHECK_THAT(missing.err, Contains("--still-reference") && Contains("--still --out"));
  CHECK_FALSE(fs::exists(box.path("a") + "/state.bin"));
  REQUIRE(run_animpak("pack " + box.scene() + " --still --out " + box.path("still") + frames).code == 0);
  const CommandResult r = run_animpak("pack " + box.scene() + " --out " + box.path("a") + frames +
                                      " --still-reference " + box.path("still"));
  INFO(r.err);
  REQUIRE(r.code == 0);
  const nlohmann::json still = nlohmann::json::parse(bytes_of(box.path("still") + "/stats.json"));
  const nlohmann::json stats = nlohmann::json::parse(bytes_of(box.path("a") + "/stats.json"));
  const double still_mean = still["quality"]["frames"]["coverage"]["mean"].get<double>();
  const nlohmann::json& ref = stats["still_reference"];
  CHECK(ref["coverage"].get<double>() == still_mean);
  CHECK(ref["lowest_over_still"].get<double>() ==
        Approx(stats["quality"]["frames"]["coverage"]["min"].get<double>() / still_mean));
  CHECK(ref["mean_over_still"].get<double>() ==
        Approx(stats["quality"]["frames"]["coverage"]["mean"].get<double>() / still_mean));
  CHECK_THAT(r.out, Contains("still: the same elements standing still cover"));
  // A render keeps the comparison, its ratios taken for the frames it draws.
  const CommandResult again = run_animpak("render " + box.path("a") + " --frames 3 --format svg --size 64");
  REQUIRE(again.code == 0);
  CHECK_THAT(again.out, Contains("still:"));
  const nlohmann::json rendered = nlohmann::json::parse(bytes_of(box.path("a") + "/stats.json"));
  CHECK(rendered["still_reference"]["coverage"].get<double>() == still_mean);
  CHECK(rendered["still_reference"]["lowest_over_still"].get<double>() ==
        Approx(rendered["quality"]["frames"]["coverage"]["min"].get<double>() / still_mean));
  CHECK(rendered["quality"]["frames"]["times"] == 3);
}

TEST_CASE("animpak pack --profile: the time of every phase and kernel at the end, and stats.json lists the kernels") {
  const Sandbox box("profile");
  const CommandResult r = run_animpak("pack " + box.scene() + " --out " + box.path("out") +
                                      " --max-iterations 30 --no-render --profile"
                                      " --device pocl");
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.err, Contains("profile: 30 iterations"));
  for (const char* row : {"forces ", "grid ", "growth ", "repulsion_force (forces)", "integrate (integrate)",
                          "propose_growth (growth)", "host: overlap broadphase (forces)"})
    CHECK_THAT(r.err, Contains(row));
  std::ifstream in(box.path("out") + "/stats.json");
  const nlohmann::json stats = nlohmann::json::parse(in);
  REQUIRE(stats.contains("kernels"));
  bool repulsion = false;
  for (const nlohmann::json& k : stats["kernels"]) {
    CHECK(k["seconds"].get<double>() >= 0.0);
    if (k["name"] == "repulsion_force") {
      repulsion = true;
      CHECK(k["launches"] == 30);  // one launch per step
      CHECK(k["phase"] == "forces");
    }
  }
  CHECK(repulsion);
  // Without --profile the table is not printed; stats.json still lists the kernels.
  const CommandResult quiet = run_animpak("pack " + box.scene() + " --out " + box.path("quiet") +
                                          " --max-iterations 10 --no-render --device pocl");
  CHECK(quiet.err.find("profile:") == std::string::npos);
}

TEST_CASE(
    "animpak pack: coarse to fine, interrupted before and after the refinement or stopped as a preview, resumes "
    "to the uninterrupted state.bin byte for byte") {
  // 13 slices packed first at four (docs/parameters.md, "Coarse to fine"), with a collision grid coarse
  // enough to allow it; started large and settled briefly, so that each of the seven packs takes seconds.
  const Sandbox box(
      "levels", animpak::test::star_scene(3, 13, 2, {"", R"("cell_size": 0.5, "coarse_step": 4, "initial_scale": 0.25,
                                                               "settle_iterations": 300)"}));
  const CommandResult whole = run_animpak("pack " + box.scene() + " --out " + box.path("whole") + " --no-render");
  INFO(whole.err);
  REQUIRE(whole.code == 0);
  CHECK_THAT(whole.err, Contains("coarse to fine: 4 slices until they stop, then the scene's 13"));
  const animpak::Stats stats = animpak::parse_stats(bytes_of(box.path("whole") + "/stats.json"), "stats.json");
  REQUIRE(stats.levels);
  REQUIRE(stats.levels->size() == 2);
  CHECK((*stats.levels)[0].slices == 4);
  CHECK((*stats.levels)[1].slices == 13);
  CHECK(!stats.level_slices);
  const std::uint64_t refined_at = (*stats.levels)[0].iterations;
  REQUIRE(refined_at >= 40);
  REQUIRE(stats.iterations > refined_at);
  const std::string expected = bytes_of(box.path("whole") + "/state.bin");
  CHECK(animpak::read_checkpoint(box.path("whole") + "/state.bin").level_slices == 0);

  // Stopped by an iteration limit before the refinement, then after it (on a check, every 10 iterations):
  // the first check past the refinement, which must come before the stop for the cut to interrupt.
  const std::uint64_t after = (refined_at / 10 + 1) * 10;
  REQUIRE(after < stats.iterations);
  for (const std::uint64_t cut : {refined_at / 20 * 10, after}) {
    INFO("interrupted at iteration " << cut);
    const std::string dir = box.path("cut" + std::to_string(cut));
    REQUIRE(run_animpak("pack " + box.scene() + " --out " + dir + " --max-iterations " + std::to_string(cut) +
                        " --no-render")
                .code == 0);
    const animpak::Checkpoint stopped = animpak::read_checkpoint(dir + "/state.bin");
    CHECK(stopped.level_slices == (cut < refined_at ? 4 : 0));
    CHECK(stopped.state.iteration == cut);
    const CommandResult resumed = run_animpak("pack --resume " + dir + " --max-iterations 100000 --no-render");
    INFO(resumed.err);
    REQUIRE(resumed.code == 0);
    CHECK(bytes_of(dir + "/state.bin") == expected);
  }

  // A preview stops at the coarse level's stop, says how to go on, and goes on to the same end.
  const CommandResult preview =
      run_animpak("pack " + box.scene() + " --out " + box.path("preview") + " --preview --no-render");
  INFO(preview.err);
  REQUIRE(preview.code == 0);
  CHECK_THAT(preview.err, Contains("a preview at 4 slices") && Contains("pack --resume"));
  const animpak::Checkpoint previewed = animpak::read_checkpoint(box.path("preview") + "/state.bin");
  CHECK(previewed.level_slices == 4);
  CHECK(previewed.state.iteration == refined_at);
  // Resumed with --preview again, it is finished; without, it refines and packs on.
  const CommandResult again = run_animpak("pack --resume " + box.path("preview") + " --preview --no-render");
  CHECK(again.code == 0);
  CHECK_THAT(again.err, Contains("holds a finished packing"));
  const CommandResult on = run_animpak("pack --resume " + box.path("preview") + " --no-render");
  INFO(on.err);
  REQUIRE(on.code == 0);
  CHECK_THAT(on.err, Contains("refined to 13 slices"));
  CHECK(bytes_of(box.path("preview") + "/state.bin") == expected);

  // A scene without a coarse level refuses --preview and leaves no folder.
  const Sandbox plain("levels-none");
  const CommandResult refused = run_animpak("pack " + plain.scene() + " --out " + plain.path("p") + " --preview");
  CHECK(refused.code == 1);
  CHECK_THAT(refused.err, Contains("no coarse level"));
  CHECK(!fs::exists(plain.path("p") + "/state.bin"));
}
