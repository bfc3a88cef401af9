// The animated vector formats against the players people use: the Lottie document drawn by rlottie and the
// SMIL-animated SVG drawn by headless Chromium, paused at a frame's time, must cover what animpak's own PNG
// frame of that index covers (alpha masks' intersection over union ≥ 0.97 for rlottie at slices, ≥ 0.99
// for rlottie between slices and for Chromium everywhere, where it measured 0.9947 at worst); the Lottie document passes a schema check; the keys sit at each element's
// own slice times; the background and container options; the dotLottie zip.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include "animpak/error.hpp"
#include "animpak/render.hpp"
#include "animpak/version.hpp"
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
// Most tests here check the keys of straight motion between slices (motion_curve 0), where the slices alone
// are the motion; the curve's keys between slices have tests of their own below.
World big_star_world(int motion_curve = 0) {
  World world = tiny_star_world();
  world.params.forces.motion_curve = motion_curve;
  return world;
}

FrameOutput animated_output(const fs::path& dir, std::vector<FrameFormat> formats) {
  FrameOutput out;
  out.dir = dir;
  out.count = kFrames;
  out.formats = std::move(formats);
  out.style.size = 320;
  out.style.background = {1, 1, 1, 0};
  out.style.container = ContainerDrawing::none;
  return out;
}

// The tiny world with element 0's slice 1 moved from t = 1/3 to t = 1/4 (frame 1.5 of 6): slices drift
// from their rest times when packed, each element's its own way.
SimState drifted_state(const World& world) {
  SimState state = world.state;
  const SpacetimeElement& lib = world.library[world.elements[0].library];
  const int P = lib.vertices_per_slice(), first = world.elements[0].vertex_begin + P;
  for (int v = 0; v < P; ++v) state.t[first + v] = 0.25f;
  return state;
}

// The tiny world with 8 slices, element 0 no longer turning but sliding along x and back over the loop,
// fast in the middle and slow at the turns (slice s moved by 0.15 (1 − cos 2πs/8) / 2): on the curve its
// points follow straight lines at uneven speed, the motion a key's easing carries.
SimState sliding_state(const World& world) {
  SimState state = world.state;
  const SpacetimeElement& lib = world.library[world.elements[0].library];
  const int P = lib.vertices_per_slice(), first = world.elements[0].vertex_begin;
  for (int s = 1; s < lib.slice_count; ++s) {
    const double offset = 0.075 * (1 - std::cos(2 * M_PI * s / lib.slice_count));
    for (int v = 0; v < P; ++v)
      state.x[first + s * P + v] = float(state.x[first + v] + offset), state.y[first + s * P + v] = state.y[first + v];
  }
  return state;
}

// A Lottie shape property's points at `frame`, as a player computes them: the key before it, moved towards
// the next along the straight line by the key's timing curve (cubic Bézier from (0, 0) over (o.x, o.y)
// and (i.x, i.y) to (1, 1), solved for x by bisection), or held; the layer's position added.
std::vector<Vec2> lottie_points_at(const nlohmann::json& shape, Vec2 layer, double frame) {
  auto points = [&](const nlohmann::json& value) {
    std::vector<Vec2> out;
    for (const auto& v : value["v"]) out.push_back(Vec2{v[0].get<double>(), v[1].get<double>()} + layer);
    return out;
  };
  if (shape["a"] == 0) return points(shape["k"]);
  const nlohmann::json& keys = shape["k"];
  std::size_t k = 0;
  while (k + 1 < keys.size() && keys[k + 1]["t"].get<double>() <= frame) ++k;
  std::vector<Vec2> a = points(keys[k]["s"][0]);
  if (k + 1 == keys.size() || keys[k].contains("h")) return a;
  const std::vector<Vec2> b = points(keys[k + 1]["s"][0]);
  const double s = (frame - keys[k]["t"].get<double>()) / (keys[k + 1]["t"].get<double>() - keys[k]["t"].get<double>());
  const double ox = keys[k]["o"]["x"], oy = keys[k]["o"]["y"], ix = keys[k]["i"]["x"], iy = keys[k]["i"]["y"];
  auto bezier = [](double p1, double p2, double u) {
    return 3 * (1 - u) * (1 - u) * u * p1 + 3 * (1 - u) * u * u * p2 + u * u * u;
  };
  double lo = 0, hi = 1;
  for (int i = 0; i < 60; ++i) (bezier(ox, ix, 0.5 * (lo + hi)) < s ? lo : hi) = 0.5 * (lo + hi);
  const double e = bezier(oy, iy, 0.5 * (lo + hi));
  for (std::size_t v = 0; v < a.size(); ++v) a[v] = a[v] + (b[v] - a[v]) * e;
  return a;
}

