// The animated formats' Bézier refit of a flattened polyline (fit_beziers, src/render/bezier_fit.cpp;
// docs/animation-formats.md, "Curves"): a densely flattened circle becomes a few cubics within the
// tolerance, a straight run one straight side, a corner stays a vertex, a two-point line comes back as it
// is, and a path keyed at several shapes gets the same segments in every key, each within the tolerance,
// as does every shape a player draws between two keys. The distance is measured here independently of the
// fitter: the curve sampled densely against the polyline's edges and back (a Hausdorff distance).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "frame_writers.hpp"

using namespace animpak;
using animpak::frame_writers::BezierLine;
using animpak::frame_writers::fit_beziers;

namespace {

double edge_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double length2 = dot(d, d);
  const double s = length2 > 0 ? std::clamp(dot(p - a, d) / length2, 0.0, 1.0) : 0.0;
  return norm(p - (a + d * s));
}

// The curve's points, 64 to a segment, in order (a closed line back to its first vertex).
std::vector<Vec2> sampled_curve(const BezierLine& line) {
  std::vector<Vec2> samples;
  const std::size_t n = line.points.size(), segments = line.closed ? n : n - 1;
  if (n == 0) return samples;
  samples.push_back(line.points[0]);
  for (std::size_t k = 0; k < segments; ++k) {
    const Vec2 p0 = line.points[k], p1 = line.after[k], p2 = line.before[(k + 1) % n], p3 = line.points[(k + 1) % n];
    for (int i = 1; i <= 64; ++i) {
      const double u = i / 64.0, v = 1 - u;
      samples.push_back(v * v * v * p0 + 3 * v * v * u * p1 + 3 * v * u * u * p2 + u * u * u * p3);
    }
  }
  return samples;
}

// The farthest a point of either the curve or the polyline lies from the other (the polyline's edges, the
// curve's dense samples joined by segments).
double bezier_hausdorff(const BezierLine& line, const std::vector<Vec2>& polyline, bool closed) {
  const std::vector<Vec2> curve = sampled_curve(line);
  std::vector<Vec2> ring = polyline;
  if (closed) ring.push_back(polyline.front());
  const auto farthest = [](const std::vector<Vec2>& from, const std::vector<Vec2>& to) {
    double worst = 0.0;
    for (Vec2 p : from) {
      double nearest = to.size() == 1 ? norm(p - to[0]) : 1e300;
      for (std::size_t k = 0; k + 1 < to.size(); ++k) nearest = std::min(nearest, edge_distance(p, to[k], to[k + 1]));
      worst = std::max(worst, nearest);
    }
    return worst;
  };
  return std::max(farthest(curve, ring), farthest(ring, curve));
}

std::vector<Vec2> circle(int points, double radius, Vec2 centre = {0, 0}) {
  std::vector<Vec2> ring;
  for (int k = 0; k < points; ++k) {
    const double a = 2 * M_PI * k / points;
    ring.push_back({centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)});
  }
  return ring;
}

}  // namespace

TEST_CASE("bezier fit: a 200-point circle is a few cubics within the tolerance") {
  const std::vector<Vec2> ring = circle(200, 100.0);
  for (const double tolerance : {0.25, 0.05}) {
    INFO("tolerance " << tolerance);
    const std::vector<BezierLine> fitted = fit_beziers({ring}, true, tolerance);
    REQUIRE(fitted.size() == 1);
    const BezierLine& line = fitted[0];
    CHECK(line.closed);
    CHECK(line.points.size() >= 2);
    CHECK(line.points.size() <= 12);
    REQUIRE(line.before.size() == line.points.size());
    REQUIRE(line.after.size() == line.points.size());
    const double distance = bezier_hausdorff(line, ring, true);
    INFO(line.points.size() << " segments, " << distance << " from the polyline");
    CHECK(distance <= tolerance);
  }
  // Coarsely flattened (each edge's middle 0.3 of the tolerance inside the circle): still a few cubics.
  const std::vector<Vec2> coarse = circle(32, 3.0);
  const BezierLine few = fit_beziers({coarse}, true, 0.05)[0];
  CHECK(few.points.size() <= 8);
  CHECK(bezier_hausdorff(few, coarse, true) <= 0.05);
  // An open arc: its ends stay its ends.
  std::vector<Vec2> arc = circle(400, 50.0);
  arc.resize(150);
  const BezierLine line = fit_beziers({arc}, false, 0.1)[0];
  CHECK(line.points.front() == arc.front());
  CHECK(line.points.back() == arc.back());
  CHECK(line.points.size() <= 6);
  CHECK(bezier_hausdorff(line, arc, false) <= 0.1);
}

