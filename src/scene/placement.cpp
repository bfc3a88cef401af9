#include "placement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
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

// Piecewise-linear interpolation of the targets at time t (paper §4: the initial guided path is a
// polygonal extrusion); missing scale is 1 and missing angle 0.
struct TargetSample {
  Vec2 position;
  double scale, angle;
};
TargetSample sample_targets(const std::vector<TargetSpec>& targets, const Container& c, double t) {
  std::size_t k = 0;
  while (k + 2 < targets.size() && targets[k + 1].t <= t) ++k;
  const TargetSpec& a = targets[k];
  const TargetSpec& b = targets[std::min(k + 1, targets.size() - 1)];
  const double span = b.t - a.t;
  const double w = span > 0 ? std::clamp((t - a.t) / span, 0.0, 1.0) : 0.0;
  auto mix = [&](double u, double v) { return u + w * (v - u); };
  const Vec2 pa = c.frame.to_unit({a.x, a.y}), pb = c.frame.to_unit({b.x, b.y});
  return {{mix(pa.x, pb.x), mix(pa.y, pb.y)},
          mix(a.scale.value_or(1.0), b.scale.value_or(1.0)),
          mix(a.angle.value_or(0.0), b.angle.value_or(0.0)) * std::numbers::pi / 180.0};
}

std::string describe_target(const std::vector<TargetSpec>& targets, std::size_t k) {
  std::ostringstream s;
  s << "target " << k << " (x " << targets[k].x << ", y " << targets[k].y << ", t " << targets[k].t << ")";
  return s.str();
}

// A target outside the container cannot be reached and is an input error. A straight stretch between
// two targets that leaves the container only misplaces the initial path: the boundary force (Eq. 4)
// pushes the slices back in, so it is a warning with the fix.
void check_target_path(const SceneSpec& scene, std::size_t index, const Container& c, std::vector<std::string>& notes) {
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
  // Samples each stretch every path_step of the unit container (1 unit of a 500-unit artboard): only a
  // hole or bay narrower than that can slip between two samples.
  constexpr double path_step = 0.002;
  for (std::size_t k = 0; k + 1 < g.targets.size(); ++k) {
    const Vec2 a = c.frame.to_unit({g.targets[k].x, g.targets[k].y});
    const Vec2 b = c.frame.to_unit({g.targets[k + 1].x, g.targets[k + 1].y});
    const int steps = std::max(1, static_cast<int>(std::ceil(norm(b - a) / path_step)));
    for (int i = 1; i < steps; ++i) {
      const Vec2 q = a + (static_cast<double>(i) / steps) * (b - a);
      if (c.contains(q)) continue;
      const bool hole = ring_contains(c.outline, q);
      notes.push_back("warning: guided \"" + g.name + "\": the straight path from " + describe_target(g.targets, k) +
                      " to target " + std::to_string(k + 1) + " runs " +
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
    check_target_path(scene, gi, container, notes);
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
    for (int s = 0; s < e.slice_count; ++s) {
      const float t = static_cast<float>(s) / static_cast<float>(e.slice_count - 1);
      const int key = key_of_slice[s];
      const TargetSample target = sample_targets(g.targets, container, key >= 0 ? g.targets[key].t : t);
      const double scale = scene.params.placement.initial_scale * target.scale;
      const Vec2 anchor = e.position(s, p.anchor);
      p.scale.push_back(scale);
      p.angle.push_back(target.angle);
      p.offset.push_back(target.position - scale * rotate(anchor - p.pivot, target.angle));
      p.path.push_back(target.position);
      if (key >= 0)
        p.keys.push_back({s,
                          {static_cast<float>(target.position.x), static_cast<float>(target.position.y), t},
                          g.targets[key].angle.has_value()});
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
