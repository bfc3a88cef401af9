// Scripted slice animation (paper §3.2): the positions of every slice vertex at t = s / (n_s − 1).
//
// Order of composition, for each slice time t:
//   (1) shape: keyed vertex handles (splined in x and y) deform the rest slice by ARAP; with the `swim`
//       preset its axis handles join them in the same solve, and the user's handle targets are carried
//       along by the swim's bend, so a keyed fin still sits on the bent body;
//   (2) the `rotate` / `pulse` preset: a similarity about the pivot, in the element's own frame;
//   (3) the keyed transform (translate, rotate, scale splined per component) about the pivot.
// (2) and (3) are both about the same pivot, so their rotations and scales commute; applying the preset
// first only means the keyed translation is not itself spun or scaled by the preset: a keyed path with
// `rotate` spins the element in place along the path instead of swinging it around the start point.
// With `loop`, slice n_s − 1 is slice 0 exactly (periodic splines, whole turns and whole wave counts).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>

#include "animpak/animation.hpp"
#include "animpak/error.hpp"

namespace animpak {

namespace {

constexpr int arap_iterations = 20;   // warm-started from the previous slice, so few are needed
constexpr int swim_axis_handles = 9;  // enough to carry a one-wavelength bend, few enough to stay smooth
constexpr int swim_curve_samples = 256;

std::string fmt(const std::string& prefix, double value) {
  std::ostringstream out;
  out << prefix << value;
  return out.str();
}

Spline keyed_spline(std::vector<double> times, std::vector<double> values, bool loop, const std::string& where) {
  try {
    return Spline(std::move(times), std::move(values), loop);
  } catch (const InputError& e) {
    throw InputError(where + e.what());
  }
}

Vec2 area_centroid(const std::vector<Vec2>& ring, const std::vector<Vec2>& fallback) {
  double a = 0.0, cx = 0.0, cy = 0.0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Vec2 p = ring[i], q = ring[(i + 1) % n];
    const double c = cross(p, q);
    a += c;
    cx += (p.x + q.x) * c;
    cy += (p.y + q.y) * c;
  }
  if (std::fabs(a) > 1e-14) return {cx / (3.0 * a), cy / (3.0 * a)};
  Vec2 mean;  // no usable outline: the mean of the slice vertices is the next best centre
  for (Vec2 p : fallback) mean = mean + p;
  return mean * (1.0 / static_cast<double>(fallback.size()));
}

/// Screen-clockwise rotation by `angle` radians (y down), scaling by `scale`, about `pivot`, then `shift`.
Vec2 similarity(Vec2 p, Vec2 pivot, double angle, double scale, Vec2 shift) {
  const double c = std::cos(angle) * scale, s = std::sin(angle) * scale;
  const Vec2 d = p - pivot;
  return pivot + shift + Vec2{c * d.x - s * d.y, s * d.x + c * d.y};
}

/// The keyed similarity transform, one spline per component; identity without keys.
struct KeyedTransform {
  std::optional<Spline> tx, ty, angle, scale;

  explicit KeyedTransform(const AnimationSpec& spec) {
    if (spec.keys.empty()) return;
    std::vector<double> t, x, y, r, s;
    for (std::size_t i = 0; i < spec.keys.size(); ++i) {
      const TransformKey& k = spec.keys[i];
      const std::string where = "animation.keys[" + std::to_string(i) + "]";
      if (!std::isfinite(k.translate.x) || !std::isfinite(k.translate.y) || !std::isfinite(k.rotate))
        throw InputError(where + ": translate and rotate must be finite numbers");
      if (!(k.scale > 0.0) || !std::isfinite(k.scale))
        throw InputError(fmt(where + ".scale = ", k.scale) + ": expected a number > 0");
      t.push_back(k.t);
      x.push_back(k.translate.x);
      y.push_back(k.translate.y);
      r.push_back(k.rotate * std::numbers::pi / 180.0);
      s.push_back(k.scale);
    }
    tx = keyed_spline(t, x, spec.loop, "animation.keys");
    ty = keyed_spline(t, y, spec.loop, "animation.keys");
    angle = keyed_spline(t, r, spec.loop, "animation.keys");
    scale = keyed_spline(std::move(t), std::move(s), spec.loop, "animation.keys");
  }

