#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include "animpak/io.hpp"
#include "animpak/render.hpp"
#include "skip.hpp"
#include "temp_dir.hpp"
#include "tiny_world.hpp"

using namespace animpak;

namespace {

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

TEST_CASE(
    "write_frames: png and svg write exactly N frames named frame_0000 on, one metric each and three per slice "
    "interval") {
  const World world = tiny_star_world();
  const animpak::test::TempDir temp("animpak-frames-");
  const auto dir = temp / "png-svg";
  const auto quality = write_frames(world, world.state, small_output(dir, {FrameFormat::png, FrameFormat::svg}));
  REQUIRE(quality.frames.size() == 3);
  CHECK(quality.frames[1].t == Approx(1.0 / 3));  // the tiny world loops: frames at i / 3
  // Four slices: eight points of each of the three intervals, in time order.
  REQUIRE(quality.between_slices.size() == 24);
  for (int i = 0; i < 24; ++i) CHECK(quality.between_slices[i].t == Approx((i / 8 + (i % 8 + 1) / 9.0) / 3));
  CHECK(sorted_names(dir / "frames") == std::vector<std::string>{"frame_0000.png", "frame_0000.svg", "frame_0001.png",
                                                                 "frame_0001.svg", "frame_0002.png", "frame_0002.svg"});
  CHECK(sorted_names(dir) == std::vector<std::string>{"frames"});
}

namespace {

// The SVG's group ids in document order (the importer flattens groups away).
std::vector<std::string> group_ids(const std::string& svg) {
  std::vector<std::string> ids;
  const std::regex group("<g id=\"([^\"]*)\">");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), group); it != std::sregex_iterator(); ++it)
    ids.push_back((*it)[1]);
  return ids;
}

}  // namespace

TEST_CASE("write_frames: an SVG frame parses back to one group per element and the container, measuring the same") {
  World world = tiny_star_world();
  // Push star 0 into star 1 and star 2 half over the container's left edge, so that overlaps and spills
  // are there to be measured both ways.
  const Vec2 into = world.elements[1].position + Vec2{0.04, 0.0} - world.elements[0].position;
  Box container = world.container.bounds();
  const Vec2 out = Vec2{container.min.x, world.elements[2].position.y} - world.elements[2].position;
  for (std::size_t v = 0; v < world.state.x.size(); ++v) {
    const int e = world.topology.element[v];
    const Vec2 shift = e == 0 ? into : e == 2 ? out : Vec2{};
    world.state.x[v] += static_cast<float>(shift.x);
    world.state.y[v] += static_cast<float>(shift.y);
  }
  const animpak::test::TempDir temp("animpak-frames-");
  const auto dir = temp / "svg";
  const PackingQuality quality = write_frames(world, world.state, small_output(dir, {FrameFormat::svg}));
  const FrameMetrics& written = quality.frames.at(1);
  REQUIRE_FALSE(written.overlapping().empty());
  REQUIRE_FALSE(written.elements_outside().empty());

  std::ifstream in(dir / "frames" / "frame_0001.svg");
  std::stringstream text;
  text << in.rdbuf();
  std::vector<std::string> names;
  for (const ElementInstance& e : world.elements) names.push_back(e.name);
  CHECK(group_ids(text.str()) == names);

  const ArtShape parsed = parse_svg(text.str(), "frame_0001.svg");
  std::size_t art_paths = 0;
  for (const ElementInstance& e : world.elements) art_paths += world.library[e.library].art.art.paths.size();
  // The background, the container under the elements, then every element's paths in drawing order.
  REQUIRE(parsed.paths.size() == 2 + art_paths);
  CHECK(parsed.paths[0].id == "background");
  const ArtPath& outline = parsed.paths[1];
  CHECK(outline.id == "container");
  CHECK(outline.fill_rule == FillRule::evenodd);
  CHECK_FALSE(outline.fill.enabled);
  REQUIRE(outline.polylines.size() == 1 + world.container.holes.size());
  const ArtPath& body = world.library[world.elements[0].library].art.art.paths[0];
  CHECK(parsed.paths[2].fill.enabled == body.fill.enabled);
  CHECK(parsed.paths[2].fill.color.r == Approx(body.fill.color.r).margin(1.0 / 255));

  // The frame lies in the container art's coordinates (scaled into the viewport by the importer): map it
  // back onto the unit container through the container's box, then measure it like any regions.
  Box drawn;
  for (Vec2 p : outline.polylines[0].points) drawn.add(p);
  const double scale = container.height() / drawn.height();
  CHECK(drawn.width() * scale == Approx(container.width()).epsilon(1e-6));
  auto to_unit = [&](Vec2 p) { return (p - drawn.min) * scale + container.min; };
  Region frame{{}, FillRule::evenodd};
  for (const Polyline& line : outline.polylines) {
    frame.rings.emplace_back();
    for (Vec2 p : line.points) frame.rings.back().push_back(to_unit(p));
  }
  std::vector<Region> elements;
  std::size_t next = 2;
  for (const ElementInstance& e : world.elements) {
    ArtShape art;
    ArtPoints points;
    for (std::size_t k = 0; k < world.library[e.library].art.art.paths.size(); ++k) {
      art.paths.push_back(parsed.paths[next++]);
      points.emplace_back();
      for (Polyline& line : art.paths.back().polylines) {
        for (Vec2& p : line.points) p = to_unit(p);
        points.back().push_back(line.points);
      }
    }
    elements.push_back(art_region(art, points, scale));
  }
  const FrameMetrics read = measure_regions(elements, frame);
  CHECK(read.coverage == Approx(written.coverage).margin(1e-4));
  CHECK(read.min_gap == Approx(written.min_gap).margin(1e-4));
  CHECK(read.mean_gap == Approx(written.mean_gap).margin(1e-4));
  CHECK(read.channel_cv == Approx(written.channel_cv).margin(1e-4));
  for (std::size_t i = 0; i < world.elements.size(); ++i) {
    INFO("element " << i);
    CHECK(read.area[i] == Approx(written.area[i]).epsilon(1e-4));
    CHECK(read.outside_share[i] == Approx(written.outside_share[i]).margin(1e-4));
  }
  REQUIRE(read.overlaps.size() == written.overlaps.size());
  for (std::size_t k = 0; k < read.overlaps.size(); ++k) {
    CHECK(read.overlaps[k].a == written.overlaps[k].a);
    CHECK(read.overlaps[k].b == written.overlaps[k].b);
    CHECK(read.overlaps[k].share == Approx(written.overlaps[k].share).margin(1e-4));
  }
}

