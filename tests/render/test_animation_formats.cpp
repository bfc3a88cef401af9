// The animated vector formats against the players people use: the Lottie document drawn by rlottie and the
// SMIL-animated SVG drawn by headless Chromium, paused at a frame's time, must cover what animpak's own PNG
// frame of that index covers (alpha masks' intersection over union ≥ 0.97); the Lottie document passes a
// schema check; every path keeps its layout from frame to frame or the export refuses it.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include "animpak/version.hpp"
#include "animpak/error.hpp"
#include "animpak/render.hpp"
#include "frame_writers.hpp"
#include "golden.hpp"
#include "lottie_schema.hpp"
#include "skip.hpp"
#include "temp_dir.hpp"
#include "tiny_world.hpp"
#ifdef ANIMPAK_HAVE_RLOTTIE
#include "players/rlottie_frame.hpp"
#endif

using namespace animpak;
namespace fs = std::filesystem;
using Catch::Matchers::Contains;

namespace {

constexpr double kMinIou = 0.97;
constexpr int kFrames = 6;

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The tiny star world's elements are a tenth of the container wide: at 320 pixels high they are about 30
// pixels across, so that a frame's edge pixels are a small share of its ink. A transparent background and
// no container keep the alpha masks the elements' paint.
World big_star_world() { return tiny_star_world(); }

FrameOutput animated_output(const fs::path& dir, std::vector<FrameFormat> formats) {
  FrameOutput out;
  out.dir = dir;
  out.count = kFrames;
  out.formats = std::move(formats);
  out.style.size = 320;
  out.style.background = {1, 1, 1, 0};
  out.style.draw_container = false;
  return out;
}

std::string frame_png(int i) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.png", i);
  return name;
}

bool have_chromium() { return std::system("command -v chromium >/dev/null 2>&1") == 0; }

}  // namespace

TEST_CASE("lottie: animation.json passes the schema check, one layer per element named by its id, N + 1 keys per path ending on frame 0") {
  const World world = big_star_world();
  const animpak::test::TempDir temp("animpak-animation-");
  const auto dir = temp / "lottie";
  FrameOutput out = animated_output(dir, {FrameFormat::png, FrameFormat::lottie});
  out.style.draw_container = true;
  write_frames(world, world.state, out);
  const nlohmann::json doc = nlohmann::json::parse(text_of(dir / "animation.json"));
  const std::vector<std::string> errors = lottie_schema::errors(doc);
  for (const std::string& e : errors) UNSCOPED_INFO(e);
  CHECK(errors.empty());
  // The generator names the version a player's user would report (CMakeLists.txt's project version).
  CHECK(doc["meta"]["g"] == "animpak " + std::string(animpak::animpak_version));

  const Image png = read_rgba(dir / "frames" / frame_png(0));
  CHECK(doc["w"] == png.width);
  CHECK(doc["h"] == png.height);
  CHECK(doc["op"] == kFrames);
  CHECK(doc["fr"] == 25);
  // Top first: the container, then the elements from the last-drawn one, ids as the SVG frames'.
  const std::vector<std::string> ids = frame_writers::element_ids(world);
  REQUIRE(doc["layers"].size() == world.elements.size() + 1);
  CHECK(doc["layers"][0]["nm"] == "container");
  for (std::size_t e = 0; e < world.elements.size(); ++e) CHECK(doc["layers"][world.elements.size() - e]["nm"] == ids[e]);
  CHECK(ids[0] == world.elements[0].name);

  const nlohmann::json& shape = doc["layers"][1]["shapes"][0]["it"][0];
  REQUIRE(shape["ty"] == "sh");
  const nlohmann::json& keys = shape["ks"]["k"];
  REQUIRE(keys.size() == kFrames + 1);
  CHECK(keys[kFrames]["t"] == kFrames);
  CHECK(keys[kFrames]["s"] == keys[0]["s"]);
  CHECK(keys[1]["s"] != keys[0]["s"]);  // the stars rotate
  for (const auto& zero : keys[0]["s"][0]["i"]) CHECK(zero == nlohmann::json::array({0, 0}));
}

