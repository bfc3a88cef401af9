// What the frame writers share (writers.cpp: PNG and SVG frames; animation_writers.cpp: Lottie and animated
// SVG). Private to the render library.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "animpak/render.hpp"

namespace animpak::frame_writers {

/// "#rrggbb" of a colour's channels (its alpha is written apart).
std::string hex(Rgba c);
std::string xml_escaped(const std::string& text);
/// One id per element, its name, unique among the SVG's ids ("container", "background" taken).
std::vector<std::string> element_ids(const World& world);

/// The paint attributes of one art path in an SVG, starting with a space: fill, its opacity and rule, the
/// stroke (`stroke_width` wide, round joins and caps as draw_art strokes) and paint order.
std::string svg_paint(const ArtPath& path, const std::string& stroke_width);

/// The keys of one element's animation, in frames of the document (frame i is frames/frame_i.png),
/// increasing: its art's points at `frames`, its stroke scale at `stroke_frames` (the same frames and, where
/// the scale is not straight between two slices, the frames between them).
struct ElementKeys {
  std::vector<double> frames;
  std::vector<ArtPoints> points;
  std::vector<double> stroke_frames, stroke_scales;
};

/// Element `element`'s keys in an `out.count`-frame document: linear, its own slices, from frame 0 to
/// frame N (N − 1 and a last one holding it, when the world does not loop); held, the N frames. One
/// frame: one key.
ElementKeys element_keys(const World& world, const SimState& state, int element, const FrameOutput& out);

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
