// What the frame writers share (writers.cpp: PNG and SVG frames; animation_keys.cpp: the animated formats'
// keys; animation_writers.cpp: Lottie and animated SVG). Private to the render library.
#pragma once

#include <cmath>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "animpak/render.hpp"
#include "animpak/xml_text.hpp"  // xml_escaped, for the ids and names the writers put in SVG

namespace animpak::frame_writers {

/// "#rrggbb" of a colour's channels (its alpha is written apart).
std::string hex(Rgba c);
/// One id per element, its name, unique among the SVG's ids ("container", "background" taken).
std::vector<std::string> element_ids(const World& world);

/// The paint attributes of one art path in an SVG, starting with a space: fill, its opacity and rule, the
/// stroke (`stroke_width` wide, round joins and caps as draw_art strokes) and paint order.
std::string svg_paint(const ArtPath& path, const std::string& stroke_width);

/// Key times are kept to a ten-thousandth of a frame, and keys closer than that are one key.
inline constexpr int key_decimals = 4;

/// How a player moves a path between two keys: from the first key's points towards the next's along the
/// straight line between them, the share e(s) of the way at the share s of the interval, with
/// e(s) = 3(1−s)²s·y1 + 3(1−s)s²·y2 + s³ (a cubic Bézier timing curve with control points (1/3, y1) and
/// (2/3, y2), Lottie's key easing and SMIL's keySplines alike). (1/3, 2/3) is e(s) = s: linear.
struct Ease {
  double y1 = 1.0 / 3.0, y2 = 2.0 / 3.0;
  bool linear = true;
  double at(double s) const {
    return linear ? s : 3 * (1 - s) * (1 - s) * s * y1 + 3 * (1 - s) * s * s * y2 + s * s * s;
  }
};

/// A similarity, where an element's local frame lies in the world at one key: a local point q is at
/// position + scale · R(angle) q, R the rotation by `angle` radians ([cos −sin; sin cos] in the world's
/// axes, which are the pictures' axes scaled: clockwise on screen, as Lottie's `r` and SVG's rotate()).
struct Placement {
  Vec2 position;
  double angle = 0.0, scale = 1.0;
  Vec2 to_world(Vec2 q) const {
    const double c = std::cos(angle) * scale, s = std::sin(angle) * scale;
    return {position.x + c * q.x - s * q.y, position.y + s * q.x + c * q.y};
  }
  Vec2 to_local(Vec2 p) const {
    const double c = std::cos(angle) / scale, s = std::sin(angle) / scale;
    const Vec2 d = p - position;
    return {c * d.x + s * d.y, -s * d.x + c * d.y};
  }
};

/// One polyline drawn as cubic Bézier segments: vertex k at points[k], with the control point before it
/// (`before[k]`, ending the segment from vertex k − 1) and the one after it (`after[k]`, starting the
/// segment to vertex k + 1), absolute, each equal to its vertex on a straight side; a closed line's last
/// segment runs from its last vertex back to vertex 0 (docs/animation-formats.md, "Curves").
struct BezierLine {
  std::vector<Vec2> points, before, after;
  bool closed = true;
};

/// One polyline at every key of a path (`keys[k]`, the same point count in each) as cubic Bézier segments
/// with the same knots in every key, so that a player's straight move of vertices and control points from
/// key to key keeps the curves within `tolerance` of the polyline's points as it moves them: each knot one
/// of the polyline's points, every turn of more than 45 degrees one, and each segment, at every key, a
/// straight side or the least-squares cubic through the points between, which lies within `tolerance` of
/// each of them and of each edge's middle at parameters common to the keys. A line of fewer than 3 points,
/// or `tolerance` 0, comes back as its polyline (every control point on its vertex).
std::vector<BezierLine> fit_beziers(const std::vector<std::vector<Vec2>>& keys, bool closed, double tolerance);

/// The keys of one art path: its polylines' points at `frames`, increasing, in frames of the document
/// (frame i is frames/frame_i.png), and the easing of each interval between two keys (ease[k] leads from
/// frames[k] to frames[k + 1]). One key: the path does not change shape in its frame. With `placements`
/// (at `place_frames`, eased by `place_ease`, each a turn and move with scale 1), the path has a frame of
/// its own within its element's, and its points are in it (docs/animation-formats.md, "The element's
/// frame").
struct PathKeys {
  std::vector<double> frames;
  std::vector<std::vector<std::vector<Vec2>>> lines;
  std::vector<Ease> ease;
  /// The polylines as cubic Béziers at each key (curves[k][q], fit_beziers), in the same coordinates as
  /// `lines`; empty: the writers write the polylines themselves.
  std::vector<std::vector<BezierLine>> curves;
  std::vector<double> place_frames;
  std::vector<Placement> placements;
  std::vector<Ease> place_ease;
};

/// The keys of one element's animation (docs/animation-formats.md, "The element's frame"). With `frames`
/// empty, the paths' points are world points (held keys, a still picture). Otherwise the element moves as
/// a whole through `placements` at `frames` (each interval eased by `ease`, as PathKeys), and its paths'
/// points are local to that frame: a path that moves with it has one key, one that changes shape in it is
/// keyed where that change needs it. The stroke widths are the art's times `stroke_scales`, at
/// `stroke_frames`, eased by `stroke_ease`, in the local frame (so the placement's scale scales them too).
struct ElementKeys {
  std::vector<double> frames;
  std::vector<Placement> placements;
  std::vector<Ease> ease;
  std::vector<PathKeys> paths;
  std::vector<double> stroke_frames, stroke_scales;
  std::vector<Ease> stroke_ease;
};

/// The similarity a player shows at `frame` from placement keys at `frames`: each of position, angle and
/// scale moved from one key towards the next by the key's easing (as Lottie and SMIL interpolate a
/// transform's parts). The identity without keys.
Placement placement_at(const std::vector<double>& frames, const std::vector<Placement>& placements,
                       const std::vector<Ease>& ease, double frame);
/// The element's placement at `frame` (placement_at of its keys).
inline Placement placement_at(const ElementKeys& keys, double frame) {
  return placement_at(keys.frames, keys.placements, keys.ease, frame);
}

/// One key of every path at frame 0, no stroke scaling: a still picture (the container's art).
ElementKeys still_keys(const ArtPoints& points);

/// Element `element`'s keys in an `out.count`-frame document, from frame 0 to frame N (N − 1 and a last
/// one holding it, when the world does not loop): linear, the element's placement at its own slices and
/// where its motion between them needs it, its paths in its frame once or where their change of shape
/// needs it (within the key tolerance); held, the N frames' world points. One frame: one key.
ElementKeys element_keys(const World& world, const SimState& state, int element, const FrameOutput& out);
/// The keys of drawn element `drawn` (drawn_count): element_keys of its element, reflected for a mirror image.
ElementKeys drawn_keys(const World& world, const SimState& state, int drawn, const FrameOutput& out);

/// animation.json: one Lottie shape layer per element (docs/animation-formats.md).
/// `file` is named in its errors.
void write_lottie(const World& world, const SimState& state, const FrameOutput& out,
                  const std::vector<std::string>& ids, std::ostream& json, const std::filesystem::path& file);
/// animation.lottie: the same document in a dotLottie zip (dotlottie.cpp).
void write_dotlottie(const World& world, const SimState& state, const FrameOutput& out,
                     const std::vector<std::string>& ids, const std::filesystem::path& file);
/// animation.svg: the SVG frames' groups and ids, each path's d (and stroke width) animated with SMIL.
void write_svg_animation(const World& world, const SimState& state, const FrameOutput& out,
                         const std::vector<std::string>& ids, const std::filesystem::path& file);

}  // namespace animpak::frame_writers
