// SVG structure as exporters write it (docs/scene-format.md, "SVG structure"): nested viewports and their
// clip, symbol sizes, the transform property from CSS, transform-origin, auto radii, selectors, and
// repeated warnings grouped.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "svg_helpers.hpp"

using namespace svg_test;

namespace {

const animpak::ArtPath& only_path(const ArtShape& art) {
  REQUIRE(art.paths.size() == 1);
  return art.paths.front();
}

animpak::Box box_of(const animpak::ArtPath& path) {
  animpak::Box box;
  for (const auto& line : path.polylines)
    for (Vec2 p : line.points) box.add(p);
  return box;
}

void require_box(const animpak::Box& box, double x0, double y0, double x1, double y1, double eps = 1e-6) {
  INFO("box " << box.min.x << " " << box.min.y << " " << box.max.x << " " << box.max.y);
  CHECK(box.min.x == Approx(x0).margin(eps));
  CHECK(box.min.y == Approx(y0).margin(eps));
  CHECK(box.max.x == Approx(x1).margin(eps));
  CHECK(box.max.y == Approx(y1).margin(eps));
}

double area_of(const animpak::ArtPath& path) {
  double a = 0.0;
  for (const auto& line : path.polylines) a += std::abs(animpak::signed_area(line.points));
  return a;
}

}  // namespace

TEST_CASE("svg structure: a nested svg places its viewBox by preserveAspectRatio and clips to its viewport", "[svg]") {
  // viewBox 10 × 10 in an 80 × 40 viewport at (10, 10): meet scales by 4 and xMax puts the viewBox at
  // x 50…90; the rect from -20 to 5 (user units) reaches x -30…70, y -70…30 and is cut to the viewport.
  const auto meet = parse(R"~(<svg x="10" y="10" width="80" height="40" viewBox="0 0 10 10"
      preserveAspectRatio="xMaxYMid meet"><rect x="-20" y="-20" width="25" height="25"/></svg>)~",
                          R"~(width="100" height="100")~");
  require_box(box_of(only_path(meet)), 10, 10, 70, 30);
  CHECK(meet.warnings.empty());
  // slice scales by 8 and yMax puts the viewBox at y -30…50: the whole viewBox rect is cut to 10…50.
  const auto slice = parse(R"~(<svg x="10" y="10" width="80" height="40" viewBox="0 0 10 10"
      preserveAspectRatio="xMidYMax slice"><rect width="10" height="10"/></svg>)~",
                           R"~(width="100" height="100")~");
  require_box(box_of(only_path(slice)), 10, 10, 90, 50);
  // none stretches each axis on its own.
  const auto none = parse(R"~(<svg width="80" height="40" viewBox="0 0 10 10" preserveAspectRatio="none">
      <rect width="5" height="5"/></svg>)~");
  require_box(box_of(only_path(none)), 0, 0, 40, 20);
}

TEST_CASE("svg structure: every alignment moves the viewBox along the axis with room", "[svg]") {
  // A 10 × 10 viewBox in a 60 × 20 viewport (meet: scale 2, 40 units of room in x) and in a 20 × 60 one.
  const char* const xs[] = {"xMin", "xMid", "xMax"};
  const char* const ys[] = {"YMin", "YMid", "YMax"};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const std::string align = std::string(xs[i]) + ys[j];
      INFO(align);
      for (const char* mode : {"meet", "slice"}) {
        INFO(mode);
        const bool slice = std::string(mode) == "slice";
        const auto wide = parse(R"~(<svg width="60" height="20" viewBox="0 0 10 10" preserveAspectRatio=")~" + align +
                                " " + mode + R"~("><rect width="10" height="10"/></svg>)~");
        const auto tall = parse(R"~(<svg width="20" height="60" viewBox="0 0 10 10" preserveAspectRatio=")~" + align +
                                " " + mode + R"~("><rect width="10" height="10"/></svg>)~");
        if (!slice) {
          require_box(box_of(only_path(wide)), 20.0 * i, 0, 20.0 * i + 20, 20);
          require_box(box_of(only_path(tall)), 0, 20.0 * j, 20, 20.0 * j + 20);
        } else {
          // Scale 6: the viewBox is 60 × 60 and the viewport shows 20 of it; the rect is clipped to that.
          require_box(box_of(only_path(wide)), 0, 0, 60, 20);
          require_box(box_of(only_path(tall)), 0, 0, 20, 60);
        }
      }
    }
  // Slice shows which part: with a viewBox-sized grid of 10 strips, yMax shows the last ones.
  const auto strips = parse(R"~(<svg width="60" height="20" viewBox="0 0 10 10" preserveAspectRatio="xMinYMax slice">
      <rect id="top" width="10" height="1"/><rect id="bottom" y="9" width="10" height="1"/></svg>)~");
  REQUIRE(strips.paths.size() == 1);
  CHECK(strips.paths[0].id == "bottom");
}

