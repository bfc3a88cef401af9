// SVG importer: one small inline document per feature, with exact expected coordinates.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "animpak/error.hpp"
#include "animpak/io.hpp"

using animpak::ArtShape;
using animpak::InputError;
using animpak::Box;
using animpak::Vec2;

namespace {

std::string doc(const std::string& body, const std::string& root_attrs = "") {
  return R"~(<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" )~" + root_attrs +
         ">" + body + "</svg>";
}

ArtShape parse(const std::string& body, const std::string& root_attrs = "", double tolerance = 0.1) {
  animpak::SvgOptions options;
  options.flatten_tolerance = tolerance;
  return animpak::parse_svg(doc(body, root_attrs), "test.svg", options);
}

bool near(Vec2 a, Vec2 b, double eps = 1e-9) { return std::abs(a.x - b.x) <= eps && std::abs(a.y - b.y) <= eps; }

void require_points(const std::vector<Vec2>& got, const std::vector<Vec2>& want, double eps = 1e-9) {
  INFO("got " << got.size() << " points, want " << want.size());
  REQUIRE(got.size() == want.size());
  for (size_t i = 0; i < want.size(); ++i) {
    INFO("point " << i << ": (" << got[i].x << ", " << got[i].y << ") want (" << want[i].x << ", " << want[i].y << ")");
    CHECK(near(got[i], want[i], eps));
  }
}

