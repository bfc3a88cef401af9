// Adaptive flattening of SVG path segments. Curves are flattened after the element's transform so the
// tolerance is in art units whatever the nesting of scales.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "svg_internal.hpp"

namespace animpak::svg {

namespace {

// Deeper subdivision than this cannot matter at any sane tolerance and guards against NaN input.
constexpr int kMaxFlattenDepth = 18;

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  if (len2 == 0.0) return norm(p - a);
  const double t = std::clamp(dot(p - a, ab) / len2, 0.0, 1.0);
  return norm(p - (a + t * ab));
}

Vec2 lerp(Vec2 a, Vec2 b, double t) { return a + t * (b - a); }

}  // namespace

Affine compose(const Affine& o, const Affine& i) {
  return {o.a * i.a + o.c * i.b, o.b * i.a + o.d * i.b,       o.a * i.c + o.c * i.d,
          o.b * i.c + o.d * i.d, o.a * i.e + o.c * i.f + o.e, o.b * i.e + o.d * i.f + o.f};
}

std::vector<Vec2> thin_straight_runs(const std::vector<Vec2>& points, const std::vector<bool>& straight,
                                     double tolerance) {
  // Sleeve fitting from an anchor: each skipped point p at distance d > h from the anchor allows the
  // directions within asin(h / d) of its own, so a chord whose direction lies in every such wedge passes
  // within h of each skipped point sideways; a chord is also never shorter than the farthest skipped
  // point less h, so none lies more than h beyond its end. With h = tolerance / √2 every skipped point,
  // and so (distance to a segment being convex) every skipped segment, is within `tolerance` of the chord.
  // Each point is looked at once or twice, so a million-point trace thins in well under a second.
  const size_t n = points.size();
  if (n < 3) return points;
  const double h = tolerance / std::numbers::sqrt2;
  const auto thinnable = [&](size_t i) { return i + 1 < n && straight[i] && straight[i + 1]; };
  std::vector<Vec2> out{points[0]};
  size_t anchor = 0;
  while (anchor + 1 < n) {
    const Vec2 a = points[anchor];
    Vec2 ref{};  // the direction angles are measured from, set by the first point farther than h
    bool wedged = false;
    double lo = 0.0, hi = 0.0, farthest = 0.0;
    size_t end = anchor + 1;
    for (size_t k = anchor + 1; k < n; ++k) {
      const Vec2 v = points[k] - a;
      const double d = norm(v);
      const double angle = wedged ? std::atan2(cross(ref, v), dot(ref, v)) : 0.0;
      if (k > anchor + 1 && (d < farthest - h || (wedged && (angle < lo || angle > hi)))) break;
      end = k;
      if (!thinnable(k)) break;
      farthest = std::max(farthest, d);
      if (d > h) {
        const double half = std::asin(h / d);
        if (!wedged) {
          ref = (1.0 / d) * v;
          wedged = true;
          lo = -half, hi = half;
        } else {
          lo = std::max(lo, angle - half), hi = std::min(hi, angle + half);
        }
      }
    }
    out.push_back(points[end]);
    anchor = end;
  }
  return out;
}

void PathFlattener::emit(Vec2 q, bool straight) {
  if (!has_open_) {
    open_ = Polyline{};
    straight_.clear();
    has_open_ = true;
  }
  if (!open_.points.empty()) {
    const Vec2 last = open_.points.back();
    if (std::abs(last.x - q.x) <= 1e-12 && std::abs(last.y - q.y) <= 1e-12) return;
  }
  open_.points.push_back(q);
  straight_.push_back(straight);
  ++points_;
}

void PathFlattener::end_subpath(bool closed) {
  if (!has_open_) return;
  has_open_ = false;
  auto& pts = open_.points;
  // A closed ring does not repeat its first point: the closing segment is implied.
  if (closed && pts.size() > 1 && norm(pts.back() - pts.front()) <= 1e-9 * (1.0 + norm(pts.front()))) {
    pts.pop_back();
    straight_.pop_back();
  }
  if (pts.size() < 2) {
    ++dropped_;
    return;
  }
  // docs/scene-format.md "Large paths": a trace of a million points is mostly straight runs finer than
  // the tolerance; thinning them here keeps the offset, sampling and binding of the element linear in
  // what the art shows rather than in how densely it was written. Curves are already flattened no finer
  // than the tolerance needs and are left as they are.
  pts = thin_straight_runs(pts, straight_, tol_);
  open_.closed = closed;
  done_.push_back(std::move(open_));
}

void PathFlattener::move_to(Vec2 p) {
  end_subpath(false);
  start_ = cur_ = p;
  emit(m_.apply(p), true);
}

void PathFlattener::line_to(Vec2 p) {
  if (!has_open_) emit(m_.apply(cur_), true);
  emit(m_.apply(p), true);
  cur_ = p;
}

void PathFlattener::quadratic_to(Vec2 c, Vec2 p) {
  // Degree elevation is exact, so the cubic flattener serves both.
  cubic_to(cur_ + (2.0 / 3.0) * (c - cur_), p + (2.0 / 3.0) * (c - p), p);
}