TEST_CASE("svg structure: overflow visible, nested clips, rotated viewports and cut strokes", "[svg]") {
  const auto visible = parse(R"~(<svg width="10" height="10" overflow="visible"><rect x="-5" width="20" height="5"/>
      </svg><svg x="20" width="10" height="10" style="overflow: auto"><rect x="-5" width="20" height="5"/></svg>)~",
                             R"~(width="100" height="100")~");
  REQUIRE(visible.paths.size() == 2);
  require_box(box_of(visible.paths[0]), -5, 0, 15, 5);
  require_box(box_of(visible.paths[1]), 15, 0, 35, 5);
  // Two viewports: the inner one at 5…25 inside the outer 0…20 leaves 5…20.
  const auto nested = parse(R"~(<svg width="20" height="20"><svg x="5" y="5" width="20" height="20">
      <rect x="-100" y="-100" width="200" height="200"/></svg></svg>)~",
                            R"~(width="100" height="100")~");
  require_box(box_of(only_path(nested)), 5, 5, 20, 20);
  // Under a 45° rotation the clip is a diamond: a large square is cut to it, area 20 × 20.
  const auto rotated = parse(R"~(<g transform="rotate(45)"><svg width="20" height="20">
      <rect x="-50" y="-50" width="100" height="100"/></svg></g>)~",
                             R"~(width="100" height="100")~");
  CHECK(area_of(only_path(rotated)) == Approx(400).epsilon(1e-6));
  // Art outside the viewport is gone; art inside is untouched (same points as without the viewport).
  const auto outside = parse(R"~(<svg width="20" height="20"><rect x="30" width="5" height="5" stroke="#000"/>
      <rect id="in" x="5" y="5" width="5" height="5"/></svg>)~",
                             R"~(width="100" height="100")~");
  REQUIRE(only_path(outside).id == "in");
  require_points(outside.paths[0].polylines.at(0).points, {{5, 5}, {10, 5}, {10, 10}, {5, 10}});
  CHECK(outside.paths[0].polylines[0].closed);
  CHECK(outside.warnings.empty());  // the stroke's miter joins are nowhere drawn
  // A stroked path across the edge: its fill inside, then its stroke as a filled band in the stroke's
  // colour, both cut; the band is the round-joined stroke (width 4) of the square inside the viewport.
  const auto cut = parse(R"~(<svg width="20" height="20"><rect id="sq" x="10" y="5" width="20" height="10"
      fill="#f00" stroke="#00f" stroke-width="4" stroke-linejoin="round"/></svg>)~",
                         R"~(width="100" height="100")~", 0.001);
  REQUIRE(cut.paths.size() == 2);
  CHECK(cut.paths[0].id == "sq");
  CHECK(cut.paths[1].id == "sq");
  CHECK((cut.paths[0].fill.color.r == 1.0 && !cut.paths[0].stroke.enabled));
  CHECK((cut.paths[1].fill.color.b == 1.0 && !cut.paths[1].stroke.enabled));
  require_box(box_of(cut.paths[0]), 10, 5, 20, 15);
  require_box(box_of(cut.paths[1]), 8, 3, 20, 17, 0.02);
  // The band inside: 12 × 14 less the 8 × 6 of the hole, less the two rounded outer corners at x = 8
  // (radius 2: 2² − π·2²/4 = 4 − π each).
  CHECK(area_of(cut.paths[1]) == Approx(12 * 14 - 8 * 6 - (4 - std::numbers::pi) * 2).epsilon(1e-3));
  CHECK(cut.paths[0].source_index == 0);
  CHECK(cut.paths[1].source_index == 1);
  // paint-order stroke first puts the band below the fill.
  const auto under = parse(R"~(<svg width="20" height="20"><rect x="10" y="5" width="20" height="10" fill="#f00"
      stroke="#00f" stroke-width="4" stroke-linejoin="round" paint-order="stroke"/></svg>)~",
                           R"~(width="100" height="100")~");
  REQUIRE(under.paths.size() == 2);
  CHECK(under.paths[0].fill.color.b == 1.0);
  CHECK(under.paths[1].fill.color.r == 1.0);
}