  Vec2 apply(Vec2 p, Vec2 pivot, double frame_scale, double t) const {
    if (!tx) return p;
    const double k = (*scale)(t);
    if (!(k > 0.0))
      throw InputError(fmt("animation.keys: the scale spline dips to ", k) + fmt(" at t = ", t) +
                       "; add keys between the scale keys or make them closer in value");
    return similarity(p, pivot, (*angle)(t), k, Vec2{(*tx)(t), (*ty)(t)} * frame_scale);
  }
};

/// The `swim` preset's bend: a wave travelling from head to tail along the main axis, applied to the
/// axis as an arc-length-preserving curve so the body bends without stretching, and to any other point
/// by its distance along the axis and its offset across it.
class SwimBend {
 public:
  SwimBend(const std::vector<Vec2>& rest, Vec2 pivot, const AnimationSpec& spec) : spec_(spec) {
    Vec2 c;
    for (Vec2 p : rest) c = c + p;
    c = c * (1.0 / static_cast<double>(rest.size()));
    double sxx = 0, sxy = 0, syy = 0;
    for (Vec2 p : rest) {
      const Vec2 d = p - c;
      sxx += d.x * d.x, sxy += d.x * d.y, syy += d.y * d.y;
    }
    const double phi = 0.5 * std::atan2(2.0 * sxy, sxx - syy);  // principal axis of the 2×2 covariance
    axis_ = {std::cos(phi), std::sin(phi)};
    double lo = 1e300, hi = -1e300;
    for (Vec2 p : rest) lo = std::min(lo, dot(p - c, axis_)), hi = std::max(hi, dot(p - c, axis_));
    // The head is the end nearer the pivot: by default the area centroid, which sits toward the bulkier
    // end (a fish's head, not its tail fin); a scene can move the pivot to choose the other end.
    if (dot(pivot - c, axis_) > 0.5 * (lo + hi)) {
      axis_ = axis_ * -1.0;
      std::swap(lo, hi);
      lo = -lo, hi = -hi;
    }
    length_ = hi - lo;
    if (!(length_ > 1e-9)) throw InputError("animation.preset swim: the slice has no extent to bend");
    head_ = c + axis_ * lo;
    across_ = {-axis_.y, axis_.x};
  }

  /// Samples the bent centre line at time t; later map() calls use it.
  void set_time(double t) {
    curve_.assign(swim_curve_samples + 1, Vec2{});
    arc_.assign(swim_curve_samples + 1, 0.0);
    for (int k = 0; k <= swim_curve_samples; ++k) {
      const double u = static_cast<double>(k) / swim_curve_samples;
      curve_[k] = {u * length_, lateral(u, t)};
      if (k > 0) arc_[k] = arc_[k - 1] + norm(curve_[k] - curve_[k - 1]);
    }
    t_ = t;
  }

  /// Where the rest-frame point p goes at the time of the last set_time().
  Vec2 map(Vec2 p) const {
    const double along = dot(p - head_, axis_), off = dot(p - head_, across_);
    // The point on the centre line at arc length `along` from the head (extended straight past the ends).
    const auto seg = std::upper_bound(arc_.begin(), arc_.end(), along) - arc_.begin() - 1;
    const std::size_t k = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(seg, 0, swim_curve_samples - 1));
    const double f = (along - arc_[k]) / (arc_[k + 1] - arc_[k]);
    const Vec2 on = curve_[k] + (curve_[k + 1] - curve_[k]) * f;
    const double u = std::clamp((k + std::clamp(f, 0.0, 1.0)) / swim_curve_samples, 0.0, 1.0);
    Vec2 tangent{length_, slope(u, t_)};
    tangent = tangent * (1.0 / norm(tangent));
    const Vec2 bent = on + Vec2{-tangent.y, tangent.x} * off;
    return head_ + axis_ * bent.x + across_ * bent.y;
  }

  /// Points on the rest axis from head to tail where the swim's ARAP handles go.
  std::vector<Vec2> axis_points() const {
    std::vector<Vec2> points;
    for (int k = 0; k < swim_axis_handles; ++k)
      points.push_back(head_ + axis_ * (length_ * k / (swim_axis_handles - 1)));
    return points;
  }

 private:
  // amplitude · L · w(u) · sin(2π(u/λ − count·t)), w(u) = u²: the head (u = 0) stays put, the tail
  // swings widest, as in carangiform swimming.
  double phase(double u, double t) const { return 2.0 * std::numbers::pi * (u / spec_.wavelength - spec_.count * t); }
  double lateral(double u, double t) const { return spec_.amplitude * length_ * u * u * std::sin(phase(u, t)); }
  double slope(double u, double t) const {  // d lateral / du
    return spec_.amplitude * length_ *
           (2.0 * u * std::sin(phase(u, t)) +
            u * u * std::cos(phase(u, t)) * 2.0 * std::numbers::pi / spec_.wavelength);
  }

  const AnimationSpec& spec_;
  Vec2 axis_, across_, head_;
  double length_ = 0.0, t_ = 0.0;
  std::vector<Vec2> curve_;
  std::vector<double> arc_;
};

void validate_preset(const AnimationSpec& spec) {
  const bool rotate = spec.preset == AnimationPreset::rotate, pulse = spec.preset == AnimationPreset::pulse,
             swim = spec.preset == AnimationPreset::swim;
  if (rotate && !std::isfinite(spec.turns)) throw InputError("animation.turns: expected a finite number");
  if (rotate && spec.loop && spec.turns != std::round(spec.turns))
    throw InputError(fmt("animation.turns = ", spec.turns) +
                     ": a looping rotation needs a whole number of turns, or t = 1 would jump back to t = 0; "
                     "use an integer or set loop to false");
  if (pulse && !(std::fabs(spec.amplitude) < 1.0))
    throw InputError(fmt("animation.amplitude = ", spec.amplitude) +
                     ": a pulse scales by 1 ± amplitude, so it must lie strictly between -1 and 1");
  if (swim && !std::isfinite(spec.amplitude)) throw InputError("animation.amplitude: expected a finite number");
  if (swim && !(spec.wavelength > 0.0 && std::isfinite(spec.wavelength)))
    throw InputError(fmt("animation.wavelength = ", spec.wavelength) + ": expected a number > 0");
}

}  // namespace

