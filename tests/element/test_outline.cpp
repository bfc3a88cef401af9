// §3.1 Fig. 2a: normalization into the unit square and the offset outline.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>

#include "animpak/error.hpp"
#include "element/fixtures.hpp"

using namespace animpak;
using namespace animpak::test;

namespace {

void check_outline(const NormalizedArt& art, const Outline& outline, double offset) {
  const auto& ring = outline.ring;
  REQUIRE(ring.size() >= 3);
  CHECK(signed_area(ring) > 0.0);
  for (std::size_t i = 0; i < ring.size(); ++i) CHECK_FALSE(ring[i] == ring[(i + 1) % ring.size()]);
  CHECK(ring_simple(ring));
  // Every art point lies inside and at least Δs (less the join's chord error) from the outline.
  for (const ArtPath& path : art.art.paths)
    for (const Polyline& line : path.polylines)
      for (Vec2 p : line.points) {
        CHECK(ring_contains(ring, p));
        CHECK(ring_distance(ring, p) >= offset - offset_tolerance);
      }
}

// `n` points drawn uniformly from a 500-unit square and joined in that order: a scribble that crosses
// itself about n² / 8.5 times (2,000 points: about 470,000). A fixed 64-bit LCG, so every platform
// draws the same points.
std::vector<Vec2> scribble_points(int n, std::uint64_t seed) {
  std::vector<Vec2> points;
  std::uint64_t state = seed;
  const auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) * 0x1.0p-53 * 500.0;
  };
  for (int i = 0; i < n; ++i) {
    const double x = next();
    points.push_back({x, next()});
  }
  return points;
}

// The star polygon {n/k}: n points round a circle, each joined to the k-th next; n·(k − 1) crossings.
std::vector<Vec2> star_polygon_points(int n, int k) {
  std::vector<Vec2> points;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * 3.14159265358979 * static_cast<double>((i * k) % n) / n;
    points.push_back({250.0 + 240.0 * std::cos(a), 250.0 + 240.0 * std::sin(a)});
  }
  return points;
}

}  // namespace

TEST_CASE("normalize_art fits the longer side to 1 and centres the art", "[element][outline]") {
  const NormalizedArt n = normalize_art(filled_art({rect(10, 20, 30, 30)}, "r.svg"));
  CHECK(n.frame.scale == Approx(1.0 / 20));
  const Box box = n.art.bounds();  // one path, one polyline
  CHECK(box.min.x == Approx(0.0).margin(1e-15));
  CHECK(box.max.x == Approx(1.0));
  CHECK(box.min.y == Approx(0.25));
  CHECK(box.max.y == Approx(0.75));
  const Vec2 back = n.frame.to_art(n.frame.to_unit({12, 27}));
  CHECK(back.x == Approx(12));
  CHECK(back.y == Approx(27));
}

TEST_CASE("normalize_art names the file for empty or zero-size art", "[element][outline]") {
  ArtShape empty;
  empty.source = "empty.svg";
  CHECK_THROWS_WITH(normalize_art(empty), Catch::Contains("empty.svg"));
  CHECK_THROWS_AS(normalize_art(filled_art({{{1, 1}, {1, 1}, {1, 1}}}, "dot.svg")), InputError);
  CHECK_THROWS_WITH(normalize_art(filled_art({{{0, 0}, {1, std::nan("")}, {2, 1}}}, "nan.svg")),
                    Catch::Contains("nan.svg"));
}

TEST_CASE("element_outline cleans self-intersecting art into a simple ring", "[element][outline]") {
  // A bow tie (one polygon crossing itself) and a star drawn as one self-crossing pentagram.
  const ArtShape bow = filled_art({{{0, 0}, {10, 10}, {10, 0}, {0, 10}}}, "bow.svg");
  std::vector<Vec2> star;
  for (int k = 0; k < 5; ++k) {
    const double a = 2.0 * 3.14159265358979 * (2 * k) / 5.0;
    star.push_back({std::cos(a), std::sin(a)});
  }
  for (const ArtShape& art :
       {bow, filled_art({star}, "star.svg"), filled_art({star}, "star-eo.svg", FillRule::evenodd)}) {
    INFO(art.source);
    const NormalizedArt n = normalize_art(art);
    check_outline(n, element_outline(n, 0.04), 0.04);
  }
}

TEST_CASE("element_outline of synthetic shapes is simple, CCW and Δs around the art", "[element][outline]") {
  const Params params;
  for (const ArtShape& art : {square_art(), l_art(), bar_art(), frame_art()}) {
    INFO(art.source);
    const NormalizedArt n = normalize_art(art);
    const Outline outline = element_outline(n, params.element.offset);
    check_outline(n, outline, params.element.offset);
    CHECK(outline.notes.empty());
  }
}