void PathFlattener::cubic_to(Vec2 c1, Vec2 c2, Vec2 p) {
  if (!has_open_) emit(m_.apply(cur_), true);
  cubic_art(m_.apply(cur_), m_.apply(c1), m_.apply(c2), m_.apply(p), 0);
  cur_ = p;
}

void PathFlattener::cubic_art(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3, int depth) {
  // The curve lies in the hull of its control points, so when both inner points are within the
  // tolerance of the chord the whole curve is.
  const double flat = std::max(distance_to_segment(p1, p0, p3), distance_to_segment(p2, p0, p3));
  if (!(flat > tol_) || depth >= kMaxFlattenDepth) {
    emit(p3, false);
    return;
  }
  const Vec2 a = lerp(p0, p1, 0.5), b = lerp(p1, p2, 0.5), c = lerp(p2, p3, 0.5);
  const Vec2 ab = lerp(a, b, 0.5), bc = lerp(b, c, 0.5), mid = lerp(ab, bc, 0.5);
  cubic_art(p0, a, ab, mid, depth + 1);
  cubic_art(mid, bc, c, p3, depth + 1);
}

void PathFlattener::arc_to(double rx, double ry, double rotation_deg, bool large_arc, bool sweep, Vec2 p) {
  // SVG 1.1 appendix F.6: endpoint to centre parameterisation, with out-of-range radii scaled up.
  const Vec2 p0 = cur_;
  rx = std::abs(rx);
  ry = std::abs(ry);
  if (rx == 0.0 || ry == 0.0 || (p0.x == p.x && p0.y == p.y)) {
    line_to(p);
    return;
  }
  const double phi = rotation_deg * std::numbers::pi / 180.0;
  const double cs = std::cos(phi), sn = std::sin(phi);
  const double dx = (p0.x - p.x) / 2, dy = (p0.y - p.y) / 2;
  const double x1 = cs * dx + sn * dy, y1 = -sn * dx + cs * dy;
  const double lambda = (x1 * x1) / (rx * rx) + (y1 * y1) / (ry * ry);
  if (lambda > 1.0) {
    rx *= std::sqrt(lambda);
    ry *= std::sqrt(lambda);
  }
  const double num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
  const double den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
  double k = std::sqrt(std::max(0.0, num / den));
  if (large_arc == sweep) k = -k;
  const double cxp = k * rx * y1 / ry, cyp = -k * ry * x1 / rx;
  const Vec2 centre{cs * cxp - sn * cyp + (p0.x + p.x) / 2, sn * cxp + cs * cyp + (p0.y + p.y) / 2};
  const double theta1 = std::atan2((y1 - cyp) / ry, (x1 - cxp) / rx);
  double dtheta = std::atan2((-y1 - cyp) / ry, (-x1 - cxp) / rx) - theta1;
  if (sweep && dtheta < 0) dtheta += 2 * std::numbers::pi;
  if (!sweep && dtheta > 0) dtheta -= 2 * std::numbers::pi;

  const auto at = [&](double t) {
    const Vec2 u{rx * std::cos(t), ry * std::sin(t)};
    return m_.apply({centre.x + cs * u.x - sn * u.y, centre.y + sn * u.x + cs * u.y});
  };
  if (!has_open_) emit(m_.apply(cur_), true);
  // Quarter turns at most, then halve until the sagitta (checked at the quarter points too, as an
  // affine-mapped ellipse need not bulge most at the middle) is within the tolerance.
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(dtheta) / (std::numbers::pi / 2))));
  std::vector<std::pair<double, double>> stack;
  for (int i = pieces - 1; i >= 0; --i)
    stack.emplace_back(theta1 + dtheta * i / pieces, theta1 + dtheta * (i + 1) / pieces);
  while (!stack.empty()) {
    const auto [t0, t1] = stack.back();
    stack.pop_back();
    const Vec2 a = at(t0), b = at(t1);
    double dev = 0.0;
    for (double s : {0.25, 0.5, 0.75}) dev = std::max(dev, distance_to_segment(at(t0 + s * (t1 - t0)), a, b));
    if (dev > tol_ && std::abs(t1 - t0) > 1e-6) {
      const double tm = 0.5 * (t0 + t1);
      stack.emplace_back(tm, t1);
      stack.emplace_back(t0, tm);
    } else {
      emit(b, false);
    }
  }
  if (!open_.points.empty()) open_.points.back() = m_.apply(p);  // land exactly on the endpoint
  cur_ = p;
}

void PathFlattener::close() {
  end_subpath(true);
  cur_ = start_;
}

std::vector<Polyline> PathFlattener::take() {
  end_subpath(false);
  return std::move(done_);
}

}  // namespace animpak::svg

namespace animpak {

std::vector<Vec2> thin_polyline(const std::vector<Vec2>& points, double tolerance) {
  return svg::thin_straight_runs(points, std::vector<bool>(points.size(), true), tolerance);
}

}  // namespace animpak