// The first shape of the last layer: element 0's outline (layers run from the last-drawn element down).
const nlohmann::json& doc_last_outline(const nlohmann::json& doc) {
  return doc["layers"].back()["shapes"][0]["it"][0]["ks"];
}

// Every shape property of a Lottie document's art layers, with its layer's position.
std::vector<std::pair<const nlohmann::json*, Vec2>> lottie_shapes(const nlohmann::json& doc) {
  std::vector<std::pair<const nlohmann::json*, Vec2>> shapes;
  for (const auto& layer : doc["layers"]) {
    if (!layer.contains("shapes")) continue;
    const Vec2 at{layer["ks"]["p"]["k"][0].get<double>(), layer["ks"]["p"]["k"][1].get<double>()};
    for (const auto& group : layer["shapes"])
      for (const auto& item : group["it"])
        if (item["ty"] == "sh") shapes.emplace_back(&item["ks"], at);
  }
  return shapes;
}

std::vector<double> key_times(const nlohmann::json& property) {
  std::vector<double> times;
  for (const auto& key : property["k"]) times.push_back(key["t"]);
  return times;
}

std::string frame_png(int i) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.png", i);
  return name;
}

bool have_chromium() { return std::system("command -v chromium >/dev/null 2>&1") == 0; }

}  // namespace

