// The element's envelope holds all of its art (§3.1; docs/parameters.md "Sampling the outline"): the
// boundary polygon follows the offset outline within boundary_tolerance, so sharp tips stay inside, and
// art pieces apart from the main body are bridged into the outline instead of dropped.
#include <catch2/catch.hpp>

#include "element/mesh_checks.hpp"

using namespace animpak;
using namespace animpak::test;

namespace {

std::vector<std::pair<std::string, ArtShape>> example_shapes() {
  std::vector<std::pair<std::string, ArtShape>> shapes;
  for (const std::string& name : animal_names()) shapes.emplace_back(name, load_path_file(shape_path(name)));
  shapes.emplace_back("star", star_art());
  return shapes;
}

void check_art_inside(const Built& b) {
  const ArtCoverage c = art_outside_boundary(b);
  REQUIRE(c.art > 0.0);
  INFO("art area " << c.art << ", outside the boundary polygon " << c.outside);
  CHECK(c.outside <= 1e-6 * c.art);
}

}  // namespace

TEST_CASE("the art of every example shape lies inside its slice's boundary polygon", "[element][envelope]") {
  const Params params;
  for (const auto& [name, art] : example_shapes()) {
    INFO(name);
    check_art_inside(build(art, params));
  }
}

TEST_CASE("the boundary polygon follows the outline within the tolerance, in short edges", "[element][envelope]") {
  Params coarse;
  coarse.element.boundary_spacing = 0.3;
  coarse.element.boundary_tolerance = 0.01;
  for (const Params& params : {Params{}, coarse})
    for (const auto& [name, art] : example_shapes()) {
      INFO(name << " at spacing " << params.element.boundary_spacing << ", tolerance "
                << params.element.boundary_tolerance);
      const Built b = build(art, params);
      check_boundary_sampling(b.outline, b.mesh, params);
    }
}

TEST_CASE("a piece apart from the body is bridged into the envelope", "[element][envelope]") {
  // A 100-unit body and a small blob 13 units (0.11 of the unit square) to its right: their Δs-offset
  // outlines stay 0.03 apart, so the offset alone leaves two pieces.
  const ArtShape blob = filled_art({rect(0, 0, 100, 100), rect(113, 45, 117, 55)}, "blob.svg");
  // A whisker: an open stroke as far from the body, not touching it.
  ArtShape whisker = filled_art({rect(0, 0, 100, 100)}, "whisker.svg");
  ArtPath line;
  line.id = "whisker";
  line.polylines.push_back({{{113, 20}, {140, 10}}, false});
  line.stroke.enabled = true;
  line.stroke_width = 1.0;
  whisker.paths.push_back(line);
  for (const ArtShape& art : {blob, whisker}) {
    INFO(art.source);
    const Built b = build(art);
    for (const std::string& note : b.outline.notes) CHECK_THAT(note, !Catch::Contains("dropped"));
    for (const Polyline& piece : b.art.art.paths.back().polylines)
      for (Vec2 p : piece.points) {
        CHECK(ring_contains(b.outline.ring, p));
        CHECK(ring_distance(b.outline.ring, p) >= 0.04 - offset_tolerance);
      }
    check_slice(b.outline, b.mesh, {});
    check_art_inside(b);
  }
}
