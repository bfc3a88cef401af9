#include "placement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>

#include "animpak/error.hpp"

namespace animpak::scene_detail {
namespace {

Vec2 rotate(Vec2 v, double angle) {
  // y points down, so the usual rotation matrix turns clockwise on screen for a positive angle.
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

int library_index(const SceneSpec& scene, const std::string& name) {
  for (std::size_t i = 0; i < scene.elements.size(); ++i)
    if (scene.elements[i].name == name) return static_cast<int>(i);
  throw InputError(scene.file.string() + ": guided element names library element \"" + name +
                   "\", which the scene does not define");
}

// A guided element's initial path (paper §4: a polygonal extrusion through the artist's targets). The
// targets are its knots, in unit-container coordinates; in a looping scene the path runs on through the
// seam, so the knots also hold the target before the last of the element that loops into this one (one
// period earlier) and the target after the first of the element this one loops into (one period later).
struct GuideKnot {
  double t;
  Vec2 position;
};
std::vector<GuideKnot> guide_knots(const SceneSpec& scene, std::size_t index, const Container& c) {
  const GuidedSpec& g = scene.guided[index];
  auto unit = [&](const TargetSpec& k) { return c.frame.to_unit({k.x, k.y}); };
  const GuidedSpec *before = nullptr, *after = nullptr;
  if (scene.loop)
    for (const GuidedSpec& o : scene.guided) {
      if (o.name == (g.loop_to.empty() ? g.name : g.loop_to)) after = &o;
      if ((o.loop_to.empty() ? o.name : o.loop_to) == g.name) before = &o;
    }
  std::vector<GuideKnot> knots;
  if (before != nullptr && before->targets.size() >= 2) {
    const TargetSpec& k = before->targets[before->targets.size() - 2];
    knots.push_back({k.t - 1.0, unit(k)});
  }
  for (const TargetSpec& k : g.targets) knots.push_back({k.t, unit(k)});
  if (after != nullptr && after->targets.size() >= 2)
    knots.push_back({after->targets[1].t + 1.0, unit(after->targets[1])});
  // A path that ends where it starts in a scene that does not loop is still a closed curve: it runs on
  // through its own start, so that it turns no corner there (an oval stays an oval, not a lens).
  const std::size_t n = g.targets.size();
  if (before == nullptr && after == nullptr && ends_where_it_starts(g)) {
    const double period = g.targets.back().t - g.targets.front().t;
    knots.insert(knots.begin(), {g.targets[n - 2].t - period, unit(g.targets[n - 2])});
    knots.push_back({g.targets[1].t + period, unit(g.targets[1])});
  }
  return knots;
}

// The path at time t: with `smooth` (guide_curve 1), a cubic Hermite in t through the knots whose tangent
// at a knot is the slope from the knot before to the knot after (Catmull–Rom for uneven times; the one
// neighbour's slope at an open end), so the element passes each target on time without turning a corner
// there; otherwise the straight line between the two targets around t.
Vec2 guide_position(const std::vector<GuideKnot>& knots, double t, bool smooth) {
  std::size_t k = 0;
  while (k + 2 < knots.size() && knots[k + 1].t <= t) ++k;
  const GuideKnot &a = knots[k], &b = knots[std::min(k + 1, knots.size() - 1)];
  const double h = b.t - a.t;
  if (!(h > 0)) return a.position;
  const double u = std::clamp((t - a.t) / h, 0.0, 1.0);
  if (!smooth) return a.position + u * (b.position - a.position);
  auto tangent = [&](std::size_t j) {
    const std::size_t lo = j > 0 ? j - 1 : j, hi = j + 1 < knots.size() ? j + 1 : j;
    return (1.0 / (knots[hi].t - knots[lo].t)) * (knots[hi].position - knots[lo].position);
  };
  const Vec2 ma = tangent(k), mb = tangent(k + 1);
  const double u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * a.position + (h * (u3 - 2 * u2 + u)) * ma + (-2 * u3 + 3 * u2) * b.position +
         (h * (u3 - u2)) * mb;
}

// The targets' scale and angle at time t, straight between two targets; missing scale is 1 and missing
// angle 0.
struct TargetSample {
  Vec2 position;
  double scale, angle;
};
TargetSample sample_targets(const std::vector<TargetSpec>& targets, const std::vector<GuideKnot>& knots, bool smooth,
                            double t) {
  std::size_t k = 0;
  while (k + 2 < targets.size() && targets[k + 1].t <= t) ++k;
  const TargetSpec& a = targets[k];
  const TargetSpec& b = targets[std::min(k + 1, targets.size() - 1)];
  const double span = b.t - a.t;
  const double w = span > 0 ? std::clamp((t - a.t) / span, 0.0, 1.0) : 0.0;
  auto mix = [&](double u, double v) { return u + w * (v - u); };
  return {guide_position(knots, t, smooth), mix(a.scale.value_or(1.0), b.scale.value_or(1.0)),
          mix(a.angle.value_or(0.0), b.angle.value_or(0.0)) * std::numbers::pi / 180.0};
}

// A guided element's angle per slice with `"orient": "path"` (docs/scene-format.md, "Facing along the
// path"): the art's `facing` direction turned along the path's direction at the slice's time, unwrapped
// from slice to slice so that it turns continuously (a slice where the path stands still keeps the angle
// before it). A target that gives an angle still wins at its slice: the difference there fades linearly in
// t to nothing at the targets on either side (a target without an angle faces along the path).
std::vector<double> path_angles(const GuidedSpec& g, const std::vector<GuideKnot>& knots, bool smooth,
                                const std::vector<double>& slice_t) {
  const double facing = g.facing * std::numbers::pi / 180.0;
  const double lo = knots.front().t, hi = knots.back().t;
  const auto direction = [&](double t) -> std::optional<double> {
    constexpr double h = 1e-4;
    const Vec2 d =
        guide_position(knots, std::min(hi, t + h), smooth) - guide_position(knots, std::max(lo, t - h), smooth);
    if (!(norm(d) > 1e-12)) return std::nullopt;
    return std::atan2(d.y, d.x) - facing;
  };
  const auto nearest_turn = [](double angle, double to) {
    return angle + 2.0 * std::numbers::pi * std::round((to - angle) / (2.0 * std::numbers::pi));
  };
  const std::size_t n = slice_t.size();
  std::vector<std::optional<double>> raw(n);
  for (std::size_t s = 0; s < n; ++s) raw[s] = direction(slice_t[s]);
  std::vector<double> angles(n, -facing);
  const auto first = std::find_if(raw.begin(), raw.end(), [](const auto& a) { return a.has_value(); });
  if (first == raw.end()) return angles;  // the path never moves: the art as drawn
  double previous = **first;
  for (std::size_t s = 0; s < n; ++s) angles[s] = previous = raw[s] ? nearest_turn(*raw[s], previous) : previous;
  // Each target's difference from the path's angle at its slice, in (−π, π]: 0 without an angle.
  std::vector<std::pair<double, double>> fixes;
  bool any = false;
  for (const TargetSpec& k : g.targets) {
    const auto s = static_cast<std::size_t>(std::lround(k.t * double(n - 1)));
    const double wanted = k.angle ? *k.angle * std::numbers::pi / 180.0 : 0.0;
    fixes.emplace_back(k.t, k.angle ? wanted - nearest_turn(angles[s], wanted) : 0.0);
    any = any || k.angle.has_value();
  }
  if (!any) return angles;
  for (std::size_t s = 0; s < n; ++s) {
    const double t = slice_t[s];
    std::size_t j = 0;
    while (j + 2 < fixes.size() && fixes[j + 1].first <= t) ++j;
    const double span = fixes[j + 1].first - fixes[j].first;
    const double w = span > 0 ? std::clamp((t - fixes[j].first) / span, 0.0, 1.0) : 0.0;
    angles[s] += fixes[j].second + w * (fixes[j + 1].second - fixes[j].second);
  }
  return angles;
}

std::string describe_target(const std::vector<TargetSpec>& targets, std::size_t k) {
  std::ostringstream s;
  s << "target " << k << " (x " << targets[k].x << ", y " << targets[k].y << ", t " << targets[k].t << ")";
  return s.str();
}

// A target outside the container cannot be reached and is an input error. A stretch of the initial path
// between two targets that leaves the container only misplaces it: the boundary force (Eq. 4) pushes
// the slices back in, so it is a warning with the fix.
void check_target_path(const SceneSpec& scene, std::size_t index, const Container& c,
                       const std::vector<GuideKnot>& knots, bool smooth, std::vector<std::string>& notes) {
  const GuidedSpec& g = scene.guided[index];
  const std::string who = "guided[" + std::to_string(index) + "] \"" + g.name + "\"";
  auto where = [&](Vec2 p) {
    return ring_contains(c.outline, p) ? "in a hole of the container" : "outside the container";
  };
  for (std::size_t k = 0; k < g.targets.size(); ++k) {
    const Vec2 p = c.frame.to_unit({g.targets[k].x, g.targets[k].y});
    if (!c.contains(p))
      throw InputError(scene.file.string() + ": " + who + ".targets[" + std::to_string(k) +
                       "]: " + describe_target(g.targets, k) + " lies " + where(p) +
                       "; the anchor cannot reach it, move it into the container");
  }
  // Samples each stretch every path_step of the unit container (1 unit of a 500-unit artboard) along its
  // chord: only a hole or bay narrower than that can slip between two samples.
  constexpr double path_step = 0.002;
  for (std::size_t k = 0; k + 1 < g.targets.size(); ++k) {
    const Vec2 a = c.frame.to_unit({g.targets[k].x, g.targets[k].y});
    const Vec2 b = c.frame.to_unit({g.targets[k + 1].x, g.targets[k + 1].y});
    const int steps = std::max(1, static_cast<int>(std::ceil(2.0 * norm(b - a) / path_step)));
    for (int i = 1; i < steps; ++i) {
      const double t = g.targets[k].t + (g.targets[k + 1].t - g.targets[k].t) * i / steps;
      const Vec2 q = guide_position(knots, t, smooth);
      if (c.contains(q)) continue;
      const bool hole = ring_contains(c.outline, q);
      notes.push_back("warning: guided \"" + g.name + "\": the " + (smooth ? "path" : "straight path") + " from " +
                      describe_target(g.targets, k) + " to target " + std::to_string(k + 1) + " runs " +
                      (hole ? "through a hole of the container" : "outside the container") +
                      "; the simulation will push it " + (hole ? "out" : "back in") +
                      ", add a target in between to steer it");
      break;
    }
  }
}

}  // namespace

Vec2 apply(const Placement& p, int slice, Vec2 q) {
  return p.offset[slice] + p.scale[slice] * rotate(q - p.pivot, p.angle[slice]);
}

Vec2 placed(const Placement& p, const SpacetimeElement& e, int s, int v) {
  const int period = e.slice_count - 1;
  const int source = p.phase == 0 || period < 1 ? s : (s + p.phase) % period;
  return apply(p, s, e.position(source, v));
}

Vec2 rest_centroid(const SpacetimeElement& e) {
  std::vector<Vec2> ring(e.slice.vertices.begin(), e.slice.vertices.begin() + e.slice.boundary_count);
  const double a = signed_area(ring);
  Vec2 c;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 p = ring[i], q = ring[(i + 1) % ring.size()];
    c = c + cross(p, q) * (p + q);
  }
  return (1.0 / (6.0 * a)) * c;
}

std::vector<Placement> place_guided(const SceneSpec& scene, const Container& container,
                                    const std::vector<SpacetimeElement>& library, std::vector<std::string>& notes) {
  std::vector<Placement> out;
  for (std::size_t gi = 0; gi < scene.guided.size(); ++gi) {
    const GuidedSpec& g = scene.guided[gi];
    Placement p;
    p.library = library_index(scene, g.element);
    p.name = g.name;
    p.guided = true;
    const SpacetimeElement& e = library[p.library];
    p.pivot = rest_centroid(e);
    // The anchor is the slice vertex closest to the centroid (paper §4).
    p.anchor = nearest_index(e.slice.vertices, p.pivot);
    const bool smooth = scene.params.placement.guide_curve != 0;
    const std::vector<GuideKnot> knots = guide_knots(scene, gi, container);
    check_target_path(scene, gi, container, knots, smooth, notes);
    // Paper §4: the anchor is sprung to the artist's target points only; the slices in between start
    // on the interpolated path and are free to smooth it out. Each target acts on the slice nearest
    // its t, and that slice is placed at the target itself, so its rest scale and angle are the
    // target's.
    std::vector<int> key_of_slice(e.slice_count, -1);
    for (std::size_t k = 0; k < g.targets.size(); ++k) {
      const TargetSpec& target = g.targets[k];
      const int s = static_cast<int>(std::lround(target.t * (e.slice_count - 1)));
      if (key_of_slice[s] >= 0)
        throw InputError(scene.file.string() + ": guided[" + std::to_string(gi) + "] \"" + g.name + "\": targets " +
                         std::to_string(key_of_slice[s]) + " and " + std::to_string(k) + " both fall on slice " +
                         std::to_string(s) + " of " + std::to_string(e.slice_count) +
                         "; move them further apart in t or raise `slices`");
      key_of_slice[s] = static_cast<int>(k);
    }
    std::vector<double> slice_t(e.slice_count);
    for (int s = 0; s < e.slice_count; ++s)
      slice_t[s] = key_of_slice[s] >= 0 ? g.targets[key_of_slice[s]].t
                                        : static_cast<float>(s) / static_cast<float>(e.slice_count - 1);
    const std::vector<double> turned = g.orient_path ? path_angles(g, knots, smooth, slice_t) : std::vector<double>{};
    for (int s = 0; s < e.slice_count; ++s) {
      const float t = static_cast<float>(s) / static_cast<float>(e.slice_count - 1);
      const int key = key_of_slice[s];
      TargetSample target = sample_targets(g.targets, knots, smooth, slice_t[s]);
      if (g.orient_path) target.angle = turned[s];
      const double scale = scene.params.placement.initial_scale * target.scale;
      const Vec2 anchor = e.position(s, p.anchor);
      p.scale.push_back(scale);
      p.angle.push_back(target.angle);
      p.offset.push_back(target.position - scale * rotate(anchor - p.pivot, target.angle));
      p.path.push_back(target.position);
      if (key >= 0)
        p.keys.push_back({s,
                          {static_cast<float>(target.position.x), static_cast<float>(target.position.y), t},
                          g.orient_path || g.targets[key].angle.has_value()});
    }
    out.push_back(std::move(p));
  }
  for (std::size_t i = 0; i < scene.guided.size(); ++i) {
    if (!scene.loop) continue;
    const std::string& to = scene.guided[i].loop_to.empty() ? scene.guided[i].name : scene.guided[i].loop_to;
    for (std::size_t j = 0; j < out.size(); ++j)
      if (out[j].name == to) out[i].loop_partner = static_cast<int>(j);
    if (out[i].loop_partner >= 0 && out[out[i].loop_partner].library != out[i].library)
      throw InputError(scene.file.string() + ": guided[" + std::to_string(i) + "].loop_to: \"" + to +
                       "\" uses another library element; a loop joins slices vertex to vertex, so both must use "
                       "the same element");
  }
  if (!out.empty()) notes.push_back("placed " + std::to_string(out.size()) + " guided element(s)");
  return out;
}

}  // namespace animpak::scene_detail