TEST_CASE("bezier fit: a straight run is one straight side, and a corner stays a vertex") {
  std::vector<Vec2> run;
  for (int k = 0; k <= 50; ++k) run.push_back({2.0 * k, 1.0 * k});
  const BezierLine straight = fit_beziers({run}, false, 0.1)[0];
  REQUIRE(straight.points.size() == 2);
  CHECK(straight.after[0] == straight.points[0]);  // zero tangents: a straight side
  CHECK(straight.before[1] == straight.points[1]);
  CHECK(bezier_hausdorff(straight, run, false) <= 1e-9);

  // A square with 20 points to a side: its four corners, four straight sides.
  std::vector<Vec2> square;
  const Vec2 corners[] = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  for (int side = 0; side < 4; ++side)
    for (int k = 0; k < 20; ++k)
      square.push_back(corners[side] + (corners[(side + 1) % 4] - corners[side]) * (k / 20.0));
  const BezierLine box = fit_beziers({square}, true, 0.1)[0];
  REQUIRE(box.points.size() == 4);
  for (const Vec2 corner : corners) CHECK(std::count(box.points.begin(), box.points.end(), corner) == 1);
  for (std::size_t k = 0; k < 4; ++k) CHECK((box.before[k] == box.points[k] && box.after[k] == box.points[k]));

  // A rounded shape with one sharp corner (a teardrop): the corner is a vertex, the curve within tolerance.
  std::vector<Vec2> drop;
  for (int k = 0; k <= 120; ++k) {
    const double a = M_PI * 0.25 + 1.5 * M_PI * k / 120;
    drop.push_back({40 * std::cos(a), 40 * std::sin(a)});
  }
  drop.push_back({0, -40 * std::sqrt(2.0)});  // the tip, where the two tangents meet at a right angle
  const BezierLine tear = fit_beziers({drop}, true, 0.1)[0];
  CHECK(std::count(tear.points.begin(), tear.points.end(), drop.back()) == 1);
  CHECK(tear.points.size() < 12);
  CHECK(bezier_hausdorff(tear, drop, true) <= 0.1);
}

TEST_CASE("bezier fit: two points, one point and no tolerance come back as the polyline") {
  const std::vector<Vec2> two{{0, 0}, {10, 5}};
  for (const bool closed : {false, true}) {
    const BezierLine line = fit_beziers({two}, closed, 0.25)[0];
    CHECK(line.points == two);
    CHECK(line.before == two);
    CHECK(line.after == two);
    CHECK(line.closed == closed);
  }
  CHECK(fit_beziers({{{3, 4}}}, true, 0.25)[0].points.size() == 1);
  const std::vector<Vec2> ring = circle(60, 10.0);
  const BezierLine as_is = fit_beziers({ring}, true, 0.0)[0];
  CHECK(as_is.points == ring);
  // Repeated points (edges of no length) do not break the fit.
  std::vector<Vec2> doubled;
  for (Vec2 p : circle(100, 30.0)) doubled.push_back(p), doubled.push_back(p);
  const BezierLine twice = fit_beziers({doubled}, true, 0.1)[0];
  CHECK(twice.points.size() < 20);
  CHECK(bezier_hausdorff(twice, doubled, true) <= 0.1);
}

TEST_CASE("bezier fit: the keys of one path get the same segments, and a player's shapes between them stay close") {
  // A circle squashed into an ellipse over three keys, turned a little: the same 200 points at each.
  std::vector<std::vector<Vec2>> keys;
  for (const double squash : {1.0, 0.8, 0.6}) {
    std::vector<Vec2> shape;
    for (Vec2 p : circle(200, 60.0)) shape.push_back({p.x + 0.1 * p.y * (1 - squash), p.y * squash});
    keys.push_back(shape);
  }
  const double tolerance = 0.1;
  const std::vector<BezierLine> fitted = fit_beziers(keys, true, tolerance);
  REQUIRE(fitted.size() == 3);
  CHECK(fitted[0].points.size() <= 16);
  for (std::size_t k = 0; k < 3; ++k) {
    INFO("key " << k);
    REQUIRE(fitted[k].points.size() == fitted[0].points.size());
    CHECK(bezier_hausdorff(fitted[k], keys[k], true) <= tolerance);
  }
  // A player moves every vertex and control point straight from one key to the next; the polyline's points
  // move the same way, and the curve stays within the tolerance of them at every share of the way.
  for (const double e : {0.25, 0.5, 0.75}) {
    for (std::size_t k = 0; k + 1 < 3; ++k) {
      const auto mix = [&](const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
        std::vector<Vec2> m;
        for (std::size_t v = 0; v < a.size(); ++v) m.push_back(a[v] + (b[v] - a[v]) * e);
        return m;
      };
      const BezierLine between{mix(fitted[k].points, fitted[k + 1].points), mix(fitted[k].before, fitted[k + 1].before),
                               mix(fitted[k].after, fitted[k + 1].after), true};
      INFO("between keys " << k << " and " << k + 1 << " at " << e);
      CHECK(bezier_hausdorff(between, mix(keys[k], keys[k + 1]), true) <= tolerance);
    }
  }
}