std::string error_of(const std::string& text) {
  try {
    animpak::parse_svg(text, "bad.svg");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

bool has_warning(const ArtShape& art, const std::string& part) {
  for (const auto& w : art.warnings)
    if (w.find(part) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("svg: relative path with H and V and implicit lineto", "[svg]") {
  const auto art = parse(R"~(<path id="p" d="m 10 20 h 30 v 40 l -10 0 -5 -5 z"/>)~");
  REQUIRE(art.paths.size() == 1);
  const auto& path = art.paths[0];
  CHECK(path.id == "p");
  CHECK(path.source_index == 0);
  REQUIRE(path.polylines.size() == 1);
  CHECK(path.polylines[0].closed);
  require_points(path.polylines[0].points, {{10, 20}, {40, 20}, {40, 60}, {30, 60}, {25, 55}});
  CHECK(path.fill.enabled);
  CHECK(path.fill.color.r == 0.0);
  CHECK(!path.stroke.enabled);
}

TEST_CASE("svg: absolute commands, shorthand curves and quadratic end where they should", "[svg]") {
  const auto art = parse(R"~(<path d="M0 0 C 0 10 10 10 10 0 S 20 -10 20 0 Q 25 10 30 0 T 40 0 L 40 20 Z"/>)~");
  const auto& pts = art.paths.at(0).polylines.at(0).points;
  auto contains = [&](Vec2 q) {
    for (Vec2 p : pts) if (near(p, q)) return true;
    return false;
  };
  CHECK(contains({10, 0}));
  CHECK(contains({20, 0}));
  CHECK(contains({30, 0}));
  CHECK(contains({40, 0}));
  CHECK(near(pts.back(), {40, 20}));
  // The S segment reflects (10,10) about (10,0): its midpoint is (15, -7.5).
  bool below = false;
  for (Vec2 p : pts) below = below || (p.x > 14 && p.x < 16 && p.y < -7.3);
  CHECK(below);
}

TEST_CASE("svg: several subpaths, open and closed, without a repeated closing point", "[svg]") {
  const auto art = parse(R"~(<path d="M0 0 L10 0 L10 10 L0 0 Z M20 0 L30 0 M40 0 40 5 45 5"/>)~");
  const auto& lines = art.paths.at(0).polylines;
  REQUIRE(lines.size() == 3);
  CHECK(lines[0].closed);
  require_points(lines[0].points, {{0, 0}, {10, 0}, {10, 10}});
  CHECK(!lines[1].closed);
  CHECK(!lines[2].closed);
  require_points(lines[2].points, {{40, 0}, {40, 5}, {45, 5}});
}

TEST_CASE("svg: rounded rect corners are quarter ellipses", "[svg]") {
  const auto art = parse(R"~(<rect x="10" y="20" width="100" height="50" rx="10" ry="5"/>)~", "", 0.01);
  const auto& line = art.paths.at(0).polylines.at(0);
  CHECK(line.closed);
  const auto box = art.bounds();
  CHECK(near(box.min, {10, 20}));
  CHECK(near(box.max, {110, 70}));
  // Every point is on the boundary of the rounded rect: on a straight edge or on a corner ellipse.
  for (Vec2 p : line.points) {
    const double cx = std::clamp(p.x, 20.0, 100.0), cy = std::clamp(p.y, 25.0, 65.0);
    const double u = (p.x - cx) / 10, v = (p.y - cy) / 5;
    if (u != 0 && v != 0) CHECK(std::abs(std::hypot(u, v) - 1) < 1e-6);
    else CHECK((std::abs(p.x - 10) < 1e-9 || std::abs(p.x - 110) < 1e-9 || std::abs(p.y - 20) < 1e-9 ||
                std::abs(p.y - 70) < 1e-9));
  }
  const auto plain = parse(R"~(<rect x="1" y="2" width="3" height="4"/>)~");
  require_points(plain.paths.at(0).polylines.at(0).points, {{1, 2}, {4, 2}, {4, 6}, {1, 6}});
}

TEST_CASE("svg: an arc reaches its extreme points", "[svg]") {
  // Half ellipse from (0,50) to (100,50) through the top: centre (50,50), rx 50, ry 30.
  const auto art = parse(R"~(<path d="M0 50 A 50 30 0 0 1 100 50" fill="none" stroke="black"/>)~", "", 0.001);
  const auto box = art.bounds();
  CHECK(near(box.min, {0, 20}, 1e-3));
  CHECK(near(box.max, {100, 50}, 1e-9));
  // Radii too small are scaled up (SVG F.6.6): a half circle of radius 5.
  const auto small = parse(R"~(<path d="M0 0 a 1 1 0 0 0 10 0" fill="none" stroke="red"/>)~", "", 0.001);
  CHECK(std::abs(small.bounds().max.y - 5) < 1e-3);
  // A relative arc with a rotated axis: both ends exact.
  const auto rot = parse(R"~(<path d="M10 10 a 20 10 30 1 1 15 5" fill="none" stroke="red"/>)~");
  const auto& pts = rot.paths.at(0).polylines.at(0).points;
  CHECK(near(pts.front(), {10, 10}));
  CHECK(near(pts.back(), {25, 15}));
}

TEST_CASE("svg: circle, ellipse, line, polyline, polygon", "[svg]") {
  const auto art = parse(R"~(<circle cx="10" cy="10" r="5"/><ellipse cx="50" cy="10" rx="20" ry="4"/>
    <line x1="0" y1="0" x2="7" y2="8" stroke="black"/><polyline points="0,0 5,5 10,0" stroke="blue" fill="none"/>
    <polygon points="1 1 2 1 2 2"/>)~");
  REQUIRE(art.paths.size() == 5);
  for (int i = 0; i < 5; ++i) CHECK(art.paths[i].source_index == i);
  const auto c = art.paths[0].polylines.at(0);
  CHECK(c.closed);
  for (Vec2 p : c.points) CHECK(std::abs(norm(p - Vec2{10, 10}) - 5) < 1e-9);
  Box e;
  for (Vec2 p : art.paths[1].polylines.at(0).points) e.add(p);
  CHECK(near(e.min, {30, 6}, 1e-6));
  CHECK(near(e.max, {70, 14}, 1e-6));
  CHECK(!art.paths[2].polylines.at(0).closed);
  require_points(art.paths[2].polylines.at(0).points, {{0, 0}, {7, 8}});
  CHECK(!art.paths[3].polylines.at(0).closed);
  require_points(art.paths[3].polylines.at(0).points, {{0, 0}, {5, 5}, {10, 0}});
  CHECK(art.paths[4].polylines.at(0).closed);
  require_points(art.paths[4].polylines.at(0).points, {{1, 1}, {2, 1}, {2, 2}});
}

TEST_CASE("svg: every transform form, nested groups, stroke width scaled", "[svg]") {
  auto first = [](const std::string& transform) {
    const auto art = parse("<g transform=\"" + transform + "\"><path d=\"M1 0 L0 1 L0 0 Z\"/></g>");
    return art.paths.at(0).polylines.at(0).points;
  };
  require_points(first("translate(10,20)"), {{11, 20}, {10, 21}, {10, 20}});
  require_points(first("translate(10)"), {{11, 0}, {10, 1}, {10, 0}});
  require_points(first("scale(2,3)"), {{2, 0}, {0, 3}, {0, 0}});
  require_points(first("rotate(90)"), {{0, 1}, {-1, 0}, {0, 0}}, 1e-12);
  require_points(first("rotate(90 5 5)"), {{10, 1}, {9, 0}, {10, 0}}, 1e-12);
  require_points(first("skewX(45)"), {{1, 0}, {1, 1}, {0, 0}}, 1e-12);
  require_points(first("skewY(45)"), {{1, 1}, {0, 1}, {0, 0}}, 1e-12);
  require_points(first("matrix(1 2 3 4 5 6)"), {{6, 8}, {8, 10}, {5, 6}});
  require_points(first("translate(10 0) scale(2)"), {{12, 0}, {10, 2}, {10, 0}});
  const auto nested = parse(R"~(<g transform="translate(100 0)"><g transform="scale(3)">
      <path d="M1 1 L2 1" stroke="black" stroke-width="2" transform="rotate(180 1 1)"/></g></g>)~");
  const auto& p = nested.paths.at(0);
  require_points(p.polylines.at(0).points, {{103, 3}, {100, 3}}, 1e-12);
  CHECK(p.stroke_width == Approx(6.0));
}

TEST_CASE("svg: viewBox with mm units and preserveAspectRatio", "[svg]") {
  const auto mm = parse(R"~(<rect x="10" y="10" width="80" height="80"/>)~",
                        R"~(width="100mm" height="100mm" viewBox="0 0 100 100")~");
  const double s = 96.0 / 25.4;
  require_points(mm.paths.at(0).polylines.at(0).points, {{10 * s, 10 * s}, {90 * s, 10 * s}, {90 * s, 90 * s}, {10 * s, 90 * s}}, 1e-9);
  // A 2:1 viewport showing a square viewBox: uniform scale 1, centred (xMidYMid meet).
  const auto meet = parse(R"~(<rect width="10" height="10"/>)~", R"~(width="20" height="10" viewBox="0 0 10 10")~");
  CHECK(near(meet.bounds().min, {5, 0}));
  CHECK(near(meet.bounds().max, {15, 10}));
  const auto none = parse(R"~(<rect width="10" height="10"/>)~",
                          R"~(width="20pt" height="1in" viewBox="0 0 10 10" preserveAspectRatio="none")~");
  CHECK(near(none.bounds().max, {20 * 96.0 / 72.0, 96}));
  const auto offset = parse(R"~(<rect x="5" y="5" width="10" height="10"/>)~", R"~(width="100%" viewBox="5 5 10 10")~");
  CHECK(near(offset.bounds().min, {0, 0}));
  CHECK(near(offset.bounds().max, {10, 10}));
  const auto units = parse(R"~(<rect width="1cm" height="1pc"/>)~");
  CHECK(near(units.bounds().max, {96 / 2.54, 16}));
}

TEST_CASE("svg: use with defs, symbol, href and xlink:href", "[svg]") {
  const auto art = parse(R"~(<defs><path id="tri" d="M0 0 L1 0 L0 1 Z" fill="red"/>
      <symbol id="sym" viewBox="0 0 10 10"><rect width="10" height="10"/></symbol></defs>
      <use xlink:href="#tri" x="10" y="20"/><use href="#tri" transform="scale(2)"/>
      <use href="#sym" x="100" width="20" height="20"/>)~");
  REQUIRE(art.paths.size() == 3);
  require_points(art.paths[0].polylines.at(0).points, {{10, 20}, {11, 20}, {10, 21}});
  CHECK(art.paths[0].fill.color.r == 1.0);
  require_points(art.paths[1].polylines.at(0).points, {{0, 0}, {2, 0}, {0, 2}});
  CHECK(near(art.paths[2].polylines.at(0).points[0], {100, 0}));
  CHECK(near(art.paths[2].polylines.at(0).points[2], {120, 20}));
}

TEST_CASE("svg: use cycles and external references terminate with warnings", "[svg]") {
  const auto art = parse(R"~(<g id="a"><rect width="1" height="1"/><use href="#b"/></g>
      <g id="b"><use href="#a"/></g><use id="self" href="#self"/><use id="ext" href="other.svg#x"/>
      <use id="gone" href="#missing"/>)~");
  CHECK(art.paths.size() >= 1);
  CHECK(art.paths.size() < 10);
  CHECK(has_warning(art, "other.svg"));
  CHECK(has_warning(art, "#missing"));
  CHECK(has_warning(art, "itself"));
}

TEST_CASE("svg: style inheritance, style attribute beats presentation attribute, currentColor", "[svg]") {
  const auto art = parse(R"~(<g fill="#00f" stroke="rgb(255,0,0)" stroke-width="3" style="color:lime">
      <path d="M0 0 L1 0 L1 1 Z"/><path d="M0 0 L1 0 L1 1 Z" fill="red" style="fill:#0f0;stroke:none"/>
      <path d="M0 0 L1 0 L1 1 Z" fill="currentColor" stroke="rgb(0%,50%,100%)"/></g>
      <path d="M0 0 L1 0 L1 1 Z" fill="white"/>)~");
  REQUIRE(art.paths.size() == 4);
  const auto& a = art.paths[0];
  CHECK((a.fill.enabled && a.fill.color.b == 1.0 && a.fill.color.r == 0.0));
  CHECK((a.stroke.enabled && a.stroke.color.r == 1.0 && a.stroke_width == 3.0));
  const auto& b = art.paths[1];
  CHECK((b.fill.color.g == 1.0 && b.fill.color.r == 0.0));
  CHECK(!b.stroke.enabled);
  const auto& c = art.paths[2];
  CHECK((c.fill.color.g == 1.0 && c.fill.color.r == 0.0 && c.fill.color.b == 0.0));
  CHECK(c.stroke.color.g == Approx(0.5).margin(0.003));
  CHECK(c.stroke.color.b == 1.0);
  const auto& d = art.paths[3];
  CHECK((d.fill.color.r == 1.0 && d.fill.color.g == 1.0 && !d.stroke.enabled));
}

TEST_CASE("svg: fill-rule and paint-order", "[svg]") {
  const auto art = parse(R"~(<g fill-rule="evenodd"><path d="M0 0 L1 0 L1 1 Z"/>
      <path d="M0 0 L1 0 L1 1 Z" style="fill-rule:nonzero;paint-order:stroke" stroke="red"/></g>
      <path d="M0 0 L1 0 L1 1 Z" paint-order="markers stroke fill"/>)~");
  REQUIRE(art.paths.size() == 3);
  CHECK(art.paths[0].fill_rule == animpak::FillRule::evenodd);
  CHECK(art.paths[0].paint_order == animpak::PaintOrder::fill_then_stroke);
  CHECK(art.paths[1].fill_rule == animpak::FillRule::nonzero);
  CHECK(art.paths[1].paint_order == animpak::PaintOrder::stroke_then_fill);
  CHECK(art.paths[2].paint_order == animpak::PaintOrder::stroke_then_fill);
}

TEST_CASE("svg: opacity folds into the colour alpha", "[svg]") {
  const auto art = parse(R"~(<g opacity="0.5"><path d="M0 0 L1 0 L1 1 Z" fill-opacity="0.5" stroke="red"
      style="opacity:0.8;stroke-opacity:0.25"/></g>)~");
  const auto& p = art.paths.at(0);
  CHECK(p.fill.color.a == Approx(0.5 * 0.8 * 0.5));
  CHECK(p.stroke.color.a == Approx(0.5 * 0.8 * 0.25));
}

TEST_CASE("svg: display none and visibility hidden draw nothing", "[svg]") {
  const auto art = parse(R"~(<g display="none"><path id="a" d="M0 0 L1 0 L1 1 Z"/></g>
      <path id="b" style="display:none" d="M0 0 L1 0 L1 1 Z"/>
      <g visibility="hidden"><path id="c" d="M0 0 L1 0 L1 1 Z"/><path id="d" visibility="visible" d="M0 0 L1 0 L1 1 Z"/></g>
      <defs><path id="e" d="M0 0 L1 0 L1 1 Z" display="none"/></defs><use id="u" href="#e"/>
      <path id="f" d="M0 0 L1 0 L1 1 Z"/>)~");
  REQUIRE(art.paths.size() == 2);
  CHECK(art.paths[0].id == "d");
  CHECK(art.paths[1].id == "f");
  CHECK(art.paths[1].source_index == 1);
}

TEST_CASE("svg: a gradient becomes its average stop colour with one warning per file", "[svg]") {
  const auto art = parse(R"~(<defs><linearGradient id="stops"><stop offset="0" stop-color="#ff0000"/>
      <stop offset="1" style="stop-color:#0000ff;stop-opacity:0.5"/></linearGradient>
      <linearGradient id="grad" xlink:href="#stops" x1="0" x2="1"/>
      <radialGradient id="rad"><stop offset="0" stop-color="white"/></radialGradient></defs>
      <path d="M0 0 L1 0 L1 1 Z" fill="url(#grad)"/><path d="M0 0 L1 0 L1 1 Z" fill="url(#grad)"/>
      <path d="M0 0 L1 0 L1 1 Z" fill="url(#rad)" stroke="url(#nowhere) green"/>
      <path d="M0 0 L1 0 L1 1 Z" fill="url(#nowhere)" stroke="black"/>)~");
  REQUIRE(art.paths.size() == 4);
  const auto& c = art.paths[0].fill.color;
  CHECK(c.r == Approx(0.5));
  CHECK(c.g == 0.0);
  CHECK(c.b == Approx(0.5));
  CHECK(c.a == Approx(0.75));
  CHECK(art.paths[2].fill.color.g == 1.0);
  CHECK((art.paths[2].stroke.enabled && art.paths[2].stroke.color.g == Approx(128.0 / 255)));
  CHECK(!art.paths[3].fill.enabled);
  int gradient_warnings = 0;
  for (const auto& w : art.warnings) gradient_warnings += w.find("gradient") != std::string::npos;
  CHECK(gradient_warnings == 1);
  CHECK(has_warning(art, "grad"));
  CHECK(has_warning(art, "rad"));
  CHECK(has_warning(art, "#nowhere"));
}

TEST_CASE("svg: text, images and other unsupported elements are skipped with a warning naming them", "[svg]") {
  const auto art = parse(R"~(<text id="caption" x="0" y="0">Hello</text><image width="5" height="5"/>
      <foreignObject id="fo"/><path d="M0 0 L1 0 L1 1 Z" clip-path="url(#c)"/>)~");
  REQUIRE(art.paths.size() == 1);
  CHECK(has_warning(art, "caption"));
  CHECK(has_warning(art, "<image> at line 1"));
  CHECK(has_warning(art, "fo"));
  CHECK(has_warning(art, "clip-path"));
  for (const auto& w : art.warnings) CHECK(w.find("Hello") == std::string::npos);
}

TEST_CASE("svg: Illustrator internal entities, switch and class styles", "[svg]") {
  const std::string ai = R"~(<?xml version="1.0"?>
<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" "http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd" [
  <!ENTITY ns_svg "http://www.w3.org/2000/svg">
  <!ENTITY ns_ai "http://ns.adobe.com/AdobeIllustrator/10.0/">
  <!ENTITY st0 "fill:#00FF00;">
]>
<svg xmlns="&ns_svg;" xmlns:i="&ns_ai;" width="10" height="10">
<style type="text/css">.st1{fill:#FF0000;stroke:#0000FF;}</style>
<switch><foreignObject requiredExtensions="&ns_ai;" width="1" height="1"><i:pgfRef/></foreignObject>
<g i:extraneous="self"><path class="st1" d="M0 0 L1 0 L1 1 Z"/><path style="&st0;" d="M0 0 L1 0 L1 1 Z"/>
<path class="st1" style="fill:#000000" d="M0 0 L1 0 L1 1 Z"/></g></switch></svg>)~";
  const auto art = animpak::parse_svg(ai, "ai.svg");
  REQUIRE(art.paths.size() == 3);
  CHECK((art.paths[0].fill.color.r == 1.0 && art.paths[0].stroke.color.b == 1.0));
  CHECK(art.paths[1].fill.color.g == 1.0);
  CHECK((art.paths[2].fill.color.r == 0.0 && art.paths[2].stroke.color.b == 1.0));
  CHECK(!has_warning(art, "foreignObject"));
}

TEST_CASE("svg: an external entity is never read", "[svg]") {
  const std::string xxe = R"~(<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY x SYSTEM "file:///etc/passwd">]>
<svg xmlns="http://www.w3.org/2000/svg"><path id="p" d="M0 0 L1 0 L1 1 Z"/><text id="t">&x;</text><desc>&x;</desc></svg>)~";
  try {
    const auto art = animpak::parse_svg(xxe, "xxe.svg");
    for (const auto& w : art.warnings) CHECK(w.find("root:") == std::string::npos);
    for (const auto& p : art.paths) CHECK(p.id.find("root:") == std::string::npos);
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("root:") == std::string::npos);
    CHECK(std::string(e.what()).find("xxe.svg") != std::string::npos);
  }
}

TEST_CASE("svg: a billion-laughs entity bomb is an InputError", "[svg]") {
  std::string dtd = R"~(<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY l0 "hahahahahahahahahaha">)~";
  for (int i = 1; i <= 10; ++i) {
    dtd += "<!ENTITY l" + std::to_string(i) + " \"";
    for (int j = 0; j < 10; ++j) dtd += "&l" + std::to_string(i - 1) + ";";
    dtd += "\">";
  }
  dtd += R"~(]><svg xmlns="http://www.w3.org/2000/svg"><path id="&l10;" d="M0 0 L1 0 L1 1 Z"/></svg>)~";
  CHECK_THROWS_AS(animpak::parse_svg(dtd, "bomb.svg"), InputError);
}

TEST_CASE("svg: a use bomb stops at the budget", "[svg]") {
  std::string body = R"~(<defs><path id="u0" d="M0 0 L1 0 L1 1 Z"/>)~";
  for (int i = 1; i <= 9; ++i) {
    body += "<g id=\"u" + std::to_string(i) + "\">";
    for (int j = 0; j < 10; ++j) body += "<use href=\"#u" + std::to_string(i - 1) + "\"/>";
    body += "</g>";
  }
  body += R"~(</defs><use href="#u9"/>)~";
  CHECK_THROWS_AS(parse(body), InputError);
}

TEST_CASE("svg: flattening respects the tolerance", "[svg]") {
  for (double tol : {1.0, 0.1, 0.001}) {
    const auto art = parse(R"~(<g transform="scale(10)"><circle cx="10" cy="10" r="8"/></g>)~", "", tol);
    const auto& pts = art.paths.at(0).polylines.at(0).points;
    INFO("tolerance " << tol << ", " << pts.size() << " points");
    CHECK(pts.size() >= 8);
    double worst_vertex = 0, worst_chord = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
      const Vec2 a = pts[i], b = pts[(i + 1) % pts.size()];
      worst_vertex = std::max(worst_vertex, std::abs(norm(a - Vec2{100, 100}) - 80));
      // A chord of a circle deviates most at its midpoint: sagitta = r - distance(centre, midpoint).
      worst_chord = std::max(worst_chord, 80 - norm(0.5 * (a + b) - Vec2{100, 100}));
    }
    CHECK(worst_vertex < 1e-9);
    CHECK(worst_chord <= tol);
    CHECK(worst_chord > tol / 8);  // adaptive, not wastefully fine
  }
  // A cubic: every polyline vertex lies on the curve, every chord within tolerance of sampled points.
  const auto cubic = parse(R"~(<path d="M0 0 C 0 100 100 100 100 0" fill="none" stroke="black"/>)~", "", 0.05);
  const auto& pts = cubic.paths.at(0).polylines.at(0).points;
  for (int k = 0; k <= 1000; ++k) {
    const double t = k / 1000.0, u = 1 - t;
    const Vec2 q{3 * u * t * t * 100 + t * t * t * 100, 3 * u * u * t * 100 + 3 * u * t * t * 100};
    double best = 1e300;
    for (size_t i = 0; i + 1 < pts.size(); ++i) {
      const Vec2 ab = pts[i + 1] - pts[i];
      const double s = std::clamp(dot(q - pts[i], ab) / dot(ab, ab), 0.0, 1.0);
      best = std::min(best, norm(q - (pts[i] + s * ab)));
    }
    CHECK(best <= 0.05);
  }
}

