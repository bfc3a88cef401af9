// SVG as browsers read it (docs/scene-format.md, "SVG art: what the importer forgives"): SVG 2's error
// handling for path data and `points`, arc flags without separators, degenerate shapes dropped with a
// warning each, and large traced paths thinned so the element pipeline stays linear.
#include <cmath>
#include <numbers>

#include "io/svg_helpers.hpp"

using namespace svg_test;

namespace {

const animpak::ArtPath& path_with_id(const ArtShape& art, const std::string& id) {
  for (const auto& p : art.paths)
    if (p.id == id) return p;
  FAIL("no imported path with id " << id);
  throw std::logic_error("unreachable");
}

bool has_path(const ArtShape& art, const std::string& id) {
  for (const auto& p : art.paths)
    if (p.id == id) return true;
  return false;
}

std::string warnings_of(const ArtShape& art) {
  std::string all;
  for (const auto& w : art.warnings) all += w + "\n";
  return all;
}

// A stroked path that is always there, so a document whose other elements are all dropped still imports.
const std::string anchor = R"~(<path id="anchor" d="M0 0 L100 0 L100 100 Z"/>)~";

}  // namespace

TEST_CASE("svg: path data is drawn up to its first error, with a warning naming the character", "[svg]") {
  const auto art = parse(anchor + R"~(<path id="tail" d="M 10 10 L 50 50 L 90 x" stroke="black"/>)~");
  INFO(warnings_of(art));
  const auto& tail = path_with_id(art, "tail");
  REQUIRE(tail.polylines.size() == 1);
  require_points(tail.polylines[0].points, {{10, 10}, {50, 50}});
  CHECK(!tail.polylines[0].closed);
  CHECK(has_warning(art, "test.svg: path#tail: path data error at character 22 (\"x\"); rendered up to there"));
}

TEST_CASE("svg: path data errors of every kind keep what came before", "[svg]") {
  SECTION("relative commands before the error") {
    const auto art = parse(anchor + R"~(<path id="p" d="m 10 10 l 40 40 l 5 x" stroke="black"/>)~");
    require_points(path_with_id(art, "p").polylines.at(0).points, {{10, 10}, {50, 50}});
    CHECK(has_warning(art, "path#p: path data error at character 21 (\"x\")"));
  }
  SECTION("a closed subpath before an error in the next one") {
    const auto art = parse(anchor + R"~(<path id="p" d="M0 0 L10 0 L10 10 Z M 20 20 L 30 $ 40"/>)~");
    const auto& p = path_with_id(art, "p");
    REQUIRE(p.polylines.size() == 1);  // M 20 20 alone is a single point: nothing to draw
    CHECK(p.polylines[0].closed);
    require_points(p.polylines[0].points, {{0, 0}, {10, 0}, {10, 10}});
    CHECK(has_warning(art, "path#p: path data error at character 34 (\"$\"); rendered up to there"));
  }
  SECTION("a command cut short quotes the command") {
    const auto art = parse(anchor + R"~(<path id="p" d="M 0 0 L 10 0 L 10 10 L 5" stroke="black"/>)~");
    require_points(path_with_id(art, "p").polylines.at(0).points, {{0, 0}, {10, 0}, {10, 10}});
    CHECK(has_warning(art, "path#p: path data error at character 22 (\"L\")"));
  }
  SECTION("an odd coordinate left after implicit linetos") {
    const auto art = parse(anchor + R"~(<path id="p" d="M 10 10 20 20 30" stroke="black"/>)~");
    require_points(path_with_id(art, "p").polylines.at(0).points, {{10, 10}, {20, 20}});
    CHECK(has_warning(art, "path#p: path data error at character 15 (\"30\")"));
  }
  SECTION("an error before anything drawable drops the element, with the one warning") {
    const auto art = parse(anchor + R"~(<path id="p" d="x 10 10 L 20 20"/><path d="L 5 5 L 6 6"/>)~");
    CHECK(!has_path(art, "p"));
    CHECK(has_warning(art, "path#p: path data error at character 1 (\"x\"); nothing before it to render"));
    CHECK(has_warning(art, "<path> at line 1: path data error at character 1 (\"L\"); nothing before it to render"));
    CHECK(art.warnings.size() == 2);
  }
}