TEST_CASE(
    "lottie: animation.json passes the schema check, one layer per element named by its id, one key per slice ending "
    "on frame N") {
  const World world = big_star_world();
  const animpak::test::TempDir temp("animpak-animation-");
  const auto dir = temp / "lottie";
  FrameOutput out = animated_output(dir, {FrameFormat::png, FrameFormat::lottie});
  out.style.container = ContainerDrawing::outline;
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
  for (std::size_t e = 0; e < world.elements.size(); ++e)
    CHECK(doc["layers"][world.elements.size() - e]["nm"] == ids[e]);
  CHECK(ids[0] == world.elements[0].name);

  const nlohmann::json& shape = doc["layers"][1]["shapes"][0]["it"][0];
  REQUIRE(shape["ty"] == "sh");
  const nlohmann::json& keys = shape["ks"]["k"];
  // The 4 slices at t = 0, 1/3, 2/3 and 1: frames 0, 2, 4 and 6, the last wrapping onto frame 0.
  REQUIRE(keys.size() == std::size_t(world.params.element.slices));
  CHECK(key_times(shape["ks"]) == std::vector<double>{0, 2, 4, 6});
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
  animpak::test::skip(
      "rlottie was not found when the build was configured (Debian package librlottie-dev); "
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

TEST_CASE(
    "svg-anim and Chromium: paused at five frames' times, at slices and between them, it covers animpak's PNG frames, "
    "alpha IoU at least 0.99") {
  if (!have_chromium())
    return animpak::test::skip("chromium is not on PATH (Debian package chromium); nothing was compared");
  // Straight lines between slices (keys at the slices), the curve (keys between them too), and a slide at
  // uneven speed (eased keys: calcMode spline).
  for (const int curve : {0, 1, 2}) {
    INFO("motion_curve " << std::min(curve, 1) << (curve == 2 ? ", sliding" : ""));
    const World world = curve == 2 ? [] {
      World w = tiny_star_world(8);
      w.params.forces.motion_curve = 1;
      return w;
    }()
                                   : big_star_world(curve);
    const SimState state = curve == 2 ? sliding_state(world) : world.state;
    const animpak::test::TempDir temp("animpak-animation-");
    const auto dir = temp / "chromium";
    const FrameOutput out = animated_output(dir, {FrameFormat::png, FrameFormat::svg_anim});
    write_frames(world, state, out);
    if (curve == 2)
      CHECK_THAT(text_of(dir / "animation.svg"), Contains("calcMode=\"spline\"") && Contains("keySplines"));
    const std::string svg = text_of(dir / "animation.svg");
    // Frames 1 and 3 lie between two slices. One page holds five copies of the SVG inline in a row, each
    // an outermost <svg> with its own timeline, paused at its frame's time, so that one Chromium run
    // (a few seconds to start) draws all five.
    const std::vector<int> frames{0, 1, kFrames / 3, 3, 2 * kFrames / 3};
    std::vector<Image> ours;
    for (const int i : frames) ours.push_back(read_rgba(dir / "frames" / frame_png(i)));
    const int w = ours[0].width, h = ours[0].height;
    const fs::path page = dir / "frames.html", shot = dir / "chromium.png";
    {
      std::ofstream html(page);
      html << "<!DOCTYPE html><html><head><style>html,body{margin:0;padding:0;overflow:hidden;"
              "background:transparent}div{display:flex}svg{display:block;flex:none}</style></head><body><div>";
      for (std::size_t k = 0; k < frames.size(); ++k) html << svg;
      html << "</div><script>const svgs = document.querySelectorAll('body > div > svg'); const times = [";
      for (std::size_t k = 0; k < frames.size(); ++k) html << (k ? "," : "") << frames[k] / out.fps;
      html << "]; svgs.forEach((s, k) => { s.pauseAnimations(); s.setCurrentTime(times[k]); "
              "});</script></body></html>\n";
    }
    // Root (CI) needs --no-sandbox; a transparent default background keeps the alpha mask the art's; a
    // profile of its own keeps a Chromium already running (another test run) from taking the page over.
    const std::string command =
        "chromium --headless --no-sandbox --disable-gpu --hide-scrollbars "
        "--user-data-dir='" +
        (dir / "profile").string() +
        "' "
        "--default-background-color=00000000 --window-size=" +
        std::to_string(w * int(frames.size())) + "," + std::to_string(h) + " --screenshot='" + shot.string() +
        "' 'file://" + page.string() + "' >/dev/null 2>&1";
    REQUIRE(std::system(command.c_str()) == 0);
    const Image row = read_rgba(shot);
    REQUIRE(row.width == w * int(frames.size()));
    REQUIRE(row.height == h);
    for (std::size_t k = 0; k < frames.size(); ++k) {
      REQUIRE(ours[k].width == w);
      REQUIRE(ours[k].height == h);
      Image theirs{w, h, std::vector<unsigned char>(std::size_t(w) * h * 4)};
      for (int y = 0; y < h; ++y)
        std::copy_n(row.rgba.begin() + (std::size_t(y) * row.width + std::size_t(k) * w) * 4, std::size_t(w) * 4,
                    theirs.rgba.begin() + std::size_t(y) * w * 4);
      const double iou = alpha_iou(ours[k], theirs);
      INFO("frame " << frames[k] << " at " << frames[k] / out.fps << " s");
      CHECK(iou >= 0.99);
    }
  }
}

TEST_CASE(
    "svg-anim: the SVG frames' groups and ids, each path's d over its slices, keyTimes at their times, one cycle N / "
    "fps long") {
  const World world = big_star_world();
  const animpak::test::TempDir temp("animpak-animation-");
  const auto dir = temp / "svg-anim";
  FrameOutput out = animated_output(dir, {FrameFormat::svg, FrameFormat::svg_anim});
  write_frames(world, world.state, out);
  const std::string svg = text_of(dir / "animation.svg"), frame0 = text_of(dir / "frames" / "frame_0000.svg");
  auto group_ids = [](const std::string& text) {
    std::vector<std::string> ids;
    const std::regex group("<g id=\"([^\"]*)\"[^>]*>|<path id=\"([^\"]*)\"");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), group); it != std::sregex_iterator(); ++it)
      ids.push_back((*it)[1].matched ? (*it)[1].str() : (*it)[2].str());
    return ids;
  };
  CHECK(group_ids(svg) == group_ids(frame0));
  CHECK_THAT(svg, Contains("<path id=\"container\" d=\"M"));

  const std::regex animate(
      "<animate attributeName=\"d\" dur=\"([^\"]*)\" repeatCount=\"indefinite\" "
      "calcMode=\"linear\" keyTimes=\"([^\"]*)\" values=\"([^\"]*)\"/>");
  std::smatch m;
  REQUIRE(std::regex_search(svg, m, animate));
  CHECK(m[1] == "0.24s");                          // 6 frames at 25 per second
  CHECK(m[2] == "0;0.3333333333;0.6666666667;1");  // the 4 slices' times
  std::vector<std::string> values;
  std::stringstream list(m[3]);
  for (std::string v; std::getline(list, v, ';');) values.push_back(v);
  REQUIRE(values.size() == std::size_t(world.params.element.slices));
  CHECK(values[1] != values[0]);

  out.interpolation = Interpolation::hold;
  write_frames(world, world.state, out);
  const std::string held = text_of(dir / "animation.svg");
  CHECK_THAT(held, Contains("calcMode=\"discrete\" keyTimes=\"0;0.1666666667;0.3333333333;0.5;0.6666666667;"
                            "0.8333333333\""));
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