TEST_CASE("write_frames: SVG ids are the element names, XML-escaped and made unique") {
  World world = tiny_star_world();
  world.elements[0].name = "a<b>&\"c\"";
  world.elements[1].name = "container";
  world.elements[2].name = "a<b>&\"c\"";
  const animpak::test::TempDir temp("animpak-frames-");
  const auto dir = temp / "ids";
  FrameOutput out = small_output(dir, {FrameFormat::svg});
  out.count = 1;
  write_frames(world, world.state, out);
  std::ifstream in(dir / "frames" / "frame_0000.svg");
  std::stringstream text;
  text << in.rdbuf();
  CHECK(group_ids(text.str()) ==
        std::vector<std::string>{"a&lt;b&gt;&amp;&quot;c&quot;", "container-2", "a&lt;b&gt;&amp;&quot;c&quot;-2"});
  // Still well-formed XML.
  CHECK(parse_svg(text.str(), "frame_0000.svg").paths.size() > 2);
}

TEST_CASE("write_frames: gif and mp4 through ffmpeg are non-empty files") {
  if (!ffmpeg_installed())
    return animpak::test::skip("ffmpeg is not on PATH (Debian package ffmpeg): gif and mp4 output not tested");
  const World world = tiny_star_world();
  const animpak::test::TempDir temp("animpak-frames-");
  const auto dir = temp / "video";
  write_frames(world, world.state, small_output(dir, {FrameFormat::gif, FrameFormat::mp4}));
  for (const char* name : {"animation.gif", "animation.mp4"}) {
    INFO(name);
    REQUIRE(std::filesystem::exists(dir / name));
    CHECK(std::filesystem::file_size(dir / name) > 0);
  }
  // Raster frames are the input ffmpeg reads, so they are kept.
  CHECK(std::filesystem::exists(dir / "frames" / "frame_0002.png"));
}
