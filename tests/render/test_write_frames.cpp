#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "animpak/io.hpp"
#include "animpak/render.hpp"
#include "tiny_world.hpp"

using namespace animpak;

namespace {

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("animpak-frames-" + std::to_string(::getpid())) / name;
  std::filesystem::remove_all(dir);
  return dir;
}

std::vector<std::string> sorted_names(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

bool ffmpeg_installed() { return std::system("command -v ffmpeg >/dev/null 2>&1") == 0; }

FrameOutput small_output(const std::filesystem::path& dir, std::vector<FrameFormat> formats) {
  FrameOutput out;
  out.dir = dir;
  out.count = 3;
  out.formats = std::move(formats);
  out.style.size = 64;
  return out;
}

}  // namespace

TEST_CASE("write_frames: png and svg write exactly N frames named frame_0000 on, and one metric each") {
  const World world = tiny_star_world();
  const auto dir = fresh_dir("png-svg");
  const auto metrics = write_frames(world, world.state, small_output(dir, {FrameFormat::png, FrameFormat::svg}));
  CHECK(metrics.size() == 3);
  CHECK(sorted_names(dir / "frames") == std::vector<std::string>{"frame_0000.png", "frame_0000.svg", "frame_0001.png",
                                                                 "frame_0001.svg", "frame_0002.png", "frame_0002.svg"});
  CHECK(sorted_names(dir) == std::vector<std::string>{"frames"});
}

TEST_CASE("write_frames: an SVG frame parses back with one path per art path after the background") {
  const World world = tiny_star_world();
  const auto dir = fresh_dir("svg");
  write_frames(world, world.state, small_output(dir, {FrameFormat::svg}));
  std::ifstream in(dir / "frames" / "frame_0001.svg");
  std::stringstream text;
  text << in.rdbuf();
  const ArtShape parsed = parse_svg(text.str(), "frame_0001.svg");
  std::size_t art_paths = 0;
  for (const ElementInstance& e : world.elements) art_paths += world.library[e.library].art.art.paths.size();
  REQUIRE(parsed.paths.size() == 1 + art_paths);
  // Drawing order survives: the first element's first path (the star body) comes right after the rect.
  const ArtPath& body = world.library[world.elements[0].library].art.art.paths[0];
  CHECK(parsed.paths[1].fill.enabled == body.fill.enabled);
  CHECK(parsed.paths[1].fill.color.r == Approx(body.fill.color.r).margin(1.0 / 255));
  CHECK(parsed.paths[1].stroke.enabled == body.stroke.enabled);
}

TEST_CASE("write_frames: gif and mp4 through ffmpeg are non-empty files") {
  if (!ffmpeg_installed()) {
    WARN("ffmpeg is not installed (not on PATH): gif and mp4 output not tested");
    return;
  }
  const World world = tiny_star_world();
  const auto dir = fresh_dir("video");
  write_frames(world, world.state, small_output(dir, {FrameFormat::gif, FrameFormat::mp4}));
  for (const char* name : {"animation.gif", "animation.mp4"}) {
    INFO(name);
    REQUIRE(std::filesystem::exists(dir / name));
    CHECK(std::filesystem::file_size(dir / name) > 0);
  }
  // Raster frames are the input ffmpeg reads, so they are kept.
  CHECK(std::filesystem::exists(dir / "frames" / "frame_0002.png"));
}
