// Drawing: anti-aliased vector pictures with Cairo, written as image files with OpenImageIO.
// This library sits beside the solver core, never under it (docs/architecture.md, "Data flow"): nothing in src/solver
// includes this header.
#pragma once

#include <algorithm>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
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
/// Where Picture puts a world box: pixel = world * scale + offset, the box centred with a margin and its
/// aspect kept.
struct PixelFit {
  double scale = 1.0;
  Vec2 offset;
  Vec2 to_pixel(Vec2 world) const { return world * scale + offset; }
};
PixelFit fit_to_picture(int width, int height, Box world, double margin_px);

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
  /// `stroke_scale` multiplies the art's stroke widths (an element drawn at a fraction of its size); strokes
  /// thinner than `min_stroke_px` pixels are drawn that wide, so hairlines stay visible in the frames.
  void draw_art(const ArtShape& art, const ArtPoints& points, double opacity = 1.0, double stroke_scale = 1.0,
                double min_stroke_px = 0.5);
  /// Line segments between positions[e[0]] and positions[e[1]]; width in pixels.
  void draw_edges(const std::vector<Vec2>& positions, const std::vector<Edge>& edges, Rgba color, double width_px,
                  bool dashed = false);
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

/// The art exactly as imported, at its document's viewport (ArtShape::viewport; the painted bounds when it
/// has none) on a transparent background, the viewport's longer side `size` pixels, strokes at their own
/// width however thin: what a browser draws at that size, for `animpak check --png`.
Picture draw_art_preview(const ArtShape& art, int size);

/// An inline `<svg>` of the art at its own coordinates, fitted into a `size`-pixel square with its aspect
/// kept: its paths in drawing order with their paint, as the SVG frames write them (`animpak report`'s
/// table of elements). Our own drawing of the imported art, never the file's text.
std::string art_svg(const ArtShape& art, int size);

/// How large element `element` is drawn for these slice positions relative to its library size (the
/// square root of the boundary's area ratio): stroke widths follow it.
double element_scale(const World& world, int element, const std::vector<Vec2>& positions);

/// Pixel width of a picture `height` pixels tall over `box`, keeping its aspect (at least 1).
int raster_width(const Box& box, int height);

/// The frame times of a `count`-frame animation: i / count when looping (frame `count` would repeat
/// frame 0), i / (count − 1) otherwise.
std::vector<double> frame_times(int count, bool loop);

/// How the frames draw the container: its outline and holes as a thin grey line over the elements, its own
/// art painted under them (as its file paints it), or not at all.
enum class ContainerDrawing { outline, fill, none };

struct FrameStyle {
  int size = 512;  ///< picture height in pixels; the width follows the container's aspect
  /// Alpha 0 draws no background: transparent PNG pixels, no Lottie background layer, no SVG backdrop.
  Rgba background{1, 1, 1, 1};
  ContainerDrawing container = ContainerDrawing::outline;
};

/// The art's own coordinates, as draw_art takes them: the art drawn where it is.
ArtPoints own_points(const ArtShape& art);

/// One element's art at one frame time: replayed on its interpolated slice (element_at, replay_art), and
/// the factor its stroke widths are drawn at (element_scale).
struct ElementArt {
  ArtPoints points;
  double stroke_scale = 1.0;
};

/// Element `element`'s art replayed on these slice vertex positions, and its stroke scale there.
ElementArt element_art(const World& world, int element, const std::vector<Vec2>& positions);

/// The mean of the art's drawn points: where the motion measures (measure_motion) and the trajectory
/// figure (`animpak trajectory`) place an element. The origin for art without points.
Vec2 art_centroid(const ElementArt& art);

/// Element `element`'s art centroid at each of `times`: its path through spacetime, on the same curve
/// between slices the frames are drawn from (element_at, element_art).
std::vector<Vec2> element_path(const World& world, const SimState& state, int element,
                               const std::vector<double>& times);