TEST_CASE("element_outline fills holes: the element is solid", "[element][outline]") {
  const Outline outline = element_outline(normalize_art(frame_art()), 0.04);
  // Area of the 1.08-wide rounded square, far above the frame's area without its hole.
  CHECK(signed_area(outline.ring) == Approx(1.0 + 4 * 0.04 + 3.14159265 * 0.04 * 0.04).epsilon(1e-3));
  CHECK(ring_contains(outline.ring, {0.5, 0.5}));
}

TEST_CASE("element_outline keeps the largest piece and notes the dropped ones", "[element][outline]") {
  const NormalizedArt n = normalize_art(two_blobs_art());
  const Outline outline = element_outline(n, 0.04);
  REQUIRE(outline.notes.size() == 1);
  CHECK_THAT(outline.notes[0], Catch::Contains("dropped 1") && Catch::Contains("blobs.svg"));
  CHECK(ring_contains(outline.ring, n.frame.to_unit({5, 5})));
  CHECK_FALSE(ring_contains(outline.ring, n.frame.to_unit({41.5, 1.5})));
}

TEST_CASE("element_outline includes open strokes and rejects art without area", "[element][outline]") {
  ArtShape line;
  line.source = "line.svg";
  ArtPath path;
  path.polylines.push_back({{{0, 0}, {10, 0}, {10, 10}}, false});
  path.stroke.enabled = true;
  path.stroke_width = 2.0;
  line.paths.push_back(path);
  const NormalizedArt n = normalize_art(line);
  const Outline outline = element_outline(n, 0.04);
  // Half the stroke (0.1 in unit coordinates) plus Δs around the stroke's centre line.
  CHECK(ring_distance(outline.ring, n.frame.to_unit({5, 0})) >= 0.1 + 0.04 - offset_tolerance);
  CHECK(ring_simple(outline.ring));

  line.paths[0].stroke.enabled = false;
  CHECK_THROWS_WITH(element_outline(normalize_art(line), 0.04), Catch::Contains("line.svg"));
  CHECK_THROWS_AS(element_outline(normalize_art(filled_art({{{0, 0}, {1, 1}, {2, 2}}}, "flat.svg")), 0.04), InputError);
}

TEST_CASE("element_outline refuses art whose paths cross themselves more than 100000 times, before the offset",
          "[element][outline][crossings]") {
  // 2,000 random points, about 470,000 crossings: the offset used to run for minutes (10,000 points: 917 MB).
  for (const int n : {2000, 10000}) {
    INFO(n << " points");
    const NormalizedArt art = normalize_art(filled_art({scribble_points(n, 7)}, "scribble.svg"));
    CHECK_THROWS_AS(element_outline(art, 0.04), InputError);
    CHECK_THROWS_WITH(element_outline(art, 0.04),
                      Catch::Contains("scribble.svg: its paths cross themselves more than 100000 times") &&
                          Catch::Contains("path 0 ('path0'), " + std::to_string(n) + " points") &&
                          Catch::Contains("simplify the path in your editor"));
  }
  // Two scribbles of 500 points each cross themselves about 29,000 times and each other about 59,000: as
  // two subpaths of one path (filled together under its fill rule) they are one path crossing itself too
  // often; as two paths they are kept.
  const std::vector<Vec2> first = scribble_points(500, 11), second = scribble_points(500, 12);
  CHECK_THROWS_WITH(element_outline(normalize_art(filled_art({first, second}, "one.svg")), 0.04),
                    Catch::Contains("cross themselves more than 100000 times"));
  ArtShape two = filled_art({first}, "two.svg");
  two.paths.push_back(filled_art({second}, "two.svg").paths.front());
  two.paths.back().source_index = 1;
  const NormalizedArt kept = normalize_art(two);
  check_outline(kept, element_outline(kept, 0.04), 0.04);
}

TEST_CASE("element_outline refuses art whose paths cross each other more than 2000000 times",
          "[element][outline][crossings]") {
  // 2,400 long thin triangles, one path each, crossing each other about 2.7 million times.
  ArtShape art;
  art.source = "triangles.svg";
  const std::vector<Vec2> corners = scribble_points(2 * 2400, 3);
  for (int i = 0; i < 2400; ++i) {
    const Vec2 a = corners[2 * i], b = corners[2 * i + 1];
    ArtShape one = filled_art({{a, b, b + Vec2{2, 2}}}, "triangles.svg");
    one.paths.front().source_index = i;
    art.paths.push_back(one.paths.front());
  }
  CHECK_THROWS_WITH(element_outline(normalize_art(art), 0.04),
                    Catch::Contains("triangles.svg: its paths cross each other more than 2000000 times"));
}

