// The frame metrics on hand-made regions whose areas and distances are known exactly (docs/quality.md).
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "animpak/render.hpp"

using namespace animpak;

namespace {

std::vector<Vec2> square(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

Region box(double x0, double y0, double x1, double y1) { return {{square(x0, y0, x1, y1)}, FillRule::nonzero}; }

// Distance from p to the box [x0, x1] × [y0, y1].
double box_distance(Vec2 p, double x0, double y0, double x1, double y1) {
  const double dx = std::max({x0 - p.x, 0.0, p.x - x1}), dy = std::max({y0 - p.y, 0.0, p.y - y1});
  return std::hypot(dx, dy);
}

}  // namespace

TEST_CASE("measure_regions: overlaps, spills over the outline and into a hole, and coverage are exact") {
  // A 4 × 4 container with a 1 × 1 hole: area 15.
  const Region container{{square(0, 0, 4, 4), square(2, 2, 3, 3)}, FillRule::evenodd};
  const std::vector<Region> elements{
      box(0.5, 0.5, 1.5, 1.5),    // 0: inside
      box(0.9, 1.25, 1.9, 2.25),  // 1: overlaps 0 by 0.6 × 0.25 = 0.15
      box(-0.5, 3, 0.5, 3.5),     // 2: half over the outline
      box(2.5, 2.5, 3.5, 3.5),    // 3: a quarter in the hole
      box(3, 0.1, 3.9, 1.0),      // 4: area 0.81, holds 5 whole
      box(3.5, 0.5, 3.7, 0.6),    // 5: area 0.02, inside 4: its whole area overlaps
  };
  const FrameMetrics m = measure_regions(elements, container);
  REQUIRE(m.area.size() == 6);
  CHECK(m.area[4] == Approx(0.81).margin(1e-9));
  CHECK(m.area[5] == Approx(0.02).margin(1e-9));
  const std::vector<double> outside{0, 0, 0.5, 0.25, 0, 0};
  for (int i = 0; i < 6; ++i) {
    INFO("element " << i);
    CHECK(m.outside_share[i] == Approx(outside[i]).margin(1e-6));
  }
  const std::vector<ElementShare> out = m.elements_outside();
  REQUIRE(out.size() == 2);
  CHECK(out[0].element == 2);
  CHECK(out[1].element == 3);
  CHECK(m.worst_outside().element == 2);

  REQUIRE(m.overlaps.size() == 2);
  CHECK(m.overlaps[0].a == 0);
  CHECK(m.overlaps[0].b == 1);
  CHECK(m.overlaps[0].share == Approx(0.15).margin(1e-6));
  CHECK(m.overlaps[1].a == 4);
  CHECK(m.overlaps[1].b == 5);
  CHECK(m.overlaps[1].share == Approx(1.0).margin(1e-6));  // a share of the smaller art
  CHECK(m.overlapping().size() == 2);
  CHECK(m.worst_overlap().a == 4);

  // (1 + 1 − 0.15) + 0.25 + 0.75 + 0.81 inside, of 15.
  CHECK(m.coverage == Approx(3.66 / 15).margin(1e-6));
  // Overlapping art is 0 apart; 2 is 0.85 from 1 (0.4 across, 0.75 down), 3 is 0.65 from 1.
  CHECK(m.min_gap == 0.0);
  CHECK(m.mean_gap == Approx((0.85 + 0.65) / 6).margin(1e-6));
}

TEST_CASE("measure_regions: a share at or below 0.2 % is measured but not counted") {
  const Region container{{square(0, 0, 10, 10)}, FillRule::nonzero};
  // 0.001 of the square's width over the left edge, and 0.003 of the other's into the first.
  const FrameMetrics m = measure_regions({box(-0.001, 1, 0.999, 2), box(0.996, 1, 1.996, 2)}, container);
  CHECK(m.outside_share[0] == Approx(0.001).margin(1e-6));
  CHECK(m.elements_outside().empty());
  REQUIRE(m.overlaps.size() == 1);
  CHECK(m.overlaps[0].share == Approx(0.003).margin(1e-6));
  CHECK(m.overlapping().size() == 1);
}

TEST_CASE("measure_regions: gaps are the exact art-to-art distances, holes included") {
  const Region container{{square(-100, -100, 100, 100)}, FillRule::nonzero};
  // Two unit squares whose nearest corners are (0.3, 0.4) apart, and a frame with a square hole holding
  // a small square 0.3 from the hole's edges.
  const Region frame{{square(10, 10, 12, 12), square(10.5, 10.5, 11.5, 11.5)}, FillRule::evenodd};
  const FrameMetrics m =
      measure_regions({box(0, 0, 1, 1), box(1.3, 1.4, 2.3, 2.4), frame, box(10.8, 10.8, 11.2, 11.2)}, container);
  CHECK(m.area[2] == Approx(3.0).margin(1e-9));
  CHECK(m.overlaps.empty());
  CHECK(m.min_gap == Approx(0.3).margin(1e-9));
  CHECK(m.mean_gap == Approx((0.5 + 0.5 + 0.3 + 0.3) / 4).margin(1e-9));
}

TEST_CASE("measure_regions: the channel CV of two squares side by side") {
  // Unit squares 0.5 apart in a container far away. Along a square's outline the distance to the
  // other is 0.5 on the facing side, 1.5 on the far side and runs from 0.5 to 1.5 along the others.
  const Region container{{square(-100, -100, 100, 100)}, FillRule::nonzero};
  const FrameMetrics m = measure_regions({box(0, 0, 1, 1), box(1.5, 0, 2.5, 1)}, container);
  // The samples 0.005 apart from a corner; the squares mirror each other, so one gives the CV.
  double sum = 0.0, sum2 = 0.0;
  const int count = 800;
  for (int k = 0; k < count; ++k) {
    const double s = 4.0 * k / count;
    const Vec2 p = s < 1 ? Vec2{s, 0} : s < 2 ? Vec2{1, s - 1} : s < 3 ? Vec2{3 - s, 1} : Vec2{0, 4 - s};
    const double d = box_distance(p, 1.5, 0, 2.5, 1);
    sum += d, sum2 += d * d;
  }
  const double mean = sum / count;
  const double cv = std::sqrt(sum2 / count - mean * mean) / mean;
  CHECK(cv > 0.2);
  CHECK(m.channel_cv == Approx(cv).margin(1e-9));
  CHECK(m.min_gap == Approx(0.5).margin(1e-9));

  // Centred in a square container every sample is equally far from the container: no variation.
  const FrameMetrics centred =
      measure_regions({box(0.25, 0.25, 0.75, 0.75)}, {{square(0, 0, 1, 1)}, FillRule::nonzero});
  CHECK(centred.channel_cv == Approx(0.0).margin(1e-9));
}

TEST_CASE("art_region: strokes are bands with round joins and caps, closed subpaths count as filled") {
  ArtShape art;
  ArtPath line;
  line.stroke = {true, {0, 0, 0, 1}};
  line.stroke_width = 0.05;
  line.polylines.push_back({{{0, 0}, {1, 0}}, false});
  art.paths.push_back(line);
  ArtPath outline;  // a closed square drawn only as a stroke: the element is solid inside it
  outline.stroke = {true, {0, 0, 0, 1}};
  outline.stroke_width = 0.1;
  outline.polylines.push_back({square(0, 1, 1, 2), true});
  art.paths.push_back(outline);
  ArtPoints points;
  for (const ArtPath& p : art.paths) points.push_back({p.polylines[0].points});

  const Region container{{square(-10, -10, 10, 10)}, FillRule::nonzero};
  // The stroke scale doubles both widths: the line becomes 1 × 0.1 with half-disc caps of radius 0.05.
  const FrameMetrics m = measure_regions({art_region(art, points, 2.0)}, container);
  const double line_area = 1.0 * 0.1 + std::numbers::pi * 0.05 * 0.05;
  const double square_area = 1.0 + 4 * 1.0 * 0.1 + std::numbers::pi * 0.1 * 0.1;  // the square grown by 0.1
  CHECK(m.area[0] == Approx(line_area + square_area).margin(1e-4));
}

namespace {

// A regular polygon of `sides` around c: its inradius is radius · cos(π / sides).
std::vector<Vec2> polygon(Vec2 c, double radius, int sides) {
  std::vector<Vec2> ring;
  for (int k = 0; k < sides; ++k) {
    const double a = 2 * std::numbers::pi * k / sides;
    ring.push_back({c.x + radius * std::cos(a), c.y + radius * std::sin(a)});
  }
  return ring;
}

}  // namespace

TEST_CASE("measure_regions: the wall ratio is the median wall gap near the wall over the median nearest gap") {
  // Unit squares (ρ = √(1 / π) ≈ 0.56) in a 4 × 4 container: 0 is 0.2 from the wall, 1 is 0.3 from it and
  // 0.5 right of 0, 2 is 0.6 above 1 and 1.2 from the wall, too far to count.
  const Region container{{square(0, 0, 4, 4)}, FillRule::nonzero};
  const FrameMetrics m =
      measure_regions({box(0.2, 0.2, 1.2, 1.2), box(1.7, 0.3, 2.7, 1.3), box(1.7, 1.9, 2.7, 2.9)}, container);
  CHECK(m.element_radius == Approx(std::sqrt(1 / std::numbers::pi)).margin(1e-9));
  // The median of the wall gaps {0.2, 0.3} over the median of the nearest gaps {0.5, 0.5, 0.6}.
  REQUIRE(m.wall_ratio);
  CHECK(*m.wall_ratio == Approx(0.25 / 0.5).margin(1e-9));

  // One element, or none near the wall: no ratio.
  CHECK_FALSE(measure_regions({box(0.2, 0.2, 1.2, 1.2)}, container).wall_ratio);
  const Region wide{{square(-10, -10, 10, 10)}, FillRule::nonzero};
  CHECK_FALSE(measure_regions({box(0, 0, 1, 1), box(1.5, 0, 2.5, 1)}, wide).wall_ratio);
  CHECK_FALSE(measure_regions({}, container).empty_disc());
}

TEST_CASE("measure_regions: the largest empty disc of closed-form arrangements") {
  const Region unit{{square(0, 0, 1, 1)}, FillRule::nonzero};
  // Empty, the disc is the inscribed one.
  CHECK(measure_regions({}, unit).empty_disc_radius == Approx(0.5).margin(1e-6));
  // A 0.4 square in a corner: the disc touches the two far walls and the square's corner,
  // centre (c, c) with 1 − c = √2 (c − 0.4).
  const FrameMetrics corner = measure_regions({box(0, 0, 0.4, 0.4)}, unit);
  const double r = 0.6 * std::sqrt(2.0) / (1 + std::sqrt(2.0));
  CHECK(corner.empty_disc_radius == Approx(r).margin(1e-6));
  REQUIRE(corner.empty_disc());
  CHECK(*corner.empty_disc() == Approx(r / (0.4 / std::sqrt(std::numbers::pi))).margin(1e-5));
  // Two discs of radius 0.3 at (±0.5, 0) in the unit circle: the disc on the y axis touches both and the
  // circle, centre (0, y) with √(0.5² + y²) − 0.3 = 1 − y.
  const int sides = 4096;
  const Region circle{{polygon({0, 0}, 1.0 / std::cos(std::numbers::pi / sides), sides)}, FillRule::nonzero};
  const FrameMetrics two = measure_regions(
      {{{polygon({-0.5, 0}, 0.3, sides)}, FillRule::nonzero}, {{polygon({0.5, 0}, 0.3, sides)}, FillRule::nonzero}},
      circle);
  const double y = (1.3 * 1.3 - 0.25) / 2.6;
  CHECK(two.empty_disc_radius == Approx(1 - y).margin(1e-5));
  // The hole of a frame-shaped element is free space: the disc fills it.
  const Region frame{{square(0.05, 0.05, 0.95, 0.95), square(0.1, 0.1, 0.9, 0.9)}, FillRule::evenodd};
  CHECK(measure_regions({frame}, unit).empty_disc_radius == Approx(0.4).margin(1e-6));
}

TEST_CASE("contact_function: the share of the container farther than r from art and wall") {
  // An empty unit square: the points farther than r from the wall fill a square of side 1 − 2r.
  const Region unit{{square(0, 0, 1, 1)}, FillRule::nonzero};
  const std::vector<double> radii{0.0, 0.1, 0.25, 0.4, 0.49, 0.5};
  const std::vector<double> empty = contact_function({}, unit, radii);
  REQUIRE(empty.size() == radii.size());
  for (std::size_t k = 0; k < radii.size(); ++k) {
    INFO("r = " << radii[k]);
    CHECK(empty[k] == Approx((1 - 2 * radii[k]) * (1 - 2 * radii[k])).margin(0.005));
  }
  // With a 0.2 square in the middle, less its neighbourhood: 0.2² + 4 · 0.2 r + π r², while that fits.
  const std::vector<double> middle = contact_function({box(0.4, 0.4, 0.6, 0.6)}, unit, {0.0, 0.05, 0.1, 0.15});
  for (std::size_t k = 0; k < middle.size(); ++k) {
    const double r = 0.05 * double(k);
    INFO("r = " << r);
    const double far_from_wall = (1 - 2 * r) * (1 - 2 * r), near_art = 0.04 + 0.8 * r + std::numbers::pi * r * r;
    CHECK(middle[k] == Approx(far_from_wall - near_art).margin(0.005));
  }
  // In the frame metrics: sampled every 0.05 ρ from 1 − coverage down to its first 0.
  const FrameMetrics m = measure_regions({box(0.4, 0.4, 0.6, 0.6)}, unit);
  REQUIRE(m.contact.size() >= 2);
  CHECK(m.contact.front() == Approx(1 - m.coverage).margin(0.005));
  CHECK(m.contact.back() == 0.0);
  CHECK(m.contact[m.contact.size() - 2] > 0.0);
  CHECK(double(m.contact.size() - 2) * contact_step * m.element_radius < m.empty_disc_radius + 0.005);
}
