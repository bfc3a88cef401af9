// The container's motion table (include/animpak/container_motion.hpp; docs/scene-format.md, "A
// container that moves"). Composed as an element's whole-body motion is (src/element/animate.cpp): the
// preset's turn or pulse about the pivot, then the keyed transform about the same pivot, so their turns
// and scales multiply and only the keyed translation moves the pivot.
#include "animpak/container_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "animpak/animation.hpp"
#include "animpak/error.hpp"

namespace animpak {
namespace {

const std::string kWhere = "container.animation";

std::string number(double v) {
  std::string s = std::to_string(v);
  while (s.size() > 1 && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

}  // namespace

Vec2 Similarity::inverse(Vec2 w) const {
  const double s2 = a * a + b * b, dx = w.x - ex, dy = w.y - ey;
  return {(a * dx + b * dy) / s2, (a * dy - b * dx) / s2};
}

double Similarity::scale() const { return std::hypot(a, b); }
double Similarity::angle() const { return std::atan2(b, a); }

ContainerMotion::ContainerMotion(const AnimationSpec& spec, Vec2 pivot, double frame_scale, bool loop) {
  if (!spec.handles.empty())
    throw InputError(kWhere +
                     ".handles: a container moves as a whole (turn, scale, move); handles would bend it, which "
                     "animpak does not pack; use keys or the rotate or pulse preset");
  if (spec.preset == AnimationPreset::swim)
    throw InputError(kWhere +
                     ".preset: swim bends its art, and a container moves as a whole; use rotate, pulse or keys");
  if (spec.preset == AnimationPreset::none && spec.keys.empty()) return;
  if (spec.preset == AnimationPreset::rotate && loop && spec.turns != std::round(spec.turns))
    throw InputError(kWhere + ".turns = " + number(spec.turns) +
                     ": a looping scene needs a whole number of turns, or t = 1 would jump back to t = 0");
  if (spec.preset == AnimationPreset::pulse && !(std::fabs(spec.amplitude) < 1.0))
    throw InputError(kWhere + ".amplitude = " + number(spec.amplitude) +
                     ": a pulse scales by 1 ± amplitude, so it must lie strictly between -1 and 1");

  std::optional<Spline> tx, ty, turn, scale;
  if (!spec.keys.empty()) {
    std::vector<double> t, x, y, r, s;
    for (std::size_t i = 0; i < spec.keys.size(); ++i) {
      const TransformKey& k = spec.keys[i];
      if (!(k.scale > 0.0) || !std::isfinite(k.scale))
        throw InputError(kWhere + ".keys[" + std::to_string(i) + "].scale = " + number(k.scale) +
                         ": expected a number > 0");
      t.push_back(k.t);
      x.push_back(k.translate.x);
      y.push_back(k.translate.y);
      r.push_back(k.rotate * std::numbers::pi / 180.0);
      s.push_back(k.scale);
    }
    try {
      tx.emplace(t, x, loop);
      ty.emplace(t, y, loop);
      turn.emplace(t, r, loop);
      scale.emplace(std::move(t), std::move(s), loop);
    } catch (const InputError& e) {
      throw InputError(kWhere + ".keys: " + e.what());
    }
  }

  const int n = kContainerMotionIntervals;
  table_.resize(n + 1);
  for (int i = 0; i <= n; ++i) {
    const double t = static_cast<double>(i) / n;
    double angle = 0.0, k = 1.0;
    Vec2 shift;
    if (spec.preset == AnimationPreset::rotate) angle = 2.0 * std::numbers::pi * spec.turns * t;
    if (spec.preset == AnimationPreset::pulse)
      k = 1.0 + spec.amplitude * std::sin(2.0 * std::numbers::pi * spec.count * t);
    if (tx) {
      angle += (*turn)(t);
      k *= (*scale)(t);
      shift = Vec2{(*tx)(t), (*ty)(t)} * frame_scale;
    }
    if (!(k > 0.0) || !std::isfinite(k))
      throw InputError(kWhere + ".keys: the scale dips to " + number(k) + " at t = " + number(t) +
                       "; add keys between the scale keys or make them closer in value");
    Similarity m{k * std::cos(angle), k * std::sin(angle), 0.0, 0.0};
    const Vec2 turned = m.linear(pivot);
    m.ex = pivot.x + shift.x - turned.x;
    m.ey = pivot.y + shift.y - turned.y;
    table_[i] = m;
  }
  if (loop) table_[n] = table_[0];  // t = 1 is t = 0 of the next loop, bit for bit
}

Similarity ContainerMotion::at(double t) const {
  if (table_.empty()) return {};
  const int n = kContainerMotionIntervals;
  const double u = std::clamp(t, 0.0, 1.0) * n;
  const int i = std::min(static_cast<int>(std::floor(u)), n - 1);
  const double w = u - i;
  const Similarity& p = table_[i];
  const Similarity& q = table_[i + 1];
  return {p.a + (q.a - p.a) * w, p.b + (q.b - p.b) * w, p.ex + (q.ex - p.ex) * w, p.ey + (q.ey - p.ey) * w};
}

double ContainerMotion::min_scale() const {
  double s = 1.0;
  for (std::size_t i = 0; i < table_.size(); ++i) s = i == 0 ? table_[i].scale() : std::min(s, table_[i].scale());
  return s;
}

double ContainerMotion::max_scale() const {
  double s = 1.0;
  for (std::size_t i = 0; i < table_.size(); ++i) s = i == 0 ? table_[i].scale() : std::max(s, table_[i].scale());
  return s;
}

double ContainerMotion::mean_scale() const {
  if (table_.empty()) return 1.0;
  double sum = 0.0;
  for (const Similarity& m : table_) sum += m.scale();
  return sum / static_cast<double>(table_.size());
}

}  // namespace animpak
