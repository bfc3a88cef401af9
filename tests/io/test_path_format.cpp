#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "animpak/error.hpp"
#include "animpak/io.hpp"

using namespace animpak;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

std::string shape_file(const std::string& name) {
  return std::string(ANIMPAK_SOURCE_DIR) + "/examples/shapes/" + name + ".path";
}

bool has_colour(const Paint& paint, int r, int g, int b) {
  return paint.enabled && paint.color.r == r / 255.0 && paint.color.g == g / 255.0 && paint.color.b == b / 255.0 &&
         paint.color.a == 1.0;
}

// A minimal valid file with one triangle; each malformed case below breaks one thing in it.
const std::string kHeader = "1\nforeground_color_rgb 0 -1,-1,-1\nbackground_color_rgb 0 10,20,30\n";
const std::string kTriangle = "0 1 0 0 0 10 0 0 10\n";

/// The InputError message for `text`, or a marker that no error was thrown.
std::string path_error_of(const std::string& text) {
  try {
    parse_path_text(text, "bad.path");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("load_path_file: bird has the body underneath and the white eye on top") {
  const ArtShape bird = load_path_file(shape_file("bird"));
  REQUIRE(bird.paths.size() == 2);
  const ArtPath& body = bird.paths[0];
  const ArtPath& eye = bird.paths[1];
  CHECK(body.source_index == 1);
  CHECK(body.id == "path1");
  CHECK(eye.source_index == 0);
  CHECK(eye.id == "path0");
  CHECK(has_colour(body.fill, 240, 100, 101));
  CHECK(has_colour(eye.fill, 255, 255, 255));
  CHECK_FALSE(body.stroke.enabled);
  CHECK_FALSE(eye.stroke.enabled);
  CHECK(body.stroke_width == 0.0);
  REQUIRE(body.polylines.size() == 1);
  REQUIRE(eye.polylines.size() == 1);
  CHECK(body.polylines[0].points.size() == 185);
  CHECK(eye.polylines[0].points.size() == 32);
  CHECK(body.polylines[0].closed);
  CHECK(eye.polylines[0].points[0].x == 142.96160888671875);
  CHECK(eye.polylines[0].points[0].y == 50.343879699707031);
  CHECK(bird.source == shape_file("bird"));
}

TEST_CASE("load_path_file: heart container keeps its tip and drops the repeated closing point") {
  const ArtShape heart = load_path_file(shape_file("heart-container"));
  REQUIRE(heart.paths.size() == 1);
  const ArtPath& outline = heart.paths[0];
  CHECK(outline.path_type == 0);
  CHECK(has_colour(outline.stroke, 0, 0, 0));
  CHECK(outline.stroke_width == 1.0);
  CHECK_FALSE(outline.fill.enabled);
  REQUIRE(outline.polylines.size() == 1);
  const auto& points = outline.polylines[0].points;
  CHECK(points.size() == 56);
  CHECK(points.front().x == Approx(250.0).margin(0.05));
  CHECK(points.front().y == 474.0);
  CHECK_FALSE(points.back() == points.front());
  double lowest = 0.0;
  for (Vec2 p : points) lowest = std::max(lowest, p.y);
  CHECK(lowest == 474.0);  // y points down: the tip is the largest y
}

TEST_CASE("load_path_file: every example shape loads with drawing order reversed") {
  struct Expected {
    const char* name;
    std::vector<size_t> points_in_file_order;
  };
  const Expected all[] = {{"bird", {32, 185}},    {"cat", {80, 80, 160}},   {"fox", {12, 14, 24, 102}},
                          {"penguin", {32, 244}}, {"snake", {18, 18, 552}}, {"heart-container", {56}}};
  for (const Expected& e : all) {
    INFO(e.name);
    const ArtShape shape = load_path_file(shape_file(e.name));
    const size_t n = e.points_in_file_order.size();
    REQUIRE(shape.paths.size() == n);
    for (size_t k = 0; k < n; ++k) {
      const ArtPath& path = shape.paths[k];
      CHECK(path.source_index == static_cast<int>(n - 1 - k));
      CHECK(path.polylines.at(0).points.size() == e.points_in_file_order[n - 1 - k]);
      CHECK((path.fill.enabled || path.stroke.enabled));
      for (Vec2 p : path.polylines[0].points) CHECK((std::isfinite(p.x) && std::isfinite(p.y)));
    }
    // The animals' bodies are last in the file and red: they come out first, painted underneath.
    if (std::string(e.name) != "heart-container") CHECK(has_colour(shape.paths[0].fill, 240, 100, 101));
  }
}

TEST_CASE("parse_path_text: holes keep pathType 7 and each ring its own colours") {
  const ArtShape donut = parse_path_text(
      "1\nforeground_color_rgb 0 0,0,0 -1,-1,-1\nbackground_color_rgb 0 -1,-1,-1 -1,-1,-1\n"
      "0 0 0 0 0 100 0 100 100 0 100 0 0\n"
      "0 1 7 40 40 60 40 60 60 40 60\n",
      "donut.path");
  REQUIRE(donut.paths.size() == 2);
  CHECK(donut.paths[0].path_type == 7);
  CHECK(donut.paths[0].source_index == 1);
  CHECK_FALSE(donut.paths[0].stroke.enabled);
  CHECK(donut.paths[0].stroke_width == 0.0);
  CHECK(donut.paths[1].path_type == 0);
  CHECK(donut.paths[1].polylines[0].points.size() == 4);
  CHECK(donut.paths[1].polylines[0].closed);
}

TEST_CASE("parse_path_text: tolerates CRLF, runs of spaces and blank trailing lines") {
  const ArtShape shape = parse_path_text(
      "1\r\nforeground_color_rgb  0 -1,-1,-1\r\nbackground_color_rgb 0 10,20,30\r\n0 1 0 0 0  10 0\t0 10 \r\n\r\n\n",
      "crlf.path");
  REQUIRE(shape.paths.size() == 1);
  CHECK(shape.paths[0].polylines[0].points.size() == 3);
  CHECK(has_colour(shape.paths[0].fill, 10, 20, 30));
}

TEST_CASE("parse_path_text: the minimal valid file parses") {
  CHECK(path_error_of(kHeader + kTriangle) == "(no error)");
}

TEST_CASE("parse_path_text: empty file") {
  CHECK_THAT(path_error_of(""), StartsWith("bad.path:1: the file is empty;"));
  CHECK_THAT(path_error_of("\n  \n"), StartsWith("bad.path:1: the file is empty;"));
}

TEST_CASE("parse_path_text: garbled region count") {
  CHECK_THAT(path_error_of("one\n" + kHeader.substr(2) + kTriangle),
             StartsWith("bad.path:1: expected the region count (one integer), got `one`;"));
  CHECK_THAT(path_error_of("2\n" + kHeader.substr(2) + kTriangle), Contains("bad.path:1: the file has 2 regions"));
}

TEST_CASE("parse_path_text: missing colour lines") {
  CHECK_THAT(path_error_of("1\n"), StartsWith("bad.path:2: missing the foreground_color_rgb line;"));
  CHECK_THAT(path_error_of("1\nforeground_color_rgb 0 -1,-1,-1\n"),
             StartsWith("bad.path:3: missing the background_color_rgb line;"));
}

TEST_CASE("parse_path_text: garbled colour header keyword") {
  CHECK_THAT(path_error_of("1\nforeground 0 -1,-1,-1\nbackground_color_rgb 0 10,20,30\n" + kTriangle),
             StartsWith("bad.path:2: expected `foreground_color_rgb`, got `foreground`;"));
  CHECK_THAT(path_error_of("1\nforeground_color_rgb 0 -1,-1,-1\nforeground_color_rgb 0 10,20,30\n" + kTriangle),
             StartsWith("bad.path:3: expected `background_color_rgb`, got `foreground_color_rgb`;"));
}

TEST_CASE("parse_path_text: garbled colour") {
  CHECK_THAT(path_error_of("1\nforeground_color_rgb 0 -1,-1\nbackground_color_rgb 0 10,20,30\n" + kTriangle),
             StartsWith("bad.path:2: expected a colour `r,g,b`, got `-1,-1`;"));
  CHECK_THAT(path_error_of("1\nforeground_color_rgb 0 -1,-1,-1\nbackground_color_rgb 0 10,20,300\n" + kTriangle),
             StartsWith("bad.path:3: colour `10,20,300` has a channel outside 0-255;"));
}

TEST_CASE("parse_path_text: colour count differs from path count") {
  CHECK_THAT(path_error_of(kHeader + kTriangle + kTriangle),
             StartsWith("bad.path:2: 1 colours for 2 paths; give exactly one r,g,b colour"));
  CHECK_THAT(path_error_of("1\nforeground_color_rgb 0 -1,-1,-1\nbackground_color_rgb 0 1,1,1 2,2,2\n" + kTriangle),
             StartsWith("bad.path:3: 2 colours for 1 paths;"));
}

TEST_CASE("parse_path_text: header without path lines") {
  CHECK_THAT(path_error_of(kHeader), StartsWith("bad.path:4: the file has no path lines;"));
}

TEST_CASE("parse_path_text: odd coordinate count") {
  CHECK_THAT(path_error_of(kHeader + "0 1 0 0 0 10 0 0 10 5\n"),
             StartsWith("bad.path:4: path 0 has an odd number of coordinates (7);"));
}

TEST_CASE("parse_path_text: non-numeric coordinate") {
  CHECK_THAT(path_error_of(kHeader + "0 1 0 0 0 10 0 0 1O\n"),
             StartsWith("bad.path:4: path 0, token 9: `1O` is not a number;"));
  CHECK_THAT(path_error_of(kHeader + "0 1 0 0 0 10 0 0 -\n"), Contains("token 9: `-` is not a number"));
}

TEST_CASE("parse_path_text: NaN and infinite coordinates") {
  CHECK_THAT(path_error_of(kHeader + "0 1 0 0 0 nan 0 0 10\n"),
             StartsWith("bad.path:4: path 0, token 6: `nan` is not a finite number;"));
  CHECK_THAT(path_error_of(kHeader + "0 1 0 0 0 10 0 0 -inf\n"), Contains("`-inf` is not a finite number"));
  CHECK_THAT(path_error_of(kHeader + "0 1 0 0 0 1e999 0 0 10\n"), Contains("`1e999` is not a finite number"));
}

TEST_CASE("parse_path_text: path with fewer than 3 distinct points") {
  CHECK_THAT(path_error_of(kHeader + "0 1 0 0 0 10 0 0 0 10 0\n"),
             StartsWith("bad.path:4: path 0 has 2 distinct points, fewer than 3;"));
  CHECK_THAT(path_error_of(kHeader + "0 1 0\n"), Contains("path 0 has 0 distinct points"));
}

TEST_CASE("parse_path_text: unknown pathType") {
  CHECK_THAT(path_error_of(kHeader + "0 1 8 0 0 10 0 0 10\n"), StartsWith("bad.path:4: path 0: unknown pathType `8`;"));
  CHECK_THAT(path_error_of(kHeader + "0 1 x 0 0 10 0 0 10\n"), Contains("unknown pathType `x`"));
}

TEST_CASE("parse_path_text: bad isClosed flag and short path prefix") {
  CHECK_THAT(path_error_of(kHeader + "0 2 0 0 0 10 0 0 10\n"),
             StartsWith("bad.path:4: path 0: expected isClosed 0 or 1, got `2`;"));
  CHECK_THAT(path_error_of(kHeader + "0 1\n"),
             StartsWith("bad.path:4: path 0 has no `<region> <isClosed> <pathType>` prefix;"));
}

TEST_CASE("parse_path_text: region other than 0") {
  CHECK_THAT(path_error_of(kHeader + "1 1 0 0 0 10 0 0 10\n"), StartsWith("bad.path:4: region 1 is not supported;"));
  CHECK_THAT(path_error_of("1\nforeground_color_rgb 3 -1,-1,-1\nbackground_color_rgb 0 10,20,30\n" + kTriangle),
             StartsWith("bad.path:2: region 3 is not supported;"));
}

TEST_CASE("load_path_file: a missing file names its absolute path") {
  std::string message;
  try {
    load_path_file("no-such-dir/missing.path");
  } catch (const InputError& e) {
    message = e.what();
  }
  CHECK_THAT(message, StartsWith("no-such-dir/missing.path: cannot read \"no-such-dir/missing.path\" (resolved to /"));
  CHECK_THAT(message, Contains("/no-such-dir/missing.path)"));
}