TEST_CASE("element_outline keeps art that crosses itself less: star polygons and a scribble",
          "[element][outline][crossings]") {
  // openclipart's star polygons cross themselves up to 4,559 times ({97/48}); {301/150} 44,551 times.
  for (const auto& [n, k] : {std::pair{97, 48}, std::pair{301, 150}}) {
    INFO("{" << n << "/" << k << "}");
    const NormalizedArt art = normalize_art(filled_art({star_polygon_points(n, k)}, "star.svg"));
    check_outline(art, element_outline(art, 0.04), 0.04);
  }
  // 300 random points, about 10,000 crossings: the union has hundreds of small holes, dropped before the
  // offset; the outline still keeps Δs from every point, and one far detached square is bridged to it.
  std::vector<Vec2> scribble = scribble_points(300, 5);
  for (Vec2& p : scribble) p = p * 0.6;
  const NormalizedArt art = normalize_art(filled_art({scribble, rect(360, 360, 365, 365)}, "holes.svg"));
  const Outline outline = element_outline(art, 0.04);
  check_outline(art, outline, 0.04);
  REQUIRE(outline.notes.size() == 1);
  CHECK_THAT(outline.notes.front(), Catch::Contains("bridged 2 disjoint outline pieces"));
}

TEST_CASE("element_outline refuses art too dense to count its crossings in bounded time",
          "[element][outline][crossings]") {
  // A stroke drawn back and forth 4,500 times along one line: no crossing, but every segment lies over
  // every other, so counting would test 40 million pairs.
  ArtShape art;
  art.source = "back-and-forth.svg";
  ArtPath path;
  path.id = "hatch";
  path.stroke.enabled = true;
  path.stroke_width = 2.0;
  Polyline line;
  line.closed = false;
  line.points.push_back({0, 240});
  for (int i = 1; i < 9000; ++i) line.points.push_back({i % 2 == 0 ? 0.0 : 500.0, 250.0});
  path.polylines.push_back(line);
  art.paths.push_back(path);
  CHECK_THROWS_WITH(element_outline(normalize_art(art), 0.04),
                    Catch::Contains("back-and-forth.svg: the art has so many long segments lying over one another") &&
                        Catch::Contains("simplify the path in your editor"));
}

TEST_CASE("element_outline names the pieces it bridges or drops, with each one's share of the art's area",
          "[element][outline][pieces]") {
  // A square body and, apart from it, a drop-shadow ellipse: two pieces, bridged; docs/scene-format.md,
  // "Leaving pieces of the art out".
  const std::string svg = R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 400 200">
    <g id="bee"><rect id="body" x="0" y="0" width="100" height="100" fill="#fc0"/></g>
    <ellipse id="shadow" class="shade" cx="250" cy="90" rx="40" ry="10" fill="#000" fill-opacity="0.2"/></svg>)";
  const ArtShape art = parse_svg(svg, "bee.svg");
  const auto area_of = [](const ArtShape& a) {
    double area = 0.0;
    for (const auto& ring : painted_region(a)) area += signed_area(ring);
    return area;
  };
  const double whole = area_of(art);
  const Outline outline = element_outline(normalize_art(art), 0.04);
  REQUIRE(outline.pieces.size() == 2);
  CHECK(outline.bridge_radius > 0.0);
  const OutlinePiece& shadow = outline.pieces[1];
  CHECK(shadow.paths == std::vector<int>{1});
  CHECK_FALSE(shadow.dropped);
  CHECK(outline.pieces[0].paths == std::vector<int>{0});
  CHECK(outline.pieces[0].share + shadow.share == Approx(1.0));
  // The ellipse's polygon: a little under π·40·10 of the square's 100².
  CHECK(shadow.share == Approx(3.1416 * 400 / (10000 + 3.1416 * 400)).epsilon(0.01));
  REQUIRE(outline.notes.size() == 1);
  CHECK_THAT(outline.notes.front(), Catch::Contains("bridged 2 disjoint outline pieces") &&
                                        Catch::Contains("apart from it: path 1 ('shadow') 11.") &&
                                        Catch::Contains("\"exclude\""));

  // Left out by its id or its class: one piece, no bridge, and the area smaller by its share.
  for (const std::string selector : {"#shadow", ".shade"}) {
    INFO(selector);
    SvgOptions options;
    options.exclude = {selector};
    const ArtShape without = parse_svg(svg, "bee.svg", options);
    REQUIRE(without.paths.size() == 1);
    CHECK(area_of(without) == Approx(whole * (1.0 - shadow.share)).epsilon(1e-9));
    const Outline one = element_outline(normalize_art(without), 0.04);
    CHECK(one.pieces.empty());
    CHECK(one.bridge_radius == 0.0);
    CHECK(one.notes.empty());
  }

  // Too far to bridge: the smaller blob is dropped, and its one path paints in both pieces.
  const Outline blobs = element_outline(normalize_art(two_blobs_art()), 0.04);
  REQUIRE(blobs.pieces.size() == 2);
  CHECK(blobs.pieces[1].dropped);
  CHECK(blobs.pieces[1].paths == std::vector<int>{0});
  CHECK(blobs.pieces[0].paths == std::vector<int>{0});
  CHECK(blobs.pieces[1].share == Approx(9.0 / 409.0));
  CHECK_THAT(blobs.notes.front(), Catch::Contains("path 0 ('path0') 2.20 % (dropped)"));
}