TEST_CASE("svg: arc flags written without separators", "[svg]") {
  // SVG 2: a flag is one character, so "1020 20" is large-arc 1, sweep 0, then x = 20, y = 20. Round
  // joins and caps, so that the stroke draws as written and nothing else warns.
  const auto arc = [](const std::string& d) {
    return parse(R"~(<path stroke="black" fill="none" stroke-linecap="round" stroke-linejoin="round" d=")~" + d +
                 "\"/>");
  };
  const auto compact = arc("M 10 50 a 20 20 0 1020 20"), spaced = arc("M 10 50 a 20 20 0 1 0 20 20");
  CHECK(compact.warnings.empty());
  require_points(compact.paths.at(0).polylines.at(0).points, spaced.paths.at(0).polylines.at(0).points);
  const auto packed = arc("M10,50A20,20,0,01,30,70"), packed_spaced = arc("M10 50 A20 20 0 0 1 30 70");
  CHECK(packed.warnings.empty());
  require_points(packed.paths.at(0).polylines.at(0).points, packed_spaced.paths.at(0).polylines.at(0).points);
}

TEST_CASE("svg: points with an odd coordinate drop it, invalid points stop there", "[svg]") {
  const auto art = parse(anchor + R"~(<polygon id="odd" points="10 10 50 10 50 50 30"/>)~"
                                  R"~(<polyline id="bad" points="0 0 10 0 10 10 x 20 20 20" stroke="black"/>)~");
  INFO(warnings_of(art));
  const auto& odd = path_with_id(art, "odd");
  REQUIRE(odd.polylines.size() == 1);
  CHECK(odd.polylines[0].closed);
  require_points(odd.polylines[0].points, {{10, 10}, {50, 10}, {50, 50}});
  CHECK(has_warning(art,
                    "test.svg: polygon#odd: odd number of coordinates in points; the last one (\"30\", "
                    "character 19) dropped"));
  const auto& bad = path_with_id(art, "bad");
  REQUIRE(bad.polylines.size() == 1);
  CHECK(!bad.polylines[0].closed);
  require_points(bad.polylines[0].points, {{0, 0}, {10, 0}, {10, 10}});
  CHECK(has_warning(art,
                    "test.svg: polyline#bad: points error at character 16 (\"x\"); rendered the 3 points "
                    "before it"));
}

TEST_CASE("svg: degenerate shapes are dropped with one warning each naming the element", "[svg]") {
  const auto art = parse(anchor + R"~(
    <path id="dot" d="M 5 5"/>
    <path id="zero" d="M 5 5 L 5 5 l 0 0 Z" stroke="black"/>
    <polygon id="line" points="0 0 10 0 20 0"/>
    <polygon id="out-and-back" points="0 0 10 0 10 10 10 0"/>
    <rect id="flat-rect" width="10" height="0"/>
    <rect id="thin-rect" width="0" height="10" rx="2"/>
    <circle id="no-circle" cx="5" cy="5" r="0"/>
    <ellipse id="no-ellipse" cx="5" cy="5" rx="4" ry="0"/>
    <path id="half" d="M 0 0 L 10 0 L 10 10 Z M 50 50 M 60 60 L 70 70"/>
    <polygon id="stroked-line" points="0 0 10 0 20 0" stroke="black" stroke-linejoin="round"/>)~");
  INFO(warnings_of(art));
  for (const char* id : {"dot", "zero", "line", "out-and-back", "flat-rect", "thin-rect", "no-circle", "no-ellipse"})
    CHECK(!has_path(art, id));
  // The same problem on several elements is one line naming them (docs/scene-format.md, "SVG structure").
  CHECK(has_warning(art,
                    "test.svg: 2 elements (path#dot, path#zero): its geometry is a single point or only "
                    "zero-length segments; nothing drawn (dropped)"));
  CHECK(has_warning(art,
                    "test.svg: 2 elements (polygon#line, polygon#out-and-back): its geometry is no area "
                    "(collinear points) and no stroke"));
  CHECK(has_warning(art,
                    "test.svg: 2 elements (rect#flat-rect, rect#thin-rect): width or height is 0; nothing "
                    "drawn (dropped)"));
  CHECK(has_warning(art, "test.svg: circle#no-circle: r is 0; nothing drawn (dropped)"));
  CHECK(has_warning(art, "test.svg: ellipse#no-ellipse: rx or ry is 0; nothing drawn (dropped)"));
  // Part of a path: the square stays, the lone M 50 50 and the filled, unstroked line are dropped.
  const auto& half = path_with_id(art, "half");
  REQUIRE(half.polylines.size() == 1);
  require_points(half.polylines[0].points, {{0, 0}, {10, 0}, {10, 10}});
  CHECK(has_warning(art,
                    "test.svg: path#half: 2 of its 3 subpaths are a single point or only zero-length "
                    "segments, or no area (collinear points) and no stroke; those dropped"));
  // A stroked line has no area but draws: kept, no warning.
  CHECK(has_path(art, "stroked-line"));
  CHECK(art.warnings.size() == 6);
  for (const auto& p : art.paths)
    for (const auto& line : p.polylines)
      for (Vec2 q : line.points) CHECK((std::isfinite(q.x) && std::isfinite(q.y)));
}