TEST_CASE("lottie: keyed at each element's own slice times, a fraction of the per-frame keys' size") {
  const World world = big_star_world();
  const SimState state = drifted_state(world);
  const animpak::test::TempDir temp("animpak-animation-");
  const auto dir = temp / "slices";
  FrameOutput out = animated_output(dir, {FrameFormat::lottie});
  out.count = 60;
  write_frames(world, state, out);
  const nlohmann::json doc = nlohmann::json::parse(text_of(dir / "animation.json"));
  CHECK(lottie_schema::errors(doc).empty());
  const std::size_t elements = world.elements.size();
  REQUIRE(doc["layers"].size() == elements);
  // Layers from the last element down; element 0's slice 1 sits at t = 1/4, frame 15 of 60.
  const nlohmann::json& first = doc["layers"][elements - 1]["shapes"][0]["it"][0]["ks"];
  CHECK(key_times(first) == std::vector<double>{0, 15, 40, 60});
  CHECK(key_times(doc["layers"][0]["shapes"][0]["it"][0]["ks"]) == std::vector<double>{0, 20, 40, 60});
  const auto sliced = fs::file_size(dir / "animation.json");
  // The frames' keys, one per frame: 60 against 4.
  out.interpolation = Interpolation::hold;
  write_frames(world, state, out);
  CHECK(double(sliced) < 0.2 * double(fs::file_size(dir / "animation.json")));
}

TEST_CASE(
    "lottie: each path keyed where its own motion needs it, a slide at uneven speed carried by the keys' easing, and "
    "the document as a player reads it within 3/4 px of the frames at every frame") {
  World world = tiny_star_world(8);
  world.params.forces.motion_curve = 1;
  const SimState state = sliding_state(world);
  const animpak::test::TempDir temp("animpak-animation-");
  FrameOutput out = animated_output(temp / "keyed", {FrameFormat::lottie});
  out.count = 48;
  write_frames(world, state, out);
  const nlohmann::json keyed = nlohmann::json::parse(text_of(temp / "keyed" / "animation.json"));
  CHECK(lottie_schema::errors(keyed).empty());
  // The frames' own points: every frame a held key.
  out.dir = temp / "held", out.interpolation = Interpolation::hold;
  write_frames(world, state, out);
  const nlohmann::json held = nlohmann::json::parse(text_of(temp / "held" / "animation.json"));
  const auto ours = lottie_shapes(keyed), frames = lottie_shapes(held);
  REQUIRE(ours.size() == frames.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < ours.size(); ++k)
    for (int i = 0; i < out.count; ++i) {
      const std::vector<Vec2> player = lottie_points_at(*ours[k].first, ours[k].second, i),
                              truth = lottie_points_at(*frames[k].first, frames[k].second, i);
      REQUIRE(player.size() == truth.size());
      for (std::size_t v = 0; v < player.size(); ++v) worst = std::max(worst, norm(player[v] - truth[v]));
    }
  CHECK(worst <= 0.75 + 0.01);  // the key tolerance, and two roundings to 1/100 px
  // Element 0 (the last layer) slides: straight keys need 23 for its outline here (keyed every one or two
  // frames where the speed changes), eased ones 6.
  const nlohmann::json& slide = doc_last_outline(keyed);
  for (const auto& key : slide["k"]) UNSCOPED_INFO(key["t"] << " " << (key.contains("o") ? key["o"].dump() : ""));
  CHECK(slide["k"].size() <= 8);
  CHECK(std::any_of(slide["k"].begin(), slide["k"].end(),
                    [](const auto& key) { return key.contains("o") && key["o"]["x"] != 0; }));
}

