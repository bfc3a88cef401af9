// SVG importer: one small inline document per feature, with exact expected coordinates.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "io/svg_helpers.hpp"

using namespace svg_test;
using animpak::Box;

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
    for (Vec2 p : pts)
      if (near(p, q)) return true;
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
  // Stroked, so the open subpath M20 0 L30 0 draws (filled only, it has no area and would be dropped).
  const auto art = parse(R"~(<path d="M0 0 L10 0 L10 10 L0 0 Z M20 0 L30 0 M40 0 40 5 45 5" stroke="black"/>)~");
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
    if (u != 0 && v != 0)
      CHECK(std::abs(std::hypot(u, v) - 1) < 1e-6);
    else
      CHECK((std::abs(p.x - 10) < 1e-9 || std::abs(p.x - 110) < 1e-9 || std::abs(p.y - 20) < 1e-9 ||
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
  require_points(mm.paths.at(0).polylines.at(0).points,
                 {{10 * s, 10 * s}, {90 * s, 10 * s}, {90 * s, 90 * s}, {10 * s, 90 * s}}, 1e-9);
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

TEST_CASE("svg: a dashed stroke is drawn solid with a warning, none, zeros and negatives are solid anyway", "[svg]") {
  const auto art = parse(R"~(<g stroke="black" stroke-linejoin="round" stroke-linecap="round">
      <g style="stroke-dasharray:4px, 2"><path id="dashed" d="M0 0 L9 0"/></g>
      <path id="solid" d="M0 1 L9 1" stroke-dasharray="none"/><path id="zeros" d="M0 2 L9 2" stroke-dasharray="0,0"/>
      <path id="negative" d="M0 3 L9 3" stroke-dasharray="3 -1"/>
      <path id="unstroked" d="M0 4 L9 4 L9 9 Z" stroke="none" stroke-dasharray="3"/></g>)~");
  REQUIRE(art.paths.size() == 5);
  CHECK(has_warning(art, "dashed: stroke-dasharray 4px, 2 is drawn solid"));
  CHECK(art.warnings.size() == 1);
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
