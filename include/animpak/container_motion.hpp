// An animated container (docs/scene-format.md, "A container that moves"): the container moves as a
// whole, turning, scaling and travelling about a pivot, so that at every t it is one similarity of its
// shape at rest. The paper packs a static container and names a moving one as future work (§8).
#pragma once

#include <vector>

#include "animpak/geometry.hpp"
#include "animpak/scene_spec.hpp"

namespace animpak {

/// A similarity of the plane, w = [a −b; b a] p + e: a turn by atan2(b, a) (clockwise on screen, y down)
/// and a uniform scale by hypot(a, b), then a move by e.
struct Similarity {
  double a = 1.0, b = 0.0, ex = 0.0, ey = 0.0;
  Vec2 apply(Vec2 p) const { return {a * p.x - b * p.y + ex, b * p.x + a * p.y + ey}; }
  /// Its inverse applied to w.
  Vec2 inverse(Vec2 w) const;
  double scale() const;
  double angle() const;  ///< radians, clockwise on screen
  /// The turn and scale alone, applied to a direction or offset.
  Vec2 linear(Vec2 d) const { return {a * d.x - b * d.y, b * d.x + a * d.y}; }
};

/// How many intervals the container's motion table has over t in [0, 1]. The table is the motion's
/// definition everywhere (the solver's kernels, the reference, the frames, the measures): at 1,024 a
/// turn a loop moves by 0.35° an interval, and a 100-frame loop reads 10 entries a frame.
inline constexpr int kContainerMotionIntervals = 1024;

/// The container's motion over t in [0, 1], in unit coordinates: at(t) takes the container at rest (the
/// unit-square outline and holes of Container) to where it is at t. The scene's `container.animation`
/// (a `rotate` or `pulse` preset, or transform keys, about its pivot, as an element's whole-body motion
/// is; animate.cpp) is sampled at kContainerMotionIntervals + 1 times in double and linearly interpolated
/// between them, entry by entry, so that the float table the solver reads is the same function. A
/// default-constructed motion does not move.
class ContainerMotion {
 public:
  ContainerMotion() = default;
  /// `pivot` and `frame_scale` in unit coordinates: the pivot (the container outline's area centroid
  /// unless the animation names one) and the art-to-unit scale the keys' translations are multiplied by.
  /// With `loop`, t = 1 is t = 0 exactly. InputError (naming `container.animation`) for handles, the swim
  /// preset, or a scale that is not positive.
  ContainerMotion(const AnimationSpec& spec, Vec2 pivot, double frame_scale, bool loop);

  bool moves() const { return !table_.empty(); }
  /// The similarity at t (clamped to [0, 1]); the identity when it does not move.
  Similarity at(double t) const;
  /// The table's entries, kContainerMotionIntervals + 1 of them, empty when it does not move.
  const std::vector<Similarity>& table() const { return table_; }
  /// The smallest and largest scale over the loop (1 and 1 when it does not move).
  double min_scale() const;
  double max_scale() const;
  /// Its mean scale over the loop's entries (1 when it does not move).
  double mean_scale() const;

 private:
  std::vector<Similarity> table_;
};

}  // namespace animpak