TEST_CASE("lottie: a world that does not loop holds its last slice from frame N - 1 to N") {
  World world = big_star_world();
  world.loop = false;
  FrameOutput out = animated_output("unused", {FrameFormat::lottie});
  out.count = 7;
  const frame_writers::ElementKeys keys = frame_writers::element_keys(world, world.state, 0, out);
  // Frame i at t = i / 6: the slices at frames 0, 2, 4 and 6, then a key at 7 holding the last.
  for (const frame_writers::PathKeys& path : keys.paths) {
    CHECK(path.frames == std::vector<double>{0, 2, 4, 6, 7});
    CHECK(path.lines[4] == path.lines[3]);
  }
  out.count = 1;
  CHECK(frame_writers::element_keys(world, world.state, 0, out).paths[0].frames == std::vector<double>{0});
}

TEST_CASE(
    "lottie and rlottie: keyed at drifted slices, every frame, between slices too, covers the PNG frame, IoU at least "
    "0.99") {
#ifndef ANIMPAK_HAVE_RLOTTIE
  animpak::test::skip(
      "rlottie was not found when the build was configured (Debian package librlottie-dev); "
      "nothing was compared");
#else
  // Straight lines between slices (keys at the slices) and the curve (keys between them too).
  for (const int curve : {0, 1}) {
    INFO("motion_curve " << curve);
    const World world = big_star_world(curve);
    const SimState state = drifted_state(world);
    const animpak::test::TempDir temp("animpak-animation-");
    const auto dir = temp / "rlottie-between";
    write_frames(world, state, animated_output(dir, {FrameFormat::png, FrameFormat::lottie}));
    const nlohmann::json doc = nlohmann::json::parse(text_of(dir / "animation.json"));
    const std::size_t keys = doc["layers"][world.elements.size() - 1]["shapes"][0]["it"][0]["ks"]["k"].size();
    if (curve == 0)
      REQUIRE(keys == 4);
    else
      REQUIRE(keys > 4);
    // Element 0's slices at frames 0, 1.5, 4 and 6, the others' at 0, 2, 4 and 6: frames 1, 3 and 5 lie
    // between two slices of every element, frame 2 between two of element 0's.
    for (int i = 0; i < kFrames; ++i) {
      const PlayerFrame theirs = rlottie_frame(dir / "animation.json", std::size_t(i));
      REQUIRE(theirs.error.empty());
      const Image ours = read_rgba(dir / "frames" / frame_png(i));
      const double iou = alpha_iou(ours, Image{theirs.width, theirs.height, theirs.rgba});
      INFO("frame " << i << ": IoU " << iou);
      CHECK(iou >= 0.99);
    }
  }
#endif
}

TEST_CASE(
    "background none: transparent PNG corners, no Lottie solid layer, no SVG backdrop, and a colour fills all three") {
  const World world = big_star_world();
  const animpak::test::TempDir temp("animpak-animation-");
  const auto dir = temp / "background";
  FrameOutput out =
      animated_output(dir, {FrameFormat::png, FrameFormat::svg, FrameFormat::lottie, FrameFormat::svg_anim});
  out.style.container = ContainerDrawing::outline;
  auto has_solid_layer = [&] {
    const nlohmann::json doc = nlohmann::json::parse(text_of(dir / "animation.json"));
    return std::any_of(doc["layers"].begin(), doc["layers"].end(), [](const auto& l) { return l["ty"] == 1; });
  };
  out.style.background = {1, 1, 1, 0};
  write_frames(world, world.state, out);
  CHECK(read_rgba(dir / "frames" / frame_png(0)).rgba[3] == 0);
  CHECK_FALSE(has_solid_layer());
  CHECK_THAT(text_of(dir / "frames" / "frame_0000.svg"), !Contains("id=\"background\""));
  CHECK_THAT(text_of(dir / "animation.svg"), !Contains("id=\"background\""));

  out.style.background = {30 / 255.0, 30 / 255.0, 30 / 255.0, 1};
  write_frames(world, world.state, out);
  const Image png = read_rgba(dir / "frames" / frame_png(0));
  CHECK(std::vector<int>(png.rgba.begin(), png.rgba.begin() + 4) == std::vector<int>{30, 30, 30, 255});
  CHECK(has_solid_layer());
  CHECK_THAT(text_of(dir / "animation.json"), Contains("\"sc\":\"#1e1e1e\""));
  CHECK_THAT(text_of(dir / "frames" / "frame_0000.svg"),
             Contains("<rect id=\"background\"") && Contains("fill=\"#1e1e1e\""));
  CHECK_THAT(text_of(dir / "animation.svg"), Contains("<rect id=\"background\"") && Contains("fill=\"#1e1e1e\""));
}