TEST_CASE("svg structure: symbol width and height, and use's overriding them", "[svg]") {
  // SVG 2: the symbol's own size when the use gives none; the use's where it does; 100 % without either.
  const auto art = parse(R"~(<defs><symbol id="s" width="20" height="10" viewBox="0 0 10 10"
      preserveAspectRatio="none"><rect width="10" height="10"/></symbol>
      <symbol id="t" viewBox="0 0 10 10"><rect width="10" height="10"/></symbol>
      <svg id="v" width="10" height="10" viewBox="0 0 1 1"><rect width="1" height="1"/></svg></defs>
      <use href="#s"/><use href="#s" y="20" width="40"/><use href="#t" y="40"/><use href="#v" y="60" height="30"/>)~",
                         R"~(width="100" height="200")~");
  REQUIRE(art.paths.size() == 4);
  require_box(box_of(art.paths[0]), 0, 0, 20, 10);
  require_box(box_of(art.paths[1]), 0, 20, 40, 30);
  // 100 % of the 100 × 200 viewport: meet scales by 10 and yMid centres the square, 50 down.
  require_box(box_of(art.paths[2]), 0, 90, 100, 190);
  // The use's height overrides the <svg>'s: a 10 × 30 viewport, the unit viewBox scaled by 10, centred.
  require_box(box_of(art.paths[3]), 0, 70, 10, 80);
  CHECK(art.warnings.empty());
}

TEST_CASE("svg structure: symbol content outside its viewport is clipped unless overflow is visible", "[svg]") {
  const auto art = parse(R"~(<defs><symbol id="s" viewBox="0 0 10 10"><rect x="-10" width="30" height="5"/></symbol>
      <symbol id="o" viewBox="0 0 10 10" overflow="visible"><rect x="-10" width="30" height="5"/></symbol></defs>
      <use href="#s" x="10" width="10" height="10"/><use href="#o" x="10" y="20" width="10" height="10"/>)~");
  REQUIRE(art.paths.size() == 2);
  require_box(box_of(art.paths[0]), 10, 0, 20, 5);
  require_box(box_of(art.paths[1]), 0, 20, 30, 25);
}

TEST_CASE("svg structure: use of plain elements at x and y, and of another use, never of another file", "[svg]") {
  const auto art = parse(R"~(<defs><g id="g"><rect width="2" height="2"/><rect x="4" width="2" height="2"/></g></defs>
      <use id="u" href="#g" x="10" y="5"/><use href="#u" x="100"/><use href="file:///etc/passwd#x"/>)~");
  REQUIRE(art.paths.size() == 4);
  require_box(box_of(art.paths[0]), 10, 5, 12, 7);
  require_box(box_of(art.paths[1]), 14, 5, 16, 7);
  require_box(box_of(art.paths[2]), 110, 5, 112, 7);
  CHECK(has_warning(art, "refused (another file is never read)"));
}

