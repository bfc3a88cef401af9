// Drawing: anti-aliased vector pictures with Cairo, written as image files with OpenImageIO.
// This library sits beside the solver core, never under it (design.md): nothing in src/solver
// includes this header.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "animpak/element.hpp"
#include "animpak/io.hpp"
#include "animpak/scene.hpp"

namespace animpak {

/// Replayed art: point k of polyline q of path p, as ArtShape::paths[p].polylines[q].points[k].
using ArtPoints = std::vector<std::vector<std::vector<Vec2>>>;

/// An RGBA raster with a world-to-pixel mapping: `world` is fitted into the picture with a margin,
/// keeping its aspect ratio; y points down in both.
class Picture {
 public:
  Picture(int width, int height, Box world, Rgba background = {1, 1, 1, 1}, double margin_px = 8.0);
  ~Picture();
  Picture(Picture&&) noexcept;
  Picture& operator=(Picture&&) noexcept;

  int width() const;
  int height() const;
  Vec2 to_pixel(Vec2 world) const;

  /// Paints the art's paths in drawing order, each fill and stroke in its paint order.
  /// `points` replaces the art's own coordinates (e.g. replayed on a deformed slice).
  /// `stroke_scale` multiplies the art's stroke widths (an element drawn at a fraction of its size).
  void draw_art(const ArtShape& art, const ArtPoints& points, double opacity = 1.0, double stroke_scale = 1.0);
  /// Line segments between positions[e[0]] and positions[e[1]]; width in pixels.
  void draw_edges(const std::vector<Vec2>& positions, const std::vector<Edge>& edges, Rgba color,
                  double width_px, bool dashed = false);
  /// A closed polygon outline.
  void draw_ring(const std::vector<Vec2>& ring, Rgba color, double width_px);
  void draw_dots(const std::vector<Vec2>& positions, Rgba color, double radius_px);
  /// An open polyline; width in pixels.
  void draw_polyline(const std::vector<Vec2>& points, Rgba color, double width_px);
  /// One line of text in Cairo's default sans face. `align` places the anchor on the text's box:
  /// (0, 0) its top-left, (0.5, 0.5) its centre, (1, 1) its bottom-right.
  void draw_text(Vec2 anchor, const std::string& text, double size_px, Rgba color, Vec2 align = {0.0, 0.0});
  /// Straight (non-premultiplied) 8-bit RGBA, row-major, top row first.
  std::vector<unsigned char> rgba8() const;
  /// Writes any format OpenImageIO knows by extension (.png, .exr, .tif, …).
  void write(const std::filesystem::path& file) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The pictures `animpak inspect --out` writes for one element, each `size` pixels high:
/// <name>-slice.png (edge classes coloured, like paper Fig. 2c), <name>-art.png (the art replayed
/// over the slice), <name>-strip.png (slices across the animation). Returns the files written.
std::vector<std::filesystem::path> write_inspect_pictures(const SpacetimeElement& element,
                                                          const std::filesystem::path& dir, int size);

/// Slice vertex positions of element instance `element` at frame time tf (paper §6): linear
/// interpolation between the two consecutive slices whose current t values bracket tf.
std::vector<Vec2> element_at(const World& world, const SimState& state, int element, double tf);

/// How large element `element` is drawn for these slice positions relative to its library size (the
/// square root of the boundary's area ratio): stroke widths follow it.
double element_scale(const World& world, int element, const std::vector<Vec2>& positions);

/// Pixel width of a picture `height` pixels tall over `box`, keeping its aspect (at least 1).
int raster_width(const Box& box, int height);

/// The frame times of a `count`-frame animation: i / count when looping (frame `count` would repeat
/// frame 0), i / (count − 1) otherwise.
std::vector<double> frame_times(int count, bool loop);

struct FrameStyle {
  int size = 512;                  ///< picture height in pixels; the width follows the container's aspect
  Rgba background{1, 1, 1, 1};
  bool draw_container = true;      ///< the outline and holes, thin grey
};

/// One frame: every element's art replayed on its interpolated slice, in element order.
Picture draw_frame(const World& world, const SimState& state, double tf, const FrameStyle& style);

/// Quality of one frame, measured on the elements' slice boundaries (their offset outlines) and on
/// the rasterized art.
struct FrameMetrics {
  double t = 0.0;
  double coverage = 0.0;   ///< share of the container's area covered by elements' art
  double min_gap = 0.0;    ///< smallest distance between two elements' offset outlines (0: channels touch)
  double mean_gap = 0.0;   ///< mean over elements of that distance to the nearest other element
  int overlapping_pairs = 0;  ///< pairs of elements whose art shares pixels
};
FrameMetrics measure_frame(const World& world, const SimState& state, double tf);

enum class FrameFormat { png, gif, mp4, svg };

struct FrameOutput {
  std::filesystem::path dir;
  int count = 100;
  double fps = 25.0;
  std::vector<FrameFormat> formats{FrameFormat::png, FrameFormat::gif};
  FrameStyle style;
};

/// Writes `count` frames one at a time (never all in memory): frames/frame_NNNN.png (and .svg), then
/// animation.gif / animation.mp4 through ffmpeg. Returns the metrics of every frame.
std::vector<FrameMetrics> write_frames(const World& world, const SimState& state, const FrameOutput& out);

}  // namespace animpak