TEST_CASE("lottie: --interpolation hold writes hold keys, linear ones ease linearly") {
  const World world = big_star_world();
  const animpak::test::TempDir temp("animpak-animation-");
  const auto dir = temp / "lottie-hold";
  FrameOutput out = animated_output(dir, {FrameFormat::lottie});
  out.interpolation = Interpolation::hold;
  write_frames(world, world.state, out);
  const nlohmann::json hold = nlohmann::json::parse(text_of(dir / "animation.json"));
  CHECK(lottie_schema::errors(hold).empty());
  const nlohmann::json& keys = hold["layers"][0]["shapes"][0]["it"][0]["ks"]["k"];
  for (int i = 0; i < kFrames; ++i) CHECK(keys[i]["h"] == 1);

  out.interpolation = Interpolation::linear;
  write_frames(world, world.state, out);
  const nlohmann::json linear = nlohmann::json::parse(text_of(dir / "animation.json"));
  const nlohmann::json& key = linear["layers"][0]["shapes"][0]["it"][0]["ks"]["k"][0];
  CHECK_FALSE(key.contains("h"));
  CHECK(key["o"]["x"] == 0);
  CHECK(key["i"]["x"] == 1);
}

TEST_CASE("lottie schema check: broken documents fail, each error naming its JSON path") {
  const World world = big_star_world();
  const animpak::test::TempDir temp("animpak-animation-");
  const auto dir = temp / "lottie-broken";
  write_frames(world, world.state, animated_output(dir, {FrameFormat::lottie}));
  const nlohmann::json good = nlohmann::json::parse(text_of(dir / "animation.json"));
  REQUIRE(lottie_schema::errors(good).empty());

  auto only_error = [](const nlohmann::json& doc) {
    const std::vector<std::string> errors = lottie_schema::errors(doc);
    REQUIRE(errors.size() == 1);
    return errors[0];
  };
  nlohmann::json doc = good;
  doc.erase("w");
  CHECK(only_error(doc) == "w: missing");
  doc = good;
  doc["layers"][1]["ks"].erase("o");
  CHECK(only_error(doc) == "layers[1].ks.o: missing");
  doc = good;
  doc["layers"][0]["shapes"][0]["it"][0]["ks"]["k"][2]["t"] = "2";
  CHECK(only_error(doc) == "layers[0].shapes[0].it[0].ks.k[2].t: expected a number");
  doc = good;
  doc["layers"][0]["shapes"][0]["it"][0]["ks"]["k"][3]["t"] = 1;
  CHECK(only_error(doc) == "layers[0].shapes[0].it[0].ks.k[3].t: not after the previous keyframe");
  doc = good;
  doc["layers"][2]["shapes"][0]["it"][0]["ks"]["k"][1]["s"][0]["i"].erase(0);
  CHECK(only_error(doc) == "layers[2].shapes[0].it[0].ks.k[1].s[0].i: not as many points as v");
  doc = good;
  doc["layers"][0]["shapes"][0]["it"].erase(doc["layers"][0]["shapes"][0]["it"].size() - 1);
  CHECK(only_error(doc) == "layers[0].shapes[0].it: a group's last item must be its transform (tr)");
  doc = good;
  doc["layers"][0]["shapes"][0]["it"][0]["ty"] = "xx";
  CHECK(only_error(doc) == "layers[0].shapes[0].it[0].ty: unexpected shape item type \"xx\"");
}

TEST_CASE("lottie and rlottie: frames 0, N/3 and 2N/3 cover animpak's PNG frames, alpha IoU at least 0.97") {
#ifndef ANIMPAK_HAVE_RLOTTIE
  animpak::test::skip("rlottie was not found when the build was configured (Debian package librlottie-dev); "
                      "nothing was compared");
#else
  const World world = big_star_world();
  const animpak::test::TempDir temp("animpak-animation-");
  const auto dir = temp / "rlottie";
  write_frames(world, world.state, animated_output(dir, {FrameFormat::png, FrameFormat::lottie}));
  REQUIRE(rlottie_frame_count(dir / "animation.json") == std::size_t(kFrames));
  for (int i : {0, kFrames / 3, 2 * kFrames / 3}) {
    const PlayerFrame theirs = rlottie_frame(dir / "animation.json", std::size_t(i));
    REQUIRE(theirs.error.empty());
    const Image ours = read_rgba(dir / "frames" / frame_png(i));
    REQUIRE(theirs.width == ours.width);
    REQUIRE(theirs.height == ours.height);
    const double iou = alpha_iou(ours, Image{theirs.width, theirs.height, theirs.rgba});
    INFO("frame " << i);
    CHECK(iou >= kMinIou);
  }
#endif
}

