// Hand-made art and mesh checks shared by the element tests.
#pragma once

#include <string>
#include <vector>

#include "animpak/element.hpp"

namespace animpak::test {

/// How far inside Δs the offset outline may come: Clipper's round joins keep each chord within the arc
/// tolerance (1e-4) of the arc, except the last chord of a join, up to 1.5 steps long (2.25 × 1e-4).
inline constexpr double offset_tolerance = 2.5e-4;

/// One filled closed path per ring, in art coordinates (y down), nonzero rule.
inline ArtShape filled_art(const std::vector<std::vector<Vec2>>& rings, const std::string& source,
                           FillRule rule = FillRule::nonzero) {
  ArtShape art;
  art.source = source;
  ArtPath path;
  path.id = "path0";
  path.fill.enabled = true;
  path.fill_rule = rule;
  for (const auto& ring : rings) path.polylines.push_back({ring, true});
  art.paths.push_back(path);
  return art;
}

inline std::vector<Vec2> rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

inline ArtShape square_art() { return filled_art({rect(0, 0, 10, 10)}, "square.svg"); }
inline ArtShape l_art() { return filled_art({{{0, 0}, {4, 0}, {4, 6}, {10, 6}, {10, 10}, {0, 10}}}, "l.svg"); }
inline ArtShape bar_art() { return filled_art({rect(0, 0, 100, 5)}, "bar.svg"); }
/// A square frame: the hole is filled by element_outline (the element is solid).
inline ArtShape frame_art() {
  return filled_art({rect(0, 0, 10, 10), rect(3, 3, 7, 7)}, "frame.svg", FillRule::evenodd);
}
/// Two blobs farther apart (0.7 of the unit square) than the outline bridges: the smaller is dropped
/// with a note.
inline ArtShape two_blobs_art() { return filled_art({rect(0, 0, 10, 40), rect(40, 0, 43, 3)}, "blobs.svg"); }

/// The five animals of examples/shapes, by file name.
inline std::vector<std::string> animal_names() { return {"bird", "cat", "fox", "penguin", "snake"}; }
std::string shape_path(const std::string& name);

/// Everything a test needs about one element at given params.
struct Built {
  NormalizedArt art;
  Outline outline;
  SliceMesh mesh;
};
Built build(const ArtShape& art, const Params& params = {}, std::uint64_t seed = 1);

/// The default example's star (examples/default/star.svg): sharp points, a stroke, a detached eye.
ArtShape star_art();

/// Area of the art's painted region (fills and strokes, unit coordinates) and of the part of it outside
/// the slice's boundary polygon, computed with Clipper.
struct ArtCoverage {
  double art = 0.0;
  double outside = 0.0;
};
ArtCoverage art_outside_boundary(const Built& b);

/// Exact-enough simplicity test of a closed ring (no two non-adjacent edges meet).
bool ring_simple(const std::vector<Vec2>& ring);

}  // namespace animpak::test
