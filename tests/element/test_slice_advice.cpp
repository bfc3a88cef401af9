// slice_advice (include/animpak/animation.hpp): how many slices a scripted motion needs for the curve
// between slices to stay within 1 % of the element's size of the script.
#include <catch2/catch.hpp>

#include <cmath>

#include "animpak/animation.hpp"
#include "element/slice_fixtures.hpp"

using namespace animpak;
using animpak::testing::grid_slice;

namespace {

// A 5 × 5 grid filling [0.3, 0.7]² with its square outline: corners 0.28 from the centre.
SliceMesh square() { return grid_slice(5, 5, 0.1, {0.3, 0.3}); }
Outline square_outline() { return Outline{{{0.3, 0.7}, {0.7, 0.7}, {0.7, 0.3}, {0.3, 0.3}}, {}, {}, {}, 0.0}; }

AnimationSpec rotate(double turns) {
  AnimationSpec spec;
  spec.preset = AnimationPreset::rotate;
  spec.turns = turns;
  return spec;
}

}  // namespace

TEST_CASE("slice_advice: a still element needs no particular count") {
  const SliceAdvice a = slice_advice(square(), square_outline(), ArtFrame{}, AnimationSpec{}, 12);
  CHECK(a.slices == 0);
  CHECK(a.error == 0.0);
}

TEST_CASE("slice_advice: a turn needs about as many slices as its corners' chord allows, two turns twice as many") {
  const SliceAdvice one = slice_advice(square(), square_outline(), ArtFrame{}, rotate(1), 6);
  const SliceAdvice two = slice_advice(square(), square_outline(), ArtFrame{}, rotate(2), 6);
  INFO("one turn: " << one.slices << " slices, two: " << two.slices);
  // A corner 0.28 from the pivot. The periodic spline through n equally spaced points of a circle misses it
  // by about r·(2π/n)⁴/... : 1 % of the size takes 5 slices a turn (4 intervals), where the monotone cubic,
  // which holds a turning coordinate flat, needs about 12 intervals (0.28 (1 − cos(a / 2)) = 1 % at a =
  // 0.54 rad), and the chord more.
  CHECK(one.slices >= 4);
  CHECK(one.slices <= 8);
  CHECK(two.slices >= one.slices + (one.slices - 1) / 2);
  CHECK(two.slices <= 2 * one.slices + 1);
  // At 4 slices a turn is far off; at the advised count it holds.
  const SliceAdvice few = slice_advice(square(), square_outline(), ArtFrame{}, rotate(1), 4);
  CHECK(few.error > slice_advice_tolerance);
  CHECK(slice_advice(square(), square_outline(), ArtFrame{}, rotate(1), one.slices).error <= slice_advice_tolerance);
  CHECK(slice_advice(square(), square_outline(), ArtFrame{}, rotate(2), two.slices).error <= slice_advice_tolerance);
  // The monotone cubic (motion_curve 1) needs more for the same turn.
  const SliceAdvice monotone = slice_advice(square(), square_outline(), ArtFrame{}, rotate(1), 6, 1);
  INFO("monotone: " << monotone.slices << " slices");
  CHECK(monotone.slices > one.slices + 3);
  CHECK(monotone.slices <= 26);
  CHECK(monotone.error > slice_advice_tolerance);
}