TEST_CASE("svg-anim and Chromium: paused at three frames' times it covers animpak's PNG frames, alpha IoU at least 0.97") {
  if (!have_chromium())
    return animpak::test::skip("chromium is not on PATH (Debian package chromium); nothing was compared");
  const World world = big_star_world();
  const animpak::test::TempDir temp("animpak-animation-");
  const auto dir = temp / "chromium";
  const FrameOutput out = animated_output(dir, {FrameFormat::png, FrameFormat::svg_anim});
  write_frames(world, world.state, out);
  const std::string svg = text_of(dir / "animation.svg");
  for (int i : {0, kFrames / 3, 2 * kFrames / 3}) {
    const Image ours = read_rgba(dir / "frames" / frame_png(i));
    // The SVG inline, so that the page's script reaches its timeline: paused at frame i's time.
    const fs::path page = dir / ("frame" + std::to_string(i) + ".html"), shot = dir / ("chromium" + std::to_string(i) + ".png");
    std::ofstream(page) << "<!DOCTYPE html><html><head><style>html,body{margin:0;padding:0;overflow:hidden;"
                           "background:transparent}svg{display:block}</style></head><body>"
                        << svg << "<script>const svg = document.querySelector('svg'); svg.pauseAnimations(); "
                        << "svg.setCurrentTime(" << i / out.fps << ");</script></body></html>\n";
    // Root (CI) needs --no-sandbox; a transparent default background keeps the alpha mask the art's; a
    // profile of its own keeps a Chromium already running (another test run) from taking the page over.
    const std::string command = "chromium --headless --no-sandbox --disable-gpu --hide-scrollbars "
                                "--user-data-dir='" + (dir / "profile").string() + "' "
                                "--default-background-color=00000000 --window-size=" +
                                std::to_string(ours.width) + "," + std::to_string(ours.height) + " --screenshot='" +
                                shot.string() + "' 'file://" + page.string() + "' >/dev/null 2>&1";
    REQUIRE(std::system(command.c_str()) == 0);
    const Image theirs = read_rgba(shot);
    REQUIRE(theirs.width == ours.width);
    REQUIRE(theirs.height == ours.height);
    const double iou = alpha_iou(ours, theirs);
    INFO("frame " << i << " at " << i / out.fps << " s");
    CHECK(iou >= kMinIou);
  }
}

TEST_CASE("svg-anim: the SVG frames' groups and ids, each path's d over N + 1 values ending on frame 0, one cycle N / fps long") {
  const World world = big_star_world();
  const animpak::test::TempDir temp("animpak-animation-");
  const auto dir = temp / "svg-anim";
  FrameOutput out = animated_output(dir, {FrameFormat::svg, FrameFormat::svg_anim});
  write_frames(world, world.state, out);
  const std::string svg = text_of(dir / "animation.svg"), frame0 = text_of(dir / "frames" / "frame_0000.svg");
  auto group_ids = [](const std::string& text) {
    std::vector<std::string> ids;
    const std::regex group("<g id=\"([^\"]*)\">|<path id=\"([^\"]*)\"");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), group); it != std::sregex_iterator(); ++it)
      ids.push_back((*it)[1].matched ? (*it)[1].str() : (*it)[2].str());
    return ids;
  };
  CHECK(group_ids(svg) == group_ids(frame0));
  CHECK_THAT(svg, Contains("<path id=\"container\" d=\"M"));

  const std::regex animate("<animate attributeName=\"d\" dur=\"([^\"]*)\" repeatCount=\"indefinite\" "
                           "calcMode=\"linear\" keyTimes=\"([^\"]*)\" values=\"([^\"]*)\"/>");
  std::smatch m;
  REQUIRE(std::regex_search(svg, m, animate));
  CHECK(m[1] == "0.24s");  // 6 frames at 25 per second
  CHECK(m[2] == "0;0.166667;0.333333;0.5;0.666667;0.833333;1");
  std::vector<std::string> values;
  std::stringstream list(m[3]);
  for (std::string v; std::getline(list, v, ';');) values.push_back(v);
  REQUIRE(values.size() == kFrames + 1);
  CHECK(values.back() == values.front());
  CHECK(values[1] != values[0]);

  out.interpolation = Interpolation::hold;
  write_frames(world, world.state, out);
  const std::string held = text_of(dir / "animation.svg");
  CHECK_THAT(held, Contains("calcMode=\"discrete\" keyTimes=\"0;0.166667;0.333333;0.5;0.666667;0.833333\""));
}