/// Every element's art at frame time tf, in element order (drawn_count entries: the reflections after
/// the elements): the one geometry every frame writer (PNG, SVG frames, Lottie, animated SVG) and the
/// frame metrics use.
std::vector<ElementArt> frame_art(const World& world, const SimState& state, double tf);
/// The same with every element's tangents (frame_tangents) computed once, for many times of one state.
std::vector<ElementArt> frame_art(const World& world, const SimState& state, double tf,
                                  const std::vector<std::vector<Vec2>>& tangents);
/// element_tangents of every element, in element order.
std::vector<std::vector<Vec2>> frame_tangents(const World& world, const SimState& state);

/// The picture of one frame's art, elements in order, then the container when the style asks for it.
Picture draw_frame(const World& world, const std::vector<ElementArt>& art, const FrameStyle& style);
/// One frame: every element's art replayed on its interpolated slice, in element order.
Picture draw_frame(const World& world, const SimState& state, double tf, const FrameStyle& style);

/// The spherical contact function is sampled every contact_step element radii, at most contact_samples times
/// (docs/quality.md, "Evenness").
inline constexpr double contact_step = 0.05;
inline constexpr int contact_samples = 400;

/// A share of art (outside the container, or overlapping another element) counts when it exceeds
/// this: 0.2 % of the art's area (docs/quality.md).
inline constexpr double quality_share_threshold = 0.002;

struct ElementShare {
  int element = -1;
  double share = 0.0;
};

struct PairShare {
  int a = -1, b = -1;  ///< element ids, a < b
  double share = 0.0;
};

/// Quality of one frame, measured exactly on the elements' painted art (polygon booleans, never a
/// raster) against the container; every distance and area in container unit coordinates.
/// docs/quality.md says how each number is computed.
struct FrameMetrics {
  double t = 0.0;
  double coverage = 0.0;              ///< area((∪ art) ∩ container) / area(container)
  double min_gap = 0.0;               ///< smallest art-to-art distance over all pairs (0: some art touches or overlaps)
  double mean_gap = 0.0;              ///< mean over elements of the distance from its art to the nearest other art
  double channel_cv = 0.0;            ///< coefficient of variation of the channel widths sampled along every outline
  std::vector<double> area;           ///< per element: the area of its art
  std::vector<double> outside_share;  ///< per element: area(art − container) / area(art)
  std::vector<PairShare> overlaps;    ///< every pair whose art overlaps: area / the smaller art's area
  /// Evenness (docs/quality.md, "Evenness"). ρ: the median over elements of √(art area / π), 0 without art.
  double element_radius = 0.0;
  /// Median art-to-wall gap of the elements within ρ of the wall over the median nearest art-to-art gap;
  /// none with fewer than two elements, no element near the wall or a median art-to-art gap of 0.
  std::optional<double> wall_ratio;
  double empty_disc_radius = 0.0;  ///< the largest disc in the container that meets no art
  /// The spherical contact function H(r) at r = k · contact_step · ρ, k = 0, 1, … up to its first 0
  /// (at most contact_samples values); empty without art.
  std::vector<double> contact;

  /// The largest empty disc's radius as a share of ρ; none without art.
  std::optional<double> empty_disc() const {
    if (!(element_radius > 0.0)) return std::nullopt;
    return empty_disc_radius / element_radius;
  }

  /// Elements whose outside share exceeds quality_share_threshold.
  std::vector<ElementShare> elements_outside() const {
    std::vector<ElementShare> out;
    for (std::size_t i = 0; i < outside_share.size(); ++i)
      if (outside_share[i] > quality_share_threshold) out.push_back({int(i), outside_share[i]});
    return out;
  }
  /// Pairs whose overlap share exceeds quality_share_threshold.
  std::vector<PairShare> overlapping() const {
    std::vector<PairShare> out;
    for (const PairShare& p : overlaps)
      if (p.share > quality_share_threshold) out.push_back(p);
    return out;
  }
  /// The element with the largest outside share (element −1 when there is none), counted or not.
  ElementShare worst_outside() const {
    ElementShare worst;
    for (std::size_t i = 0; i < outside_share.size(); ++i)
      if (outside_share[i] > worst.share) worst = {int(i), outside_share[i]};
    return worst;
  }
  /// The pair with the largest overlap share (a = b = −1 when no art overlaps), counted or not.
  PairShare worst_overlap() const {
    PairShare worst;
    for (const PairShare& p : overlaps)
      if (p.share > worst.share) worst = p;
    return worst;
  }
};

