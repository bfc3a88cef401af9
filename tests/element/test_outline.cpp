// §3.1 Fig. 2a: normalization into the unit square and the offset outline.
#include <catch2/catch.hpp>
#include <cmath>

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