TEST_CASE("animated formats: --precision sets the decimals of a pixel kept") {
  const World world = big_star_world();
  const animpak::test::TempDir temp("animpak-animation-");
  const auto dir = temp / "precision";
  FrameOutput out = animated_output(dir, {FrameFormat::lottie});
  // The most decimals of any point, [x,y] (colours have four numbers, widths one).
  auto longest_decimals = [&] {
    const std::string text = text_of(dir / "animation.json");
    std::size_t longest = 0;
    const std::regex point("\\[-?[0-9]+(\\.[0-9]+)?,-?[0-9]+(\\.[0-9]+)?\\]");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), point); it != std::sregex_iterator(); ++it)
      for (int c : {1, 2}) longest = std::max(longest, (*it)[c].matched ? std::size_t((*it)[c].length() - 1) : 0);
    return longest;
  };
  out.precision = 0;
  write_frames(world, world.state, out);
  const auto coarse = fs::file_size(dir / "animation.json");
  CHECK(longest_decimals() == 0);
  out.precision = 3;
  write_frames(world, world.state, out);
  CHECK(longest_decimals() == 3);
  CHECK(fs::file_size(dir / "animation.json") > coarse);
}

TEST_CASE("animated formats: a frame whose replayed art lost a path, polyline or point is refused, naming element and frame") {
  const World world = big_star_world();
  const animpak::test::TempDir temp("animpak-animation-");
  const auto dir = temp / "layout";
  fs::create_directories(dir);
  const std::vector<ElementArt> good = frame_art(world, world.state, 0.0);
  auto append_twice = [&](const std::vector<ElementArt>& second) {
    frame_writers::GeometryLog log(world, dir / "scratch");
    log.append(good, 0);
    log.append(second, 1);
  };
  CHECK_NOTHROW(append_twice(good));
  std::vector<ElementArt> broken = good;
  broken[1].points[0][0].pop_back();
  CHECK_THROWS_WITH(append_twice(broken), Contains("element " + world.elements[1].name + ", frame 1, path") &&
                                              Contains("polyline 0:") && Contains("points replayed"));
  broken = good;
  broken[2].points[0].clear();
  CHECK_THROWS_WITH(append_twice(broken), Contains("element " + world.elements[2].name + ", frame 1") &&
                                              Contains("0 polylines replayed"));
  broken = good;
  broken[0].points.clear();
  CHECK_THROWS_WITH(append_twice(broken), Contains("0 paths replayed"));
  CHECK_FALSE(fs::exists(dir / "scratch"));  // the scratch file goes with the log
}

TEST_CASE("animated formats: the scratch file gives back every frame's coordinates and stroke scale") {
  const World world = big_star_world();
  const animpak::test::TempDir temp("animpak-animation-");
  const auto dir = temp / "scratch";
  fs::create_directories(dir);
  frame_writers::GeometryLog log(world, dir / "scratch");
  std::vector<std::vector<ElementArt>> frames;
  for (int i = 0; i < 3; ++i) {
    frames.push_back(frame_art(world, world.state, i / 3.0));
    log.append(frames.back(), i);
  }
  for (int i = 2; i >= 0; --i)
    for (int e = 0; e < int(world.elements.size()); ++e) {
      CHECK(log.stroke_scale(i, e) == frames[i][e].stroke_scale);
      CHECK(log.points(i, e, 0, 0) == frames[i][e].points[0][0]);
    }
}