TEST_CASE("svg: a file of degenerate shapes only is refused with the first warning", "[svg]") {
  const std::string e = error_of(doc(R"~(<rect id="r" width="0" height="5"/><circle r="0"/>)~"));
  CHECK(e.find("no drawable geometry") != std::string::npos);
  CHECK(e.find("first of 2 warnings: bad.svg: rect#r: width or height is 0") != std::string::npos);
}

TEST_CASE("svg: a dense traced path is thinned within the tolerance, curves and coarse detail are not", "[svg]") {
  // A 12-arm star written as 60,000 points 0.02 user units apart with a 0.02 zigzag, as a tracer
  // writes it: what it shows is the star's 24 corners. Without thinning every point reaches the offset
  // and the triangulation (docs/scene-format.md "Large paths"); with it the count is bounded by the shape.
  const int n = 60000, arms = 12;
  std::vector<Vec2> corners;
  for (int k = 0; k < 2 * arms; ++k) {
    const double r = k % 2 ? 45.0 : 100.0, a = std::numbers::pi * k / arms;
    corners.push_back({100 + r * std::cos(a), 100 + r * std::sin(a)});
  }
  const double edge = norm(corners[1] - corners[0]);
  std::vector<Vec2> trace;
  std::string d = "M";
  for (int i = 0; i < n; ++i) {
    const double s = edge * corners.size() * i / n;
    const size_t k = static_cast<size_t>(s / edge);
    const Vec2 a = corners[k], b = corners[(k + 1) % corners.size()];
    const Vec2 along = (1.0 / edge) * (b - a), normal{along.y, -along.x};
    trace.push_back(a + (s - edge * k) * along + (i % 2 ? 0.02 : -0.02) * normal);
    d += (i == 1 ? " L" : " ") + std::to_string(trace.back().x) + " " + std::to_string(trace.back().y);
  }
  const double tolerance = 0.1;
  const auto art = parse("<path d=\"" + d + " Z\"/>", "", tolerance);
  const auto& ring = art.paths.at(0).polylines.at(0).points;
  INFO(ring.size() << " of " << n << " points kept");
  CHECK(ring.size() >= corners.size());
  CHECK(ring.size() <= 2 * corners.size());
  // Every point of the trace (6 decimals in the text) stays within the tolerance of the thinned ring.
  double worst = 0.0;
  for (size_t i = 0, j = 0; i < trace.size(); ++i) {
    // The ring keeps the trace's order, so the nearest segment is found by walking forward.
    double best = segment_distance(trace[i], ring[j], ring[(j + 1) % ring.size()]);
    for (size_t step = 1; step < 4; ++step) {
      const size_t m = (j + step) % ring.size();
      const double dm = segment_distance(trace[i], ring[m], ring[(m + 1) % ring.size()]);
      if (dm < best) best = dm, j = m;
    }
    worst = std::max(worst, best);
  }
  CHECK(worst <= tolerance + 1e-5);

  // A zigzag coarser than the tolerance is detail the art shows: every point stays.
  std::string coarse = "M 0 0 L";
  for (int i = 1; i <= 200; ++i) coarse.append(" ").append(std::to_string(i)).append(i % 2 ? " 0.3" : " 0");
  CHECK(parse("<path d=\"" + coarse + " Z\"/>", "", tolerance).paths.at(0).polylines.at(0).points.size() == 201);
  // Flattened curves keep every point the flattener chose.
  const auto circle = parse(R"~(<circle cx="0" cy="0" r="50"/>)~", "", tolerance);
  for (Vec2 p : circle.paths.at(0).polylines.at(0).points) CHECK(std::abs(norm(p) - 50) < 1e-9);
  CHECK(circle.paths.at(0).polylines.at(0).points.size() > 24);
}

TEST_CASE("svg: an attribute over libxml2's 10 MB default is read unless the file declares entities", "[svg]") {
  std::string body = R"~(<path d="M0 0 L10 0 L10 10 Z" data-trace=")~";
  body.append(10500000, 'a').append("\"/>");
  CHECK(parse(body).paths.size() == 1);
  const std::string with_entity = R"~(<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY e "x">]>)~" + doc(body);
  CHECK_THROWS_WITH(animpak::parse_svg(with_entity, "big.svg"),
                    Catch::Contains("big.svg") && Catch::Contains("at most 10000000 characters"));
}