TEST_CASE("svg structure: the transform property in style and rules wins over the attribute", "[svg]") {
  const auto art = parse(R"~(<style>.moved { transform: translate(50px, 0px) } #q { transform: translateY(7px) }
      rect.big { transform: scale(2) }</style>
      <rect id="a" width="1" height="1" style="transform: translate(10px,10px)"/>
      <rect id="b" width="1" height="1" class="moved" transform="translate(0 70)"/>
      <rect id="q" width="1" height="1"/>
      <rect id="c" width="1" height="1" class="big moved"/>
      <rect id="d" width="1" height="1" style="transform: none" transform="translate(5 5)"/>
      <rect id="e" width="1" height="1" style="transform: rotate(90deg) scaleX(3)"/>
      <rect id="f" width="1" height="1" style="transform: skew(45deg, 0) rotate(0.25turn)"/>)~");
  REQUIRE(art.paths.size() == 7);
  require_box(box_of(art.paths[0]), 10, 10, 11, 11);
  require_box(box_of(art.paths[1]), 50, 0, 51, 1);
  require_box(box_of(art.paths[2]), 0, 7, 1, 8);
  // rect.big is more specific than .moved, so its transform wins whatever the order.
  require_box(box_of(art.paths[3]), 0, 0, 2, 2);
  require_box(box_of(art.paths[4]), 0, 0, 1, 1);
  require_box(box_of(art.paths[5]), -1, 0, 0, 3);
  require_box(box_of(art.paths[6]), -1, 0, 1, 1, 1e-9);  // a quarter turn, then x += y
  CHECK(art.warnings.empty());
}

TEST_CASE("svg structure: the transform attribute's number forms", "[svg]") {
  // Signs, leading points, exponents and numbers that run into each other, as SVG's grammar allows.
  const auto art = parse(R"~(<rect width="1" height="1" transform="translate(-.5 .5)"/>
      <rect width="1" height="1" transform="scale(+2)translate(10-5)"/>
      <rect width="1" height="1" transform="matrix(1,0,0,1,1e1,0) , rotate(90,0,0)"/>
      <rect width="1" height="1" transform="rotate(180 1 1)"/>
      <rect width="1" height="1" transform="skewY(45) scale(1 2)"/>)~");
  REQUIRE(art.paths.size() == 5);
  CHECK(art.warnings.empty());
  require_box(box_of(art.paths[0]), -0.5, 0.5, 0.5, 1.5);
  require_box(box_of(art.paths[1]), 20, -10, 22, -8);
  require_box(box_of(art.paths[2]), 9, 0, 10, 1, 1e-9);
  require_box(box_of(art.paths[3]), 1, 1, 2, 2, 1e-9);
  require_box(box_of(art.paths[4]), 0, 0, 1, 3, 1e-9);
}

TEST_CASE("svg structure: an invalid CSS transform is dropped for the attribute, with a warning", "[svg]") {
  const auto art = parse(R"~(<rect id="a" width="1" height="1" style="transform: translate(1em, 0)"
      transform="translate(3 0)"/><rect id="b" width="1" height="1" style="transform: rotateX(10deg)"/>
      <rect id="c" width="1" height="1" transform="scale(2"/>)~");
  REQUIRE(art.paths.size() == 3);
  require_box(box_of(art.paths[0]), 3, 0, 4, 1);
  require_box(box_of(art.paths[1]), 0, 0, 1, 1);
  require_box(box_of(art.paths[2]), 0, 0, 1, 1);
  INFO(art.warnings.size());
  CHECK(has_warning(art,
                    "test.svg: rect#a: invalid CSS transform \"translate(1em, 0)\" (translate(): unit \"em\" is "
                    "not supported here (give px or plain numbers)) ignored; the transform attribute is used"));
  CHECK(has_warning(art, "rect#b: invalid CSS transform \"rotateX(10deg)\" (rotatex() is a 3D transform"));
  CHECK(has_warning(art, "rect#c: invalid transform \"scale(2\""));
}