std::vector<std::vector<Vec2>> animate_slices(const SliceMesh& mesh, const Outline& outline, const ArtFrame& frame,
                                              const AnimationSpec& spec, int slices) {
  if (slices < 2) throw InputError("slices = " + std::to_string(slices) + ": need at least 2 slices");
  if (mesh.vertices.empty()) throw InputError("animation: the slice has no vertices");
  validate_preset(spec);
  const KeyedTransform keyed(spec);
  const Vec2 pivot = spec.pivot ? frame.to_unit(*spec.pivot) : area_centroid(outline.ring, mesh.vertices);

  // User handles: bound to their nearest rest vertex, keys splined per coordinate in unit space.
  std::vector<int> handle_vertex;
  std::vector<Spline> handle_x, handle_y;
  for (std::size_t h = 0; h < spec.handles.size(); ++h) {
    const HandleSpec& hs = spec.handles[h];
    const std::string where = "animation.handles[" + std::to_string(h) + "]";
    if (hs.keys.empty()) throw InputError(where + ".keys: a handle needs at least one key position");
    const int v = nearest_index(mesh.vertices, frame.to_unit(hs.point));
    const auto same = std::find(handle_vertex.begin(), handle_vertex.end(), v);
    if (same != handle_vertex.end())
      throw InputError(where + " and animation.handles[" + std::to_string(same - handle_vertex.begin()) +
                       "] bind to the same slice vertex " + std::to_string(v) +
                       "; move one of their points further apart or merge them into one handle");
    std::vector<double> t, x, y;
    for (std::size_t k = 0; k < hs.keys.size(); ++k) {
      const Vec2 p = frame.to_unit(hs.keys[k].position);
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw InputError(where + ".keys[" + std::to_string(k) + "].position: expected finite numbers");
      t.push_back(hs.keys[k].t);
      x.push_back(p.x);
      y.push_back(p.y);
    }
    handle_vertex.push_back(v);
    handle_x.push_back(keyed_spline(t, x, spec.loop, where + ".keys"));
    handle_y.push_back(keyed_spline(std::move(t), std::move(y), spec.loop, where + ".keys"));
  }

  std::optional<SwimBend> swim;
  std::vector<int> arap_vertices = handle_vertex;
  std::vector<int> swim_vertices;  // axis handles not already keyed by the user
  if (spec.preset == AnimationPreset::swim) {
    swim.emplace(mesh.vertices, pivot, spec);
    for (Vec2 p : swim->axis_points()) {
      const int v = nearest_index(mesh.vertices, p);
      if (std::find(arap_vertices.begin(), arap_vertices.end(), v) != arap_vertices.end()) continue;
      arap_vertices.push_back(v);
      swim_vertices.push_back(v);
    }
  }
  std::optional<ArapSolver> arap;
  if (!arap_vertices.empty()) arap.emplace(mesh, arap_vertices);

  std::vector<std::vector<Vec2>> out(slices);
  std::vector<Vec2> shape = mesh.vertices;  // stage (1) of the previous slice: the next one's warm start
  const int computed = spec.loop ? slices - 1 : slices;
  for (int s = 0; s < computed; ++s) {
    const double t = static_cast<double>(s) / (slices - 1);
    if (arap) {
      std::vector<Vec2> targets;
      for (std::size_t h = 0; h < handle_vertex.size(); ++h) targets.push_back({handle_x[h](t), handle_y[h](t)});
      if (swim) {
        swim->set_time(t);
        for (Vec2& p : targets) p = swim->map(p);
        for (int v : swim_vertices) targets.push_back(swim->map(mesh.vertices[v]));
        if (s == 0)
          for (std::size_t v = 0; v < shape.size(); ++v) shape[v] = swim->map(mesh.vertices[v]);
      }
      shape = arap->solve(targets, shape, arap_iterations);
    }
    double angle = 0.0, scale = 1.0;
    if (spec.preset == AnimationPreset::rotate) angle = 2.0 * std::numbers::pi * spec.turns * t;
    if (spec.preset == AnimationPreset::pulse)
      scale = 1.0 + spec.amplitude * std::sin(2.0 * std::numbers::pi * spec.count * t);
    out[s].reserve(shape.size());
    for (Vec2 p : shape) out[s].push_back(keyed.apply(similarity(p, pivot, angle, scale, {}), pivot, frame.scale, t));
  }
  if (spec.loop) out[slices - 1] = out[0];  // t = 1 is t = 0 of the next loop, bit for bit
  return out;
}

}  // namespace animpak
