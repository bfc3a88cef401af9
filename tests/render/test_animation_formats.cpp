// The animated vector formats against the players people use: the Lottie document drawn by rlottie and the
// SMIL-animated SVG drawn by headless Chromium, paused at a frame's time, must cover what animpak's own PNG
// frame of that index covers (alpha masks' intersection over union ≥ 0.97 for rlottie at slices, ≥ 0.99
// for rlottie between slices and for Chromium everywhere, where it measured 0.9966 at worst); the Lottie
// document passes a schema check; each element's transform is keyed at its own slice times and its rigid
// paths written once, a many-path element a fifth of what keying every path's points wrote; detailed art
// written as Bézier curves, a third of its points' size and within ¾ pixel of the frames; the background
// and container options; the dotLottie zip.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <limits>
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

// The share of the way a player is from a key towards the next at the share s of the interval: the key's
// timing curve (cubic Bézier from (0, 0) over (o.x, o.y) and (i.x, i.y) to (1, 1), solved for x by
// bisection; a multi-dimensional property's easing comes as one-entry arrays).
double eased_share(const nlohmann::json& key, double s) {
  auto first = [](const nlohmann::json& v) { return v.is_array() ? v[0].get<double>() : v.get<double>(); };
  const double ox = first(key["o"]["x"]), oy = first(key["o"]["y"]), ix = first(key["i"]["x"]),
               iy = first(key["i"]["y"]);
  auto bezier = [](double p1, double p2, double u) {
    return 3 * (1 - u) * (1 - u) * u * p1 + 3 * (1 - u) * u * u * p2 + u * u * u;
  };
  double lo = 0, hi = 1;
  for (int i = 0; i < 60; ++i) (bezier(ox, ix, 0.5 * (lo + hi)) < s ? lo : hi) = 0.5 * (lo + hi);
  return bezier(oy, iy, 0.5 * (lo + hi));
}

// A property's value at `frame` as a player computes it, `value` reading one key's start value: the key
// before the frame moved towards the next along the straight line by the key's easing, or held.
template <class Value>
auto property_at(const nlohmann::json& property, double frame, Value value) {
  if (property["a"] == 0) return value(property["k"], false);
  const nlohmann::json& keys = property["k"];
  std::size_t k = 0;
  while (k + 1 < keys.size() && keys[k + 1]["t"].get<double>() <= frame) ++k;
  auto a = value(keys[k]["s"], true);
  if (k + 1 == keys.size() || keys[k].contains("h") || frame <= keys[k]["t"].get<double>()) return a;
  const auto b = value(keys[k + 1]["s"], true);
  const double s = (frame - keys[k]["t"].get<double>()) / (keys[k + 1]["t"].get<double>() - keys[k]["t"].get<double>());
  const double e = eased_share(keys[k], s);
  for (std::size_t v = 0; v < a.size(); ++v) a[v] = a[v] + (b[v] - a[v]) * e;
  return a;
}

// A Lottie shape property's points at `frame`, in its layer's coordinates.
std::vector<Vec2> lottie_points_at(const nlohmann::json& shape, double frame) {
  return property_at(shape, frame, [](const nlohmann::json& value, bool keyed) {
    std::vector<Vec2> out;
    for (const auto& v : (keyed ? value[0] : value)["v"]) out.push_back(Vec2{v[0].get<double>(), v[1].get<double>()});
    return out;
  });
}

// A number or vector property's numbers at `frame`.
std::vector<double> lottie_numbers_at(const nlohmann::json& property, double frame) {
  return property_at(property, frame, [](const nlohmann::json& value, bool) {
    std::vector<double> out;
    if (value.is_array())
      for (const auto& x : value) out.push_back(x.get<double>());
    else
      out.push_back(value.get<double>());
    return out;
  });
}

// Where a transform (a layer's ks, a group's tr) takes its points `q` at `frame`: p + R(r) · (s / 100) · (q − a),
// Lottie's order, R turning clockwise on screen by r degrees.
void lottie_transform(const nlohmann::json& ks, std::vector<Vec2>& q, double frame) {
  const std::vector<double> p = lottie_numbers_at(ks["p"], frame), a = lottie_numbers_at(ks["a"], frame),
                            s = lottie_numbers_at(ks["s"], frame);
  const double r = lottie_numbers_at(ks["r"], frame)[0] * M_PI / 180;
  for (Vec2& v : q) {
    const double x = (v.x - a[0]) * s[0] / 100, y = (v.y - a[1]) * s[1] / 100;
    v = {p[0] + std::cos(r) * x - std::sin(r) * y, p[1] + std::sin(r) * x + std::cos(r) * y};
  }
}