TEST_CASE("svg structure: transform-origin by lengths, percentages of the viewport and keywords", "[svg]") {
  // The viewBox is 200 × 100, what percentages and keywords resolve against (transform-box view-box).
  const std::string root = R"~(viewBox="0 0 200 100")~";
  const auto scale_about = [&](const std::string& origin, bool css) {
    const std::string attrs = css ? "style=\"transform: scale(0.5); transform-origin: " + origin + "\""
                                  : "transform=\"scale(0.5)\" transform-origin=\"" + origin + "\"";
    const auto art = parse("<rect x=\"20\" y=\"20\" width=\"40\" height=\"40\" " + attrs + "/>", root);
    INFO(origin);
    CHECK(art.warnings.empty());
    return box_of(only_path(art));
  };
  for (bool css : {false, true}) {
    INFO(css);
    // About (o): x' = o + (x − o) / 2.
    require_box(scale_about("0 0", css), 10, 10, 30, 30);
    require_box(scale_about("40 40", css), 30, 30, 50, 50);
    require_box(scale_about("center", css), 60, 35, 80, 55);  // about (100, 50)
    require_box(scale_about("50% 50%", css), 60, 35, 80, 55);
    require_box(scale_about("right bottom", css), 110, 60, 130, 80);
    require_box(scale_about("bottom right", css), 110, 60, 130, 80);
    require_box(scale_about("top", css), 60, 10, 80, 30);   // center top
    require_box(scale_about("left", css), 10, 35, 30, 55);  // left center
    require_box(scale_about("40px", css), 30, 35, 50, 55);  // 40px center
    require_box(scale_about("25% 40px 0", css), 35, 30, 55, 50);
    require_box(scale_about("10px top", css), 15, 10, 35, 30);
  }
  // rotate(90) about the rect's centre (40, 40) keeps it in place.
  const auto turned = parse(R"~(<rect x="20" y="20" width="40" height="40" transform="rotate(90)"
      transform-origin="40 40"/>)~",
                            root);
  require_box(box_of(only_path(turned)), 20, 20, 60, 60, 1e-9);
}

TEST_CASE("svg structure: an invalid transform-origin or an unsupported transform-box warns", "[svg]") {
  const auto art = parse(R"~(<rect id="a" width="10" height="10" transform="scale(2)" transform-origin="top 10px"/>
      <rect id="b" width="10" height="10" transform="scale(2)" transform-origin="5 5"
            style="transform-box: fill-box"/>
      <rect id="c" width="10" height="10" transform="scale(2)" transform-origin="5 5 1"/>)~");
  REQUIRE(art.paths.size() == 3);
  require_box(box_of(art.paths[0]), 0, 0, 20, 20);
  CHECK(has_warning(art, "rect#a: invalid transform-origin \"top 10px\""));
  CHECK(has_warning(art, "the transform is applied about 0 0"));
  CHECK(has_warning(art, "rect#b: transform-box fill-box is not supported"));
  CHECK(has_warning(art, "rect#c: invalid transform-origin \"5 5 1\" (a z offset"));
}

TEST_CASE("svg structure: SVG 2 auto radii on rect and ellipse", "[svg]") {
  const auto art = parse(R"~(<rect id="a" width="40" height="40" rx="auto" ry="10"/>
      <rect id="b" width="40" height="40" rx="auto" ry="auto"/>
      <ellipse id="c" cx="100" cy="100" rx="auto" ry="15"/>
      <ellipse id="d" cx="100" cy="100" rx="20" ry="auto"/>
      <ellipse id="e" cx="100" cy="100" ry="5"/>)~",
                         "", 0.001);
  REQUIRE(art.paths.size() == 5);
  CHECK(art.warnings.empty());
  // A rounded square of radius 10 has area 40² − (4 − π)·10²; square corners give 40².
  CHECK(area_of(art.paths[0]) == Approx(1600 - (4 - std::numbers::pi) * 100).epsilon(1e-3));
  CHECK(area_of(art.paths[1]) == Approx(1600));
  require_box(box_of(art.paths[2]), 85, 85, 115, 115, 1e-6);
  require_box(box_of(art.paths[3]), 80, 80, 120, 120, 1e-6);
  require_box(box_of(art.paths[4]), 95, 95, 105, 105, 1e-6);
  // An auto radius against a percentage is of the other axis: not supported, said so.
  const auto pct = parse(R"~(<ellipse id="p" cx="10" cy="10" rx="auto" ry="10%"/><rect width="1" height="1"/>)~");
  CHECK(has_warning(pct, "test.svg: ellipse#p: rx and ry auto, or auto opposite a percentage, is not supported"));
}

