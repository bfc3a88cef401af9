// Scripted animation of a slice (paper §3.2): keyframed transforms interpolated by splines, keyframed
// vertex handles followed by as-rigid-as-possible deformation, and the named presets.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "animpak/element.hpp"
#include "animpak/scene_spec.hpp"

namespace animpak {

/// Cubic interpolation through (t_i, v_i) keys, t strictly increasing in [0, 1]. Periodic when
/// `loop` (period 1, C¹ across t = 1 ≡ 0; the value at t = 1 must equal the value at t = 0, or the
/// key at t = 1 may be left out); clamped to the end keys otherwise. One key: constant.
class Spline {
 public:
  Spline(std::vector<double> times, std::vector<double> values, bool loop);
  double operator()(double t) const;

 private:
  std::vector<double> times_, values_;
  bool loop_;
  std::vector<double> moments_;  ///< second derivatives at the keys, solved once in the constructor
};

/// ARAP (Sorkine & Alexa 2007) on one slice mesh, over its triangulation edges. The system matrix is
/// factored once (Eigen sparse Cholesky) for a fixed set of handle vertices; each solve takes the handle
/// positions and returns every vertex position.
class ArapSolver {
 public:
  ArapSolver(const SliceMesh& mesh, std::vector<int> handle_vertices);
  ~ArapSolver();
  ArapSolver(ArapSolver&&) noexcept;
  ArapSolver& operator=(ArapSolver&&) noexcept;

  /// `handles[i]` is the target of handle_vertices[i]; `initial` seeds the local/global iterations.
  std::vector<Vec2> solve(const std::vector<Vec2>& handles, const std::vector<Vec2>& initial,
                          int iterations = 10) const;
  /// The ARAP energy of `positions` relative to the rest mesh (with the best rotations).
  double energy(const std::vector<Vec2>& positions) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Vertex positions of every slice, s = 0..slices-1 at t = s/(slices-1), for the animation in `spec`.
/// `frame` maps the art coordinates used by handles, pivots and translations onto the unit square.
std::vector<std::vector<Vec2>> animate_slices(const SliceMesh& mesh, const Outline& outline, const ArtFrame& frame,
                                              const AnimationSpec& spec, int slices);

/// How far the curve between slices may stray from a scripted motion, as a share of the element's size
/// (its art fits the unit square): 1 %, a pixel of a 100-pixel element.
inline constexpr double slice_advice_tolerance = 0.01;

/// How many slices the scripted motion in `spec` needs (docs/parameters.md, "How many slices a motion
/// needs"): `slices`, about the fewest with which the curve between slices keeps every vertex within
/// slice_advice_tolerance of the script (0: it barely moves, any count will do); `error`, the largest
/// distance at `slices_now` slices, in the same units; `mode` is the curve (`motion_curve`, CurveMode).
struct SliceAdvice {
  int slices = 0;
  double error = 0.0;
};
SliceAdvice slice_advice(const SliceMesh& mesh, const Outline& outline, const ArtFrame& frame,
                         const AnimationSpec& spec, int slices_now, int mode = 2);

/// The warning for an element whose scripted motion needs more slices than it was built with (its
/// slices_needed above its slice_count), naming it, the error and the advised count; empty otherwise.
std::string slice_advice_warning(const SpacetimeElement& element);

/// The whole §3 pipeline for one library element: normalize, offset, sample, triangulate, bind,
/// animate, extrude. Deterministic for a seed.
SpacetimeElement build_element(const std::string& name, const ArtShape& art, const AnimationSpec& spec,
                               const Params& params, std::uint64_t seed);

}  // namespace animpak