TEST_CASE("svg: malformed input is an InputError naming file and element", "[svg]") {
  const std::string bad_path = error_of(doc(R"~(<path id="broken" d="M 0 0 L 10 10 L 5 x 20"/>)~"));
  CHECK(bad_path.find("bad.svg") != std::string::npos);
  CHECK(bad_path.find("broken") != std::string::npos);
  INFO(bad_path);
  CHECK(bad_path.find("at character 14") != std::string::npos);  // where the bad "L 5 x" begins
  const std::string not_xml = error_of("<svg xmlns=\"http://www.w3.org/2000/svg\">\n<path d=\"M0 0\">\n</svg>");
  CHECK(not_xml.find("bad.svg: line 3") != std::string::npos);
  CHECK(error_of("<html/>").find("not <svg>") != std::string::npos);
  CHECK(error_of(doc("<text>only words</text>")).find("no drawable geometry") != std::string::npos);
  CHECK(error_of("").find("bad.svg") != std::string::npos);
}

TEST_CASE("svg: files are read with a size limit, load_art dispatches by extension", "[svg]") {
  const auto dir = std::filesystem::temp_directory_path() / "animpak_test_svg";
  std::filesystem::create_directories(dir);
  const auto file = dir / "tri.SVG";
  std::ofstream(file) << doc(R"~(<path d="M0 0 L1 0 L1 1 Z"/>)~");
  CHECK(animpak::load_art(file).paths.size() == 1);
  animpak::SvgOptions tiny;
  tiny.max_file_bytes = 10;
  CHECK_THROWS_WITH(animpak::load_svg(file, tiny), Catch::Contains("over the limit"));
  CHECK_THROWS_WITH(animpak::load_svg(dir / "missing.svg"), Catch::Contains("missing.svg"));
  CHECK_THROWS_WITH(animpak::load_art(dir / "art.png"), Catch::Contains("art.png") && Catch::Contains(".svg") &&
                                                            Catch::Contains(".path"));
  std::filesystem::remove_all(dir);
}