// The first shape of the last layer: element 0's outline (layers run from the last-drawn element down).
const nlohmann::json& doc_last_outline(const nlohmann::json& doc) {
  return doc["layers"].back()["shapes"][0]["it"][0]["ks"];
}

// Every shape property of a Lottie document's art layers, with its group's transform and its layer's.
struct LottieShape {
  const nlohmann::json *shape, *group, *layer;
};
std::vector<LottieShape> lottie_shapes(const nlohmann::json& doc) {
  std::vector<LottieShape> shapes;
  for (const auto& layer : doc["layers"]) {
    if (!layer.contains("shapes")) continue;
    for (const auto& group : layer["shapes"])
      for (const auto& item : group["it"])
        if (item["ty"] == "sh") shapes.push_back({&item["ks"], &group["it"].back(), &layer["ks"]});
  }
  return shapes;
}

// Where a player draws points `q` of a shape at `frame`: its group's transform, then its layer's.
void lottie_drawn(const LottieShape& shape, std::vector<Vec2>& q, double frame) {
  lottie_transform(*shape.group, q, frame);
  lottie_transform(*shape.layer, q, frame);
}

// A Lottie shape property at `frame` as a player computes it: its vertices, then their in tangents, then
// their out tangents (each key's "v", "i" and "o" moved together), and whether it is closed.
std::vector<Vec2> lottie_bezier_at(const nlohmann::json& shape, double frame, bool& closed) {
  const nlohmann::json& first = shape["a"] == 0 ? shape["k"] : shape["k"][0]["s"][0];
  closed = first["c"].get<bool>();
  return property_at(shape, frame, [](const nlohmann::json& value, bool keyed) {
    std::vector<Vec2> out;
    for (const char* part : {"v", "i", "o"})
      for (const auto& v : (keyed ? value[0] : value)[part])
        out.push_back(Vec2{v[0].get<double>(), v[1].get<double>()});
    return out;
  });
}

// The distance from p to the segment ab.
double to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double length2 = dot(d, d);
  const double s = length2 > 0 ? std::clamp(dot(p - a, d) / length2, 0.0, 1.0) : 0.0;
  return norm(p - (a + d * s));
}

// The farthest a point of either line lies from the other line (each a chain of segments): their
// Hausdorff distance.
double chains_apart(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  const auto farthest = [](const std::vector<Vec2>& from, const std::vector<Vec2>& to) {
    double worst = 0.0;
    for (Vec2 p : from) {
      double nearest = to.size() == 1 ? norm(p - to[0]) : std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k + 1 < to.size(); ++k) nearest = std::min(nearest, to_segment(p, to[k], to[k + 1]));
      worst = std::max(worst, nearest);
    }
    return worst;
  };
  return std::max(farthest(a, b), farthest(b, a));
}

// A shape's Bézier segments (lottie_bezier_at's vertices and tangents) sampled 16 to a segment, in order,
// a closed one back to its first vertex.
std::vector<Vec2> bezier_samples(const std::vector<Vec2>& parts, bool closed) {
  const std::size_t n = parts.size() / 3;
  std::vector<Vec2> samples;
  if (n == 0) return samples;
  samples.push_back(parts[0]);
  for (std::size_t k = 0; k < (closed ? n : n - 1); ++k) {
    const std::size_t next = (k + 1) % n;
    const Vec2 p0 = parts[k], p1 = parts[k] + parts[2 * n + k], p2 = parts[next] + parts[n + next], p3 = parts[next];
    for (int i = 1; i <= 16; ++i) {
      const double u = i / 16.0, v = 1 - u;
      samples.push_back(v * v * v * p0 + 3 * v * v * u * p1 + 3 * v * u * u * p2 + u * u * u * p3);
    }
  }
  return samples;
}

