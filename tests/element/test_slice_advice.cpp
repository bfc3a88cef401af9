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
Outline square_outline() { return Outline{{{0.3, 0.7}, {0.7, 0.7}, {0.7, 0.3}, {0.3, 0.3}}, {}, {}}; }

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
  // A corner 0.28 from the pivot: a coordinate held flat over an interval of angle a misses the circle by
  // up to 0.28 (1 − cos(a / 2)), which is 1 % at a = 0.54 rad, about 12 intervals a turn. The curve does
  // better where no coordinate turns, so fewer may do; never more than twice that.
  CHECK(one.slices >= 5);
  CHECK(one.slices <= 26);
  CHECK(two.slices >= one.slices + (one.slices - 1) / 2);
  CHECK(two.slices <= 2 * one.slices + 1);
  // At 6 slices a turn is far off; at the advised count it holds.
  CHECK(one.error > slice_advice_tolerance);
  CHECK(slice_advice(square(), square_outline(), ArtFrame{}, rotate(1), one.slices).error <= slice_advice_tolerance);
  CHECK(slice_advice(square(), square_outline(), ArtFrame{}, rotate(2), two.slices).error <= slice_advice_tolerance);
}