/// A planar region as rings under a fill rule, in container unit coordinates.
struct Region {
  std::vector<std::vector<Vec2>> rings;
  FillRule rule = FillRule::nonzero;
};

/// What an art drawn with `points` paints (painted_region of every path, united), with the art's
/// stroke widths times `stroke_scale`, exactly as draw_art and the SVG frames draw it.
Region art_region(const ArtShape& art, const ArtPoints& points, double stroke_scale);

/// What measure_regions measures: everything, or everything but the evenness measures, whose raster and
/// disc search cost about as much as the rest (the points between slices skip them, docs/quality.md).
enum class Measures { all, no_evenness };

/// The metrics of one arrangement: each element's art region and the container region (t is left 0).
FrameMetrics measure_regions(const std::vector<Region>& elements, const Region& container,
                             Measures what = Measures::all);

/// The spherical contact function of the negative space: for each r, the share of the container's area
/// farther than r from all art and from the container's boundary (docs/quality.md, "Evenness"); `radii`
/// ascending.
std::vector<double> contact_function(const std::vector<Region>& elements, const Region& container,
                                     const std::vector<double>& radii);

/// Draws every frame's contact function H(r) (r in element radii) and their mean into a PNG.
void write_contact_plot(const std::vector<FrameMetrics>& frames, const std::filesystem::path& file);

/// Per sample of the contact function, its mean over the times (a time whose H reached 0 sooner counts 0 there).
inline std::vector<double> mean_contact(const std::vector<FrameMetrics>& metrics) {
  std::vector<double> mean;
  for (const FrameMetrics& m : metrics) {
    mean.resize(std::max(mean.size(), m.contact.size()), 0.0);
    for (std::size_t k = 0; k < m.contact.size(); ++k) mean[k] += m.contact[k] / double(metrics.size());
  }
  return mean;
}

/// The container as a region at time t: the outline minus the holes (even–odd), carried by
/// container.motion.at(t) when the container moves; the shown (whole) container of a mirrored scene.
Region container_region(const Container& container, double t);

/// The metrics at frame time tf: every element's art replayed on its interpolated slice as the frames
/// draw it (element_at, replay_art, element_scale), measured with measure_regions against the container
/// where it is at tf (container_region).
FrameMetrics measure_frame(const World& world, const SimState& state, double tf, Measures what = Measures::all);
/// The same for art frame_art has replayed at tf.
FrameMetrics measure_frame(const World& world, const std::vector<ElementArt>& art, double tf,
                           Measures what = Measures::all);

/// Times audited inside every slice interval: eight, evenly spaced.
inline constexpr int between_slice_points = 8;

/// Eight evenly spaced points of every slice interval, t = (s + q / 9) / (n_s − 1) for s = 0 … n_s − 2
/// and q = 1 … 8, in increasing order: the times away from every slice, where elements on the curve
/// between slices can overlap unseen by the slices (paper §6). The middle alone misses a tip that passes
/// a neighbour between it and a slice (docs/quality.md).
std::vector<double> between_slice_times(int slices);