// The farthest any shape of `keyed` lies, at any of `count` frames, from the same shape of `held` (the
// frames' own points, every frame a held key), both as a player draws them, at every `step`th frame: the
// keyed shape's Bézier
// segments against the held polyline (a Hausdorff distance, so that a curve with fewer vertices than the
// polyline's points is measured along its whole length).
double farthest_from_frames(const nlohmann::json& keyed, const nlohmann::json& held, int count, int step = 1) {
  const auto ours = lottie_shapes(keyed), frames = lottie_shapes(held);
  REQUIRE(ours.size() == frames.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < ours.size(); ++k)
    for (int i = 0; i < count; i += step) {
      bool closed = true, truth_closed = true;
      const std::vector<Vec2> parts = lottie_bezier_at(*ours[k].shape, i, closed);
      std::vector<Vec2> player = bezier_samples(parts, closed);
      std::vector<Vec2> truth = lottie_points_at(*frames[k].shape, i);
      lottie_bezier_at(*frames[k].shape, i, truth_closed);
      REQUIRE(closed == truth_closed);
      if (truth.empty()) continue;
      if (truth_closed) truth.push_back(truth.front());
      lottie_drawn(ours[k], player, i);
      lottie_drawn(frames[k], truth, i);
      worst = std::max(worst, chains_apart(player, truth));
    }
  return worst;
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

// Headless Chromium's pictures of an animated SVG paused at `frames` (at frame / fps seconds), each w × h:
// one page holds a copy of the SVG inline per frame in a row, each an outermost <svg> with its own
// timeline, paused at its frame's time, so that one Chromium run (a few seconds to start) draws them all.
std::vector<Image> chromium_frames(const fs::path& dir, const std::string& svg, const std::vector<int>& frames,
                                   double fps, int w, int h) {
  const fs::path page = dir / "frames.html", shot = dir / "chromium.png";
  {
    std::ofstream html(page);
    html << "<!DOCTYPE html><html><head><style>html,body{margin:0;padding:0;overflow:hidden;"
            "background:transparent}div{display:flex}svg{display:block;flex:none}</style></head><body><div>";
    for (std::size_t k = 0; k < frames.size(); ++k) html << svg;
    html << "</div><script>const svgs = document.querySelectorAll('body > div > svg'); const times = [";
    for (std::size_t k = 0; k < frames.size(); ++k) html << (k ? "," : "") << frames[k] / fps;
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
  std::vector<Image> drawn;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    Image theirs{w, h, std::vector<unsigned char>(std::size_t(w) * h * 4)};
    for (int y = 0; y < h; ++y)
      std::copy_n(row.rgba.begin() + (std::size_t(y) * row.width + std::size_t(k) * w) * 4, std::size_t(w) * 4,
                  theirs.rgba.begin() + std::size_t(y) * w * 4);
    drawn.push_back(std::move(theirs));
  }
  return drawn;
}

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

  const nlohmann::json& layer = doc["layers"][1];
  const nlohmann::json& shape = layer["shapes"][0]["it"][0];  // the eye, a 32-point circle
  REQUIRE(layer["shapes"][0]["nm"] == "eye");
  REQUIRE(shape["ty"] == "sh");
  // The stars turn whole: each outline is written once in its layer, and the layer's transform is keyed at
  // the 4 slices at t = 0, 1/3, 2/3 and 1 (frames 0, 2, 4 and 6, the last wrapping onto frame 0), and
  // between them where the straight lines between slices turn and shrink the star along its chords.
  CHECK(shape["ks"]["a"] == 0);
  const std::vector<double> times = key_times(layer["ks"]["r"]);
  for (const double slice : {0, 2, 4, 6}) CHECK(std::count(times.begin(), times.end(), slice) == 1);
  CHECK(times.back() == kFrames);
  CHECK(key_times(layer["ks"]["p"]) == times);
  CHECK(key_times(layer["ks"]["s"]) == times);
  CHECK(layer["ks"]["r"]["k"][1]["s"] != layer["ks"]["r"]["k"][0]["s"]);  // the stars rotate
  // The outline, a polygon, keeps its 10 corners and straight sides (every tangent zero); the eye, a
  // circle flattened to 32 points, is a few cubic segments (docs/animation-formats.md, "Curves").
  const nlohmann::json& body = layer["shapes"].back();
  REQUIRE(body["nm"] == "body");
  CHECK(body["it"][0]["ks"]["k"]["v"].size() == 10);
  for (const char* tangent : {"i", "o"})
    for (const auto& zero : body["it"][0]["ks"]["k"][tangent]) CHECK(zero == nlohmann::json::array({0, 0}));
  CHECK(shape["ks"]["k"]["v"].size() < 8);
  CHECK(shape["ks"]["k"]["i"][0] != nlohmann::json::array({0, 0}));
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
  // The layer's transform carries the motion; its first key (the chords of the first slice's interval
  // start straight) eases linearly.
  const nlohmann::json& key = linear["layers"][0]["ks"]["r"]["k"][0];
  CHECK_FALSE(key.contains("h"));
  CHECK(key["o"]["x"][0] == 0);
  CHECK(key["i"]["x"][0] == 1);
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
  doc["layers"][0]["ks"]["r"]["k"][2]["t"] = "2";
  CHECK(only_error(doc) == "layers[0].ks.r.k[2].t: expected a number");
  doc = good;
  doc["layers"][0]["ks"]["r"]["k"][3]["t"] = doc["layers"][0]["ks"]["r"]["k"][1]["t"];
  CHECK(only_error(doc) == "layers[0].ks.r.k[3].t: not after the previous keyframe");
  doc = good;
  doc["layers"][2]["shapes"][0]["it"][0]["ks"]["k"]["i"].erase(0);
  CHECK(only_error(doc) == "layers[2].shapes[0].it[0].ks.k.i: not as many points as v");
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
    // Frames 1 and 3 lie between two slices.
    const std::vector<int> frames{0, 1, kFrames / 3, 3, 2 * kFrames / 3};
    std::vector<Image> ours;
    for (const int i : frames) ours.push_back(read_rgba(dir / "frames" / frame_png(i)));
    const std::vector<Image> drawn = chromium_frames(dir, svg, frames, out.fps, ours[0].width, ours[0].height);
    for (std::size_t k = 0; k < frames.size(); ++k) {
      REQUIRE(ours[k].width == drawn[k].width);
      REQUIRE(ours[k].height == drawn[k].height);
      const Image& theirs = drawn[k];
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

  // The stars turn whole: their paths' d is still, their groups' transform animated, moved, turned and
  // scaled in that order, keyed at the slices' times and between them.
  CHECK_THAT(svg, !Contains("<animate attributeName=\"d\""));
  const std::regex animate(
      "<animateTransform attributeName=\"transform\" type=\"(translate|rotate|scale)\" "
      "additive=\"(replace|sum)\" dur=\"([^\"]*)\" repeatCount=\"indefinite\" "
      "calcMode=\"(linear|spline)\" keyTimes=\"([^\"]*)\"[^>]* values=\"([^\"]*)\"/>");
  std::vector<std::string> types;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), animate); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    types.push_back(m[1].str() + " " + m[2].str());
    CHECK(m[3] == "0.24s");  // 6 frames at 25 per second
    std::vector<std::string> times, values;
    std::stringstream time_list(m[5]), value_list(m[6]);
    for (std::string t; std::getline(time_list, t, ';');) times.push_back(t);
    for (std::string v; std::getline(value_list, v, ';');) values.push_back(v);
    for (const char* slice : {"0", "0.3333333333", "0.6666666667", "1"})  // the 4 slices' times
      CHECK(std::count(times.begin(), times.end(), slice) == 1);
    REQUIRE(values.size() == times.size());
    if (m[1] == "rotate") CHECK(values[1] != values[0]);  // the stars turn in place
  }
  const std::vector<std::string> element{"translate replace", "rotate sum", "scale sum"};
  std::vector<std::string> expected;
  for (std::size_t e = 0; e < world.elements.size(); ++e)
    expected.insert(expected.end(), element.begin(), element.end());
  CHECK(types == expected);

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
  // The stars turn whole, their layers' transforms keyed at their slices (and between them).
  for (const auto& [layer, slices] : {std::pair{elements - 1, std::vector<double>{0, 15, 40, 60}},
                                      std::pair{std::size_t(0), std::vector<double>{0, 20, 40, 60}}}) {
    INFO("layer " << layer);
    const std::vector<double> times = key_times(doc["layers"][layer]["ks"]["r"]);
    for (const double slice : slices) CHECK(std::count(times.begin(), times.end(), slice) == 1);
    CHECK(doc["layers"][layer]["shapes"][0]["it"][0]["ks"]["a"] == 0);
  }
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
  CHECK(farthest_from_frames(keyed, held, out.count) <= 0.75 + 0.01);  // the key tolerance, and roundings
  // Element 0 (the last layer) slides: its outline still, its layer's position keyed, some keys eased. Its
  // outline keyed on its own points to the key tolerance (0.27 pixels here) took 23 straight keys (every
  // one or two frames where the speed changes) or 6 eased ones; its placement, held to a quarter of that,
  // takes 9.
  CHECK(doc_last_outline(keyed)["a"] == 0);
  const nlohmann::json& slide = keyed["layers"].back()["ks"]["p"];
  for (const auto& key : slide["k"]) UNSCOPED_INFO(key["t"] << " " << (key.contains("o") ? key["o"].dump() : ""));
  CHECK(slide["k"].size() <= 10);
  CHECK(std::any_of(slide["k"].begin(), slide["k"].end(),
                    [](const auto& key) { return key.contains("o") && key["o"]["x"][0] != 0; }));
}