TEST_CASE("container fill: its art painted under the elements in the PNG, the SVG frames, Lottie and animated SVG") {
  const World world = big_star_world();
  REQUIRE_FALSE(world.container.art.paths.empty());
  const animpak::test::TempDir temp("animpak-animation-");
  const auto dir = temp / "container";
  FrameOutput out =
      animated_output(dir, {FrameFormat::png, FrameFormat::svg, FrameFormat::lottie, FrameFormat::svg_anim});
  auto opaque_pixels = [&] {
    const Image png = read_rgba(dir / "frames" / frame_png(0));
    std::size_t n = 0;
    for (std::size_t i = 3; i < png.rgba.size(); i += 4) n += png.rgba[i] > 127;
    return n;
  };
  write_frames(world, world.state, out);
  const std::size_t elements_only = opaque_pixels();
  out.style.container = ContainerDrawing::fill;
  write_frames(world, world.state, out);
  // The heart's art, a black stroke, is painted too.
  CHECK(opaque_pixels() > elements_only + 500);
  const Image png = read_rgba(dir / "frames" / frame_png(0));
  const nlohmann::json doc = nlohmann::json::parse(text_of(dir / "animation.json"));
  CHECK(lottie_schema::errors(doc).empty());
  CHECK(doc["layers"].back()["nm"] == "container");  // the bottom layer: the background is transparent
  CHECK(doc["layers"][0]["nm"] != "container");
  for (const fs::path& file : {dir / "frames" / "frame_0000.svg", dir / "animation.svg"}) {
    const std::string svg = text_of(file);
    INFO(file);
    CHECK(svg.find("<g id=\"container-art\">") < svg.find("<path id=\"container\""));
    CHECK_THAT(svg, Contains("<path id=\"container\"") && Contains("stroke=\"none\"/>"));
  }
#ifdef ANIMPAK_HAVE_RLOTTIE
  const PlayerFrame theirs = rlottie_frame(dir / "animation.json", 0);
  REQUIRE(theirs.error.empty());
  CHECK(alpha_iou(png, Image{theirs.width, theirs.height, theirs.rgba}) >= 0.99);
#endif
}

TEST_CASE("dotlottie: animation.lottie is a zip of manifest.json and animations/animation.json, the Lottie document") {
  if (std::system("command -v python3 >/dev/null 2>&1") != 0)
    return animpak::test::skip("python3 is not on PATH; the zip was not opened");
  const World world = big_star_world();
  const animpak::test::TempDir temp("animpak-animation-");
  const auto dir = temp / "dotlottie";
  write_frames(world, world.state, animated_output(dir, {FrameFormat::lottie, FrameFormat::dotlottie}));
  // Python's zipfile checks every entry's CRC (testzip) and unpacks both files beside it.
  const std::string command =
      "python3 -c \"import sys, zipfile; z = zipfile.ZipFile(sys.argv[1]); "
      "assert z.testzip() is None; print(' '.join(z.namelist())); z.extractall(sys.argv[2])\" '" +
      (dir / "animation.lottie").string() + "' '" + (dir / "unzipped").string() + "' > '" +
      (dir / "names.txt").string() + "'";
  REQUIRE(std::system(command.c_str()) == 0);
  CHECK(text_of(dir / "names.txt") == "manifest.json animations/animation.json\n");
  const nlohmann::json manifest = nlohmann::json::parse(text_of(dir / "unzipped" / "manifest.json"));
  CHECK(manifest["animations"][0]["id"] == "animation");
  CHECK(manifest["activeAnimationId"] == "animation");
  CHECK(manifest["generator"] == "animpak " + std::string(animpak::animpak_version));
  CHECK(text_of(dir / "unzipped" / "animations" / "animation.json") == text_of(dir / "animation.json"));
  CHECK(fs::file_size(dir / "animation.lottie") < fs::file_size(dir / "animation.json") / 2);
}
