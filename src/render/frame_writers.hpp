// What the frame writers share (writers.cpp: PNG and SVG frames; animation_writers.cpp: Lottie and animated
// SVG). Private to the render library.
#pragma once

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "animpak/render.hpp"

namespace animpak::frame_writers {

/// "#rrggbb" of a colour's channels (its alpha is written apart).
std::string hex(Rgba c);
std::string xml_escaped(const std::string& text);
/// One id per element, its name, unique among the SVG's ids ("container", "background" taken).
std::vector<std::string> element_ids(const World& world);

/// The replayed coordinates of every frame, appended one frame at a time to a scratch file and read back
/// one polyline at a time. The frames come element by element, while the animated formats write each
/// path's keyframes together: the file turns one order into the other holding one frame's numbers at
/// most, whatever the frame count (docs/animation-formats.md, "Memory").
class GeometryLog {
 public:
  GeometryLog(const World& world, std::filesystem::path file);
  ~GeometryLog();
  GeometryLog(const GeometryLog&) = delete;
  GeometryLog& operator=(const GeometryLog&) = delete;

  /// Appends frame `frame`, after checking that every element's art has the art's own paths, polylines and
  /// point counts: a path is one keyframed shape, so its layout must not change from frame to frame.
  void append(const std::vector<ElementArt>& art, int frame);
  int frames() const { return frames_; }
  /// Element `element`'s stroke scale in frame `frame`.
  double stroke_scale(int frame, int element);
  /// Polyline `line` of path `path` of element `element` in frame `frame`, container unit coordinates.
  const std::vector<Vec2>& points(int frame, int element, int path, int line);

 private:
  void read(int frame, std::size_t offset, std::size_t count);

  const World& world_;
  std::filesystem::path file_;
  std::fstream io_;
  std::size_t stride_ = 0;                                     // doubles per frame
  std::vector<std::size_t> scale_at_;                          // per element
  std::vector<std::vector<std::vector<std::size_t>>> line_at_;  // per element, path, polyline
  int frames_ = 0;
  std::vector<double> numbers_;
  std::vector<Vec2> points_;
};

/// animation.json: one Lottie shape layer per element (docs/animation-formats.md).
void write_lottie(const World& world, GeometryLog& log, const FrameOutput& out, const std::vector<std::string>& ids,
                  const std::filesystem::path& file);
/// animation.svg: the SVG frames' groups and ids, each path's d (and stroke width) animated with SMIL.
void write_svg_animation(const World& world, GeometryLog& log, const FrameOutput& out,
                         const std::vector<std::string>& ids, const std::filesystem::path& file);

}  // namespace animpak::frame_writers