TEST_CASE("lottie: a world that does not loop holds its last slice from frame N - 1 to N") {
  World world = big_star_world();
  world.loop = false;
  FrameOutput out = animated_output("unused", {FrameFormat::lottie});
  out.count = 7;
  const frame_writers::ElementKeys keys = frame_writers::element_keys(world, world.state, 0, out);
  // Frame i at t = i / 6: the slices at frames 0, 2, 4 and 6, then a key at 7 holding the last. The star
  // turns whole: its placement is keyed, its paths written once.
  for (const double slice : {0, 2, 4, 6}) CHECK(std::count(keys.frames.begin(), keys.frames.end(), slice) == 1);
  REQUIRE(keys.frames.size() >= 5);
  const std::size_t last = keys.frames.size() - 1;
  CHECK(keys.frames[last - 1] == 6);
  CHECK(keys.frames[last] == 7);
  CHECK(keys.placements[last].position == keys.placements[last - 1].position);
  CHECK(keys.placements[last].angle == keys.placements[last - 1].angle);
  CHECK(keys.placements[last].scale == keys.placements[last - 1].scale);
  for (const frame_writers::PathKeys& path : keys.paths) CHECK(path.frames == std::vector<double>{0});
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
    // Element 0 turns: its layer's transform keyed at its slices and between them.
    const nlohmann::json& layer = doc["layers"][world.elements.size() - 1];
    const std::vector<double> times = key_times(layer["ks"]["r"]);
    REQUIRE(times.size() > 4);
    if (curve == 0)
      for (const double slice : {0.0, 1.5, 4.0, 6.0}) CHECK(std::count(times.begin(), times.end(), slice) == 1);
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

namespace {

// Three bees (examples/crossing/bee.svg: 46 paths) turning on the spline through 8 slices, a third of the
// container's size, built as tiny_star_world is (no simulation steps): each moves rigidly, its art turned
// whole, but element 0, squashed to 92 % of its height about its middle at slice 4, deforms over the
// quarter of the loop around that slice.
World bee_world(const std::string& art = "crossing/bee.svg") {
  const std::string examples = std::string(ANIMPAK_SOURCE_DIR) + "/examples";
  SceneSpec scene;
  scene.file = "bee-world";
  scene.container.art = examples + "/shapes/heart-container.path";
  scene.seed = 7;
  scene.params.element.slices = 8;
  scene.params.placement.initial_scale = 0.3;
  LibraryElementSpec bee;
  bee.name = "bee";
  bee.art = examples + "/" + art;
  bee.animation.preset = AnimationPreset::rotate;
  bee.count = 3;
  scene.elements.push_back(bee);
  return make_world(scene);
}

SimState squashed_state(const World& world) {
  SimState state = world.state;
  const SpacetimeElement& lib = world.library[world.elements[0].library];
  const int P = lib.vertices_per_slice(), first = world.elements[0].vertex_begin + 4 * P;
  double middle = 0.0;
  for (int v = 0; v < P; ++v) middle += state.y[first + v] / P;
  for (int v = 0; v < P; ++v) state.y[first + v] = float(middle + 0.92 * (state.y[first + v] - middle));
  return state;
}

}  // namespace

TEST_CASE(
    "lottie and svg-anim: a many-path element moving rigidly is its layer's transform and its paths written once, a "
    "fifth of per-path keys' size, as close to the frames under a player, rlottie and Chromium") {
  const World world = bee_world();
  const SimState state = squashed_state(world);
  REQUIRE(world.library[0].art.art.paths.size() >= 40);
  const animpak::test::TempDir temp("animpak-animation-");
  const auto dir = temp / "placed";
  FrameOutput out = animated_output(dir, {FrameFormat::png, FrameFormat::lottie, FrameFormat::svg_anim});
  out.count = 24;
  write_frames(world, state, out);
  const nlohmann::json keyed = nlohmann::json::parse(text_of(dir / "animation.json"));
  const std::vector<std::string> errors = lottie_schema::errors(keyed);
  for (const std::string& e : errors) UNSCOPED_INFO(e);
  CHECK(errors.empty());
  // Every bee's layer turns; the rigid bees' paths are still, the squashed one's keyed only where the
  // squash reaches (the spline carries it a little beyond the slices next to slice 4, none in the first
  // quarter of the loop).
  REQUIRE(keyed["layers"].size() == 3);
  for (std::size_t l = 0; l < 3; ++l) {
    INFO("layer " << l);
    CHECK(keyed["layers"][l]["ks"]["r"]["a"] == 1);
    std::size_t moving = 0;
    for (const auto& group : keyed["layers"][l]["shapes"])
      for (const auto& item : group["it"]) {
        if (item["ty"] != "sh" || item["ks"]["a"] == 0) continue;
        ++moving;
        for (double t : key_times(item["ks"])) CHECK((t == 0 || t > out.count / 4));
      }
    if (l < 2)
      CHECK(moving == 0);
    else
      CHECK(moving > 0);
  }
  const auto placed_lottie = fs::file_size(dir / "animation.json"), placed_svg = fs::file_size(dir / "animation.svg");

  // The frames' own points, every frame a held key: the keyed document as a player reads it stays within
  // the key tolerance of them (and the roundings of points, position, angle and scale).
  FrameOutput held_out = animated_output(temp / "held", {FrameFormat::lottie, FrameFormat::svg_anim});
  held_out.count = out.count, held_out.interpolation = Interpolation::hold;
  write_frames(world, state, held_out);
  const nlohmann::json held = nlohmann::json::parse(text_of(temp / "held" / "animation.json"));
  CHECK(farthest_from_frames(keyed, held, out.count) <= 0.75 + 0.02);
  // Each path keyed on its own points (0.17.0) wrote 1.17 times the held Lottie document here (2,635,590
  // bytes) and 1.09 times the held SVG; the element's frame, a fifth of that at most.
  const auto held_lottie = fs::file_size(temp / "held" / "animation.json"),
             held_svg = fs::file_size(temp / "held" / "animation.svg");
  INFO("Lottie " << placed_lottie << " of " << held_lottie << " bytes held, SVG " << placed_svg << " of " << held_svg);
  CHECK(double(placed_lottie) <= 1.17 / 5 * double(held_lottie));
  CHECK(double(placed_svg) <= 1.09 / 5 * double(held_svg));

#ifdef ANIMPAK_HAVE_RLOTTIE
  for (int i = 0; i < out.count; ++i) {
    const PlayerFrame theirs = rlottie_frame(dir / "animation.json", std::size_t(i));
    REQUIRE(theirs.error.empty());
    const double iou =
        alpha_iou(read_rgba(dir / "frames" / frame_png(i)), Image{theirs.width, theirs.height, theirs.rgba});
    INFO("rlottie, frame " << i << ": IoU " << iou);
    CHECK(iou >= 0.99);
  }
#endif
  if (!have_chromium()) return;
  // Slices at frames 0, 3, 6, …: 1, 4, 10, 11 and 13 lie between two, 12 is the squashed slice.
  const std::vector<int> frames{0, 1, 4, 10, 11, 12, 13, 21};
  std::vector<Image> ours;
  for (const int i : frames) ours.push_back(read_rgba(dir / "frames" / frame_png(i)));
  const std::vector<Image> drawn =
      chromium_frames(dir, text_of(dir / "animation.svg"), frames, out.fps, ours[0].width, ours[0].height);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const double iou = alpha_iou(ours[k], drawn[k]);
    INFO("Chromium, frame " << frames[k] << ": IoU " << iou);
    // Chromium draws the Bézier curves a little off cairo's polylines where rlottie does not (its paths
    // within 0.05 pixels of the polylines, rlottie 0.9907 at worst): 0.9864 at worst (frame 12), 0.9924–
    // 0.9945 at the rigid frames; written point by point, 0.9918 and 0.9972–0.9983.
    CHECK(iou >= 0.985);
  }
}

