// Mirror symmetry as a user packs it (docs/scene-format.md, "Mirror"): the frames are symmetric about the
// line to a pixel, every element stays on its side of the line with its reflection on the other, and no art
// overlaps or touches, its own image included, at the frames or between slices.
#include <catch2/catch.hpp>

#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "run_animpak.hpp"
#include "scene/tiny_scenes.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Rgba8 {
  int width = 0, height = 0, channels = 0;
  std::vector<unsigned char> pixels;
  int at(int x, int y, int c) const { return pixels[(std::size_t(y) * width + x) * channels + c]; }
};

Rgba8 read_png(const fs::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  REQUIRE(in);
  Rgba8 image{in->spec().width, in->spec().height, in->spec().nchannels, {}};
  image.pixels.resize(std::size_t(image.width) * image.height * image.channels);
  REQUIRE(in->read_image(0, 0, 0, -1, OIIO::TypeDesc::UINT8, image.pixels.data()));
  return image;
}

// The heart container is symmetric about x = 250.02 in its art's coordinates (its tip and notch lie there).
std::string mirrored_scene(const std::string& mirror) {
  std::string scene = animpak::test::star_scene(4, 12, 1, {", \"mirror\": " + mirror, R"("initial_scale": 0.12)"});
  return scene;
}

}  // namespace

TEST_CASE("mirror: frames symmetric to a pixel, each element on its side of the line, no overlap across it") {
  const animpak::test::TempDir dir("animpak-mirror-");
  std::ofstream(dir / "scene.json") << mirrored_scene(R"({"x": 250.02})");
  const std::string packed = (dir / "packed").string();
  const CommandResult pack =
      run_animpak("pack " + (dir / "scene.json").string() + " --out " + packed +
                  " --max-iterations 2000 --frames 6 --size 160 --format png,svg,svg-anim,lottie");
  INFO(pack.err);
  REQUIRE(pack.code == 0);
  const json stats = json::parse(read_text(fs::path(packed) / "stats.json"));
  for (const char* when : {"frames", "between_slices"}) {
    INFO(when);
    CHECK(stats["quality"][when]["overlapping_pair_frames"] == 0);
    CHECK(stats["quality"][when]["element_frames_outside"] == 0);
    // Eight elements drawn: four and their images, none touching another.
    CHECK(stats["quality"][when]["element_frames"] == 8 * stats["quality"][when]["times"].get<int>());
  }
  // At the frames no art touches another, its own image included.
  CHECK(stats["quality"]["frames"]["min_gap"].get<double>() > 0.0);
  // The animated formats draw the reflections too: a group and a layer each.
  const std::string animated = read_text(fs::path(packed) / "animation.svg"),
                    lottie = read_text(fs::path(packed) / "animation.json");
  for (int k = 1; k <= 4; ++k) {
    const std::string id = "star#" + std::to_string(k);
    INFO(id);
    CHECK(animated.find("<g id=\"" + id + "\"") != std::string::npos);
    CHECK(animated.find("<g id=\"" + id + " mirrored\"") != std::string::npos);
    CHECK(lottie.find("\"nm\":\"" + id + " mirrored\"") != std::string::npos);
  }
  for (int i = 0; i < 6; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d", i);
    INFO(name);
    // The picture against its own reflection: equal but for the anti-aliasing of edges, which Cairo does
    // not sample symmetrically (within 32 levels of 255 at every pixel, 3 at 98 % of them; a packing that
    // is not symmetric differs by up to 255 over whole elements).
    const Rgba8 image = read_png(fs::path(packed) / "frames" / (std::string(name) + ".png"));
    int worst = 0;
    std::size_t off = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        int d = 0;
        for (int c = 0; c < image.channels; ++c)
          d = std::max(d, std::abs(image.at(x, y, c) - image.at(image.width - 1 - x, y, c)));
        worst = std::max(worst, d);
        off += d > 3 ? 1 : 0;
      }
    CHECK(worst <= 32);
    CHECK(off <= std::size_t(image.width) * image.height / 50);
    // Every element's points lie left of the line, every image's right of it (the SVG frames are in the
    // container art's coordinates).
    const std::string svg = read_text(fs::path(packed) / "frames" / (std::string(name) + ".svg"));
    // Each image is its element's points reflected, exactly (to the file's ten digits). The frame's groups
    // are `<g id="NAME">` holding paths whose data are "M x y L x y … Z".
    std::map<std::string, std::vector<std::pair<double, double>>> points;
    for (std::size_t at = svg.find("<g id=\""); at != std::string::npos; at = svg.find("<g id=\"", at + 1)) {
      const std::size_t name_end = svg.find('"', at + 7), end = svg.find("</g>", at);
      const std::string id = svg.substr(at + 7, name_end - at - 7);
      const bool image_of = id.find(" mirrored") != std::string::npos;
      std::istringstream words(svg.substr(name_end, end - name_end));
      for (std::string word; words >> word;) {
        if (word.rfind("d=\"", 0) == 0) word.erase(0, 3);
        if (word.size() < 2 || (word[0] != 'M' && word[0] != 'L') ||
            !(std::isdigit(static_cast<unsigned char>(word[1])) || word[1] == '-'))
          continue;
        std::string y;
        words >> y;
        const double x = std::stod(word.substr(1));
        points[id].push_back({x, std::stod(y)});
        if (image_of ? !(x > 250.02) : !(x < 250.02)) FAIL_CHECK(id << ": a point at x " << x << " on the wrong side");
      }
    }
    CHECK(points.size() == 8);
    // The line is a wall the elements grew against: one comes within 3 % of the container's width of it.
    double nearest = 1e9;
    for (const auto& [id, list] : points)
      if (id.find(" mirrored") == std::string::npos)
        for (const auto& p : list) nearest = std::min(nearest, 250.02 - p.first);
    CHECK(nearest < 15.0);
    for (int k = 1; k <= 4; ++k) {
      const std::string id = "star#" + std::to_string(k);
      const auto& own = points[id];
      const auto& reflected = points[id + " mirrored"];
      REQUIRE(own.size() == reflected.size());
      REQUIRE_FALSE(own.empty());
      double off_by = 0.0;
      for (std::size_t p = 0; p < own.size(); ++p)
        off_by = std::max({off_by, std::abs(reflected[p].first - (2 * 250.02 - own[p].first)),
                           std::abs(reflected[p].second - own[p].second)});
      INFO(id);
      CHECK(off_by < 1e-5);
    }
  }
}