/// How the elements move and how their sizes follow their script (docs/quality.md, "Motion").
struct MotionMetrics {
  /// The art centroids' frame-to-frame acceleration (second difference, cyclic when the world loops), in
  /// container units per frame², over every element and frame: its median and 99th percentile.
  double acceleration_median = 0.0, acceleration_p99 = 0.0;
  /// The mean acceleration at the frames next to one of the element's slice times over the mean at the
  /// others: 1 when the slices do not show; straight lines between slices make it enormous. NaN when
  /// every frame is next to a slice (as many slices as frames), or none is.
  double slice_ratio = std::numeric_limits<double>::quiet_NaN();
  /// Per element, at its slices: the largest over the smallest of its boundary's area over its scripted
  /// area there (the rest copy's, shrunk as placed): its growth g squared, deformation included.
  std::vector<double> size_over_script;
  /// Per frame: the largest acceleration of any element there (container units per frame²); NaN where it
  /// has no second difference (the first and last frames when the world does not loop). Over
  /// acceleration_median it is the frame's own kink, which shows where the jolts are (`animpak report`).
  std::vector<double> frame_peak;
  /// Per element, how far it moves over the loop (docs/quality.md, "Motion"): the largest distance of its
  /// art's centroid from its mean place over the frames (how far it steps aside to let a traveller by, or
  /// how far a traveller travels), and the length of the centroid's path per loop, frame to frame, in
  /// container units; in the container's frame at rest when it moves (docs/quality.md, "A container that
  /// moves"). `guided` says which elements are guided: the motion line sums up the others.
  std::vector<double> detour, path_length;
  std::vector<bool> guided;
  /// Per element, its start's smallest scale over its largest (ElementInstance::dip): below 1 where its
  /// script gives way to a traveller.
  std::vector<double> dip;
  /// 99th percentile over median of the acceleration (infinite when the median is 0).
  double kink() const {
    return acceleration_median > 0.0 ? acceleration_p99 / acceleration_median : std::numeric_limits<double>::infinity();
  }
};

/// The metrics of the rendered frames and of the times between slices.
struct PackingQuality {
  std::vector<FrameMetrics> frames;
  std::vector<FrameMetrics> between_slices;
  MotionMetrics motion;
};

/// Across a looping scene's seam an element continues as the element it loops into (§5.2's loop pairs: two
/// guided elements that swap places): `into` is that element, `from` the one that loops into this one;
/// both the element itself when it loops into itself.
struct LoopNeighbours {
  int from, into;
};
/// Every element's LoopNeighbours, in element order, from one pass over the loop pairs.
std::vector<LoopNeighbours> loop_neighbours(const World& world);

/// MotionMetrics from each element's art centroid at each frame (centroids[element][frame]) at `times`,
/// and the packed state's slices.
MotionMetrics measure_motion(const World& world, const SimState& state, const std::vector<std::vector<Vec2>>& centroids,
                             const std::vector<double>& times);

/// lottie: animation.json, a Lottie (Bodymovin) document; dotlottie: animation.lottie, the same document in
/// a dotLottie zip; svg_anim: animation.svg, paths animated with SMIL (docs/animation-formats.md).
enum class FrameFormat { png, gif, mp4, svg, lottie, dotlottie, svg_anim };

/// How the animated vector formats move a path. linear: keys at the element's own slice times, straight
/// in between, which is the motion itself (paper §6); hold: keys at the frames, each held until the next.
enum class Interpolation { linear, hold };

struct FrameOutput {
  std::filesystem::path dir;
  int count = 100;
  double fps = 25.0;
  std::vector<FrameFormat> formats{FrameFormat::png, FrameFormat::gif};
  FrameStyle style;
  int precision = 2;  ///< decimals of a pixel (of a `style.size` picture) kept in Lottie and animated SVG coordinates
  /// Lottie and animated SVG paths are cubic Béziers within this many pixels (of a `style.size` picture) of
  /// the art's polylines, at most 0.5, taken from the keys' three quarters of a pixel
  /// (docs/animation-formats.md, "Curves"); 0 writes the polylines, point by point.
  double curve_tolerance = 0.05;
  Interpolation interpolation = Interpolation::linear;
  /// Called as the render goes: `stage` is "frame" once per frame (done = frames written so far, total =
  /// count), then the name of each file or measure as it starts ("animation.json", "between slices",
  /// "animation.gif", ...; done 0, total 1). Empty: no calls.
  std::function<void(const std::string& stage, int done, int total)> on_progress;
};

/// The file name of an animated format (animation.json, animation.lottie, animation.svg), empty for the
/// others.
std::string animation_file_name(FrameFormat format);

/// Writes `count` frames one at a time (never all in memory): frames/frame_NNNN.png (and .svg), then
/// animation.gif / animation.mp4 through ffmpeg, and animation.json / animation.svg assembled from a
/// scratch file of the frames' coordinates. Returns the metrics of every frame and of every time
/// between slices.
PackingQuality write_frames(const World& world, const SimState& state, const FrameOutput& out);

}  // namespace animpak