TEST_CASE(
    "lottie and svg-anim: detailed art's paths are cubic Bezier curves, smaller than point by point and as close to "
    "the frames under a player and rlottie") {
  // Three frogs (examples/crossing/frog.svg: 72 paths, 5,425 points flattened from its curves) turning
  // through 8 slices, one squashed at slice 4 as the bees are: their outlines are flattened finely
  // (0.1 art units, about 0.02 pixels here), so the curves take a small share of the points.
  const World world = bee_world("crossing/frog.svg");
  const SimState state = squashed_state(world);
  REQUIRE(world.library[0].art.art.paths.size() >= 70);
  const animpak::test::TempDir temp("animpak-animation-");
  FrameOutput out = animated_output(temp / "curves", {FrameFormat::png, FrameFormat::lottie, FrameFormat::svg_anim});
  out.count = 24;
  write_frames(world, state, out);
  const nlohmann::json keyed = nlohmann::json::parse(text_of(temp / "curves" / "animation.json"));
  CHECK(lottie_schema::errors(keyed).empty());
  std::size_t curved = 0, vertices = 0;  // tangents that are not [0, 0], and vertices, over every key
  for (const LottieShape& shape : lottie_shapes(keyed)) {
    const nlohmann::json& ks = *shape.shape;
    const auto count = [&](const nlohmann::json& value) {
      vertices += value["v"].size();
      for (const auto& t : value["o"]) curved += t != nlohmann::json::array({0, 0});
    };
    if (ks["a"] == 0)
      count(ks["k"]);
    else
      for (const auto& key : ks["k"]) count(key["s"][0]);
  }
  CHECK(curved > vertices / 3);  // 4,673 of 5,375 measured

  FrameOutput points_out = out;
  points_out.dir = temp / "points", points_out.curve_tolerance = 0;
  points_out.formats = {FrameFormat::lottie, FrameFormat::svg_anim};
  write_frames(world, state, points_out);
  FrameOutput held_out = animated_output(temp / "held", {FrameFormat::lottie});
  held_out.count = out.count, held_out.interpolation = Interpolation::hold;
  write_frames(world, state, held_out);
  const nlohmann::json held = nlohmann::json::parse(text_of(temp / "held" / "animation.json"));
  // Within the ¾ pixel of the keys and the curves together, and the roundings (measured 0.33 pixels over
  // every frame; every third frame here, each a few seconds of 5,400 points against 5,400 points).
  CHECK(farthest_from_frames(keyed, held, out.count, 3) <= 0.75 + 0.02);
  const auto curves_lottie = fs::file_size(temp / "curves" / "animation.json"),
             curves_svg = fs::file_size(temp / "curves" / "animation.svg"),
             points_lottie = fs::file_size(temp / "points" / "animation.json"),
             points_svg = fs::file_size(temp / "points" / "animation.svg");
  INFO("curves: Lottie " << curves_lottie << " bytes, SVG " << curves_svg << "; point by point: Lottie "
                         << points_lottie << ", SVG " << points_svg);
  // Measured: 477,538 bytes of Lottie against 1,395,599 (0.34), 341,537 of SVG against 777,222 (0.44).
  CHECK(double(curves_lottie) <= 0.45 * double(points_lottie));
  CHECK(double(curves_svg) <= 0.55 * double(points_svg));
#ifdef ANIMPAK_HAVE_RLOTTIE
  for (int i = 0; i < out.count; i += 3) {
    const PlayerFrame theirs = rlottie_frame(temp / "curves" / "animation.json", std::size_t(i));
    REQUIRE(theirs.error.empty());
    const double iou = alpha_iou(read_rgba(temp / "curves" / "frames" / frame_png(i)),
                                 Image{theirs.width, theirs.height, theirs.rgba});
    INFO("rlottie, frame " << i << ": IoU " << iou);
    CHECK(iou >= 0.985);  // measured 0.9906 at worst (frame 9), 0.9924–0.9957 at the others
  }
#endif
}