TEST_CASE("svg structure: type, id and compound selectors by specificity, the others reported", "[svg]") {
  const auto art = parse(R"~(<style>#x { fill: #0f0 } .c { fill: #f00 } rect { fill: #00f; stroke: #000 }
      rect.c { stroke: none } g + rect { fill: #fff } a:hover { fill: #fff } svg ~ text.label { font-family: serif }</style>
      <rect id="x" class="c" width="1" height="1"/><rect class="c" width="1" height="1"/>
      <rect width="1" height="1" style="fill: #ff0"/>)~");
  REQUIRE(art.paths.size() == 3);
  CHECK((art.paths[0].fill.color.g == 1.0 && art.paths[0].fill.color.r == 0.0 && !art.paths[0].stroke.enabled));
  CHECK((art.paths[1].fill.color.r == 1.0 && art.paths[1].fill.color.g == 0.0 && !art.paths[1].stroke.enabled));
  CHECK((art.paths[2].fill.color.r == 1.0 && art.paths[2].fill.color.g == 1.0 && art.paths[2].stroke.enabled));
  CHECK(has_warning(art, "<style> at line 1: CSS selector \"g + rect\" is not supported"));
  CHECK(has_warning(art, "CSS selector \"a:hover\""));
  CHECK(!has_warning(art, "text.label"));  // it sets no property the art is drawn with
  // Descendant and child combinators: `g .a` anywhere under a g, `#top > rect` only directly in #top.
  const auto nested = parse(R"~(<style>g .a { fill: #f00 } #top > rect { stroke: #00f } g g > .a { fill: #0f0 }</style>
      <g id="top"><rect id="r1" class="a" width="1" height="1"/><g><rect id="r2" class="a" width="1" height="1"/>
      <g><rect id="r3" width="1" height="1"/></g></g></g><rect id="r4" class="a" width="1" height="1"/>)~");
  REQUIRE(nested.paths.size() == 4);
  CHECK((nested.paths[0].fill.color.r == 1.0 && nested.paths[0].stroke.enabled));   // g .a, #top > rect
  CHECK((nested.paths[1].fill.color.g == 1.0 && !nested.paths[1].stroke.enabled));  // g g > .a wins
  CHECK((nested.paths[2].fill.color.r == 0.0 && !nested.paths[2].stroke.enabled));  // no rule
  CHECK((nested.paths[3].fill.color.r == 0.0 && nested.paths[3].fill.color.g == 0.0));
  REQUIRE(nested.warnings.size() == 1);
  CHECK(nested.warnings[0] == "test.svg: rect#r1: stroke-linejoin miter is drawn round");
  const auto media = parse(R"~(<style>@import url(other.css); @media print { rect { fill: #f00 } }</style>
      <rect width="1" height="1"/>)~");
  CHECK(only_path(media).fill.color.r == 0.0);
  CHECK(has_warning(media, "test.svg: <style> at line 1: @media rules are not applied; their styles are ignored"));
}

TEST_CASE("svg structure: the same warning on many elements is one line with a count and the first ids", "[svg]") {
  std::string body = R"~(<g fill="none" stroke="#000">)~";
  for (char c = 'a'; c < 'a' + 11; ++c) body += std::string("<path id=\"") + c + "\" d=\"M0 0 L5 5 L10 0 Z\"/>";
  body += R"~(<path id="solo" d="M0 0 L5 5 L10 0" stroke-linejoin="round"/></g>)~";
  const auto art = parse(body);
  INFO(art.warnings.size());
  REQUIRE(art.warnings.size() == 2);
  CHECK(art.warnings[0] ==
        "test.svg: 11 elements (path#a, path#b, path#c and 8 more): stroke-linejoin miter is drawn round");
  CHECK(art.warnings[1] == "test.svg: path#solo: stroke-linecap butt is drawn round");
}
