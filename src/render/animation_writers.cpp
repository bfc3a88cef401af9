// The animated vector formats: a Lottie document and an SVG animated with SMIL, both written from each
// element's keys (element_keys, animation_keys.cpp). docs/animation-formats.md describes both documents.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "animpak/error.hpp"
#include "animpak/file_io.hpp"
#include "animpak/version.hpp"
#include "frame_writers.hpp"

namespace animpak::frame_writers {
namespace {

// v with `decimals` decimals, trailing zeros dropped ("12.5", "3", never "-0").
std::string number(double v, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, v);
  std::string s = text;
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  return s == "-0" ? "0" : s;
}

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\')
      out += '\\', out += c;
    else if (static_cast<unsigned char>(c) < 0x20) {
      char code[8];
      std::snprintf(code, sizeof code, "\\u%04x", c);
      out += code;
    } else
      out += c;
  }
  return out + "\"";
}

void check_written(const std::ostream& out, const std::filesystem::path& file) {
  if (!out) throw InputError(file.string() + ": writing failed; check free disk space");
}

// Polylines with no point draw nothing (Picture::draw_art skips them); the formats leave them out too.
bool drawn(const Polyline& line) { return !line.points.empty(); }

// The least corner of all of an element's keyed points, each mapped by `to` (into pixels or art units),
// rounded down to `decimals`: where the animated formats place the element's layer or group, so that its
// points are written as short numbers from there. (0, 0) when there is no point.
template <class Map>
Vec2 least_corner(const ElementKeys& keys, Map to, int decimals) {
  Vec2 least{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  for (const PathKeys& path : keys.paths)
    for (const auto& lines : path.lines)
      for (const auto& line : lines)
        for (Vec2 v : line) {
          const Vec2 p = to(v);
          least = {std::min(least.x, p.x), std::min(least.y, p.y)};
        }
  if (!std::isfinite(least.x)) return {0, 0};
  const double steps = std::pow(10.0, decimals);
  return {std::floor(least.x * steps) / steps, std::floor(least.y * steps) / steps};
}

// The farthest any of a placed element's local points lies from its frame's origin, in world units: how far
// a turn or a scale of the frame moves a point, which sets the decimals its angle and scale need.
double farthest_local(const ElementKeys& keys) {
  double farthest = 0.0;
  for (const PathKeys& path : keys.paths) {
    double offset = 0.0;  // where the path's own frame lies in the element's, at the farthest
    for (const Placement& at : path.placements) offset = std::max(offset, norm(at.position));
    for (const auto& lines : path.lines)
      for (const auto& line : lines)
        for (Vec2 v : line) farthest = std::max(farthest, offset + norm(v));
  }
  return farthest;
}

// The farthest a path's points lie from its own frame's origin (world units): the decimals of its angle.
double farthest_in_path(const PathKeys& path) {
  double farthest = 0.0;
  for (const auto& lines : path.lines)
    for (const auto& line : lines)
      for (Vec2 v : line) farthest = std::max(farthest, norm(v));
  return farthest;
}

// ---- Lottie -------------------------------------------------------------------------------------------

// A static property; Lottie's "a": 0.
std::string still(const std::string& value) { return "{\"a\":0,\"k\":" + value + "}"; }

// The transform every layer and group needs, the identity.
constexpr const char* identity_layer_transform =
    "{\"o\":{\"a\":0,\"k\":100},\"r\":{\"a\":0,\"k\":0},\"p\":{\"a\":0,\"k\":[0,0,0]},"
    "\"a\":{\"a\":0,\"k\":[0,0,0]},\"s\":{\"a\":0,\"k\":[100,100,100]}}";
constexpr const char* identity_group_transform =
    "{\"ty\":\"tr\",\"p\":{\"a\":0,\"k\":[0,0]},\"a\":{\"a\":0,\"k\":[0,0]},\"s\":{\"a\":0,\"k\":[100,100]},"
    "\"r\":{\"a\":0,\"k\":0},\"o\":{\"a\":0,\"k\":100},\"sk\":{\"a\":0,\"k\":0},\"sa\":{\"a\":0,\"k\":0},\"nm\":"
    "\"transform\"}";

std::string colour(Rgba c) {
  std::string s = "[";
  for (double channel : {c.r, c.g, c.b}) s += number(std::clamp(channel, 0.0, 1.0), 4) + ",";
  return s + "1]";
}

// A Lottie shape value: straight segments, so every in and out tangent is zero.
std::string shape_value(const std::vector<Vec2>& pixels, bool closed, int decimals) {
  std::string v = "[", zeros = "[";
  for (std::size_t k = 0; k < pixels.size(); ++k) {
    v += (k ? ",[" : "[") + number(pixels[k].x, decimals) + "," + number(pixels[k].y, decimals) + "]";
    zeros += k ? ",[0,0]" : "[0,0]";
  }
  v += "]", zeros += "]";
  return "{\"i\":" + zeros + ",\"o\":" + zeros + ",\"v\":" + v + ",\"c\":" + (closed ? "true" : "false") + "}";
}

// A Lottie shape value of cubic Bézier segments (BezierLine), its points mapped by `to`: each vertex with its
// in and out tangents relative to it, [0, 0] on a straight side.
template <class Map>
std::string bezier_shape_value(const BezierLine& line, Map to, int decimals) {
  std::string v = "[", in = "[", out = "[";
  const auto pair = [&](Vec2 p) { return "[" + number(p.x, decimals) + "," + number(p.y, decimals) + "]"; };
  for (std::size_t k = 0; k < line.points.size(); ++k) {
    const Vec2 at = to(line.points[k]);
    const std::string comma = k ? "," : "";
    v += comma + pair(at), in += comma + pair(to(line.before[k]) - at), out += comma + pair(to(line.after[k]) - at);
  }
  return "{\"i\":" + in + "],\"o\":" + out + "],\"v\":" + v + "],\"c\":" + (line.closed ? "true" : "false") + "}";
}

// Keyframes of one property, value(k) at frames[k]. Linear keys ease linearly (a straight line between two
// keys) unless `ease` gives the interval a timing curve (Ease); hold keys ("h": 1) show their value until
// the next. Keys carry no end value ("e"): each interval ends on the next key's start, as Bodymovin 5.5 and
// later write it, and players draw such a file exactly as one with end values. `shape` properties take
// scalar easing, others one entry per dimension.
template <class Value>
void write_keyframes(std::ostream& json, const std::vector<double>& frames, Interpolation interpolation, bool shape,
                     Value value, const std::vector<Ease>& ease = {}) {
  if (frames.size() == 1) {
    json << still(value(0));
    return;
  }
  const std::string linear = shape ? "\"i\":{\"x\":1,\"y\":1},\"o\":{\"x\":0,\"y\":0}"
                                   : "\"i\":{\"x\":[1],\"y\":[1]},\"o\":{\"x\":[0],\"y\":[0]}";
  const auto easing = [&](std::size_t k) {
    if (k >= ease.size() || ease[k].linear) return linear;
    const std::string y1 = number(ease[k].y1, 4), y2 = number(ease[k].y2, 4);
    return shape ? "\"i\":{\"x\":0.6667,\"y\":" + y2 + "},\"o\":{\"x\":0.3333,\"y\":" + y1 + "}"
                 : "\"i\":{\"x\":[0.6667],\"y\":[" + y2 + "]},\"o\":{\"x\":[0.3333],\"y\":[" + y1 + "]}";
  };
  const bool hold = interpolation == Interpolation::hold;
  json << "{\"a\":1,\"k\":[";
  for (std::size_t k = 0; k < frames.size(); ++k) {
    json << (k ? ",{\"t\":" : "{\"t\":") << number(frames[k], key_decimals) << ",\"s\":[" << value(k) << "]";
    if (hold)
      json << ",\"h\":1";
    else if (k + 1 < frames.size())
      json << "," << easing(k);
    json << "}";
  }
  json << "]}";
}

// The decimals that keep a coordinate within 10^−precision pixels when one unit is `pixels_per_unit`
// pixels.
int decimals_for(int precision, double pixels_per_unit) {
  return std::clamp(static_cast<int>(std::ceil(precision + std::log10(std::max(pixels_per_unit, 1e-12)) - 1e-9)), 0,
                    12);
}

// The Lottie layers, written top first (Lottie draws layers[0] on top). Coordinates are the PNG frames'
// pixels (draw_frame's size, margin and fit), so frame i here is frame_i.png.
class LottieLayers {
 public:
  LottieLayers(std::ostream& json, const World& world, const FrameOutput& out)
      : json_(json),
        interpolation_(out.interpolation),
        decimals_(std::clamp(out.precision, 0, 12)),
        width_(raster_width(world.container.shown_bounds(), out.style.size)),
        height_(out.style.size),
        frames_(out.count),
        fit_(fit_to_picture(width_, height_, world.container.shown_bounds(), 0.02 * height_)) {}
  void document_head(double fps) {
    json_ << "{\"v\":\"5.7.4\",\"fr\":" << number(fps, 6) << ",\"ip\":0,\"op\":" << frames_ << ",\"w\":" << width_
          << ",\"h\":" << height_ << ",\"nm\":\"animpak\",\"ddd\":0,\"meta\":{\"g\":\"animpak " << animpak_version
          << "\"},\"assets\":[],\"layers\":[";
  }
  void document_tail() { json_ << "\n]}\n"; }

  // draw_frame's grey line over the outline and holes, max(1, size / 400) pixels wide.
  void container_outline(const Container& container) {
    head(4, "container");
    json_ << ",\"shapes\":[{\"ty\":\"gr\",\"nm\":\"outline\",\"it\":[";
    std::vector<std::vector<Vec2>> rings{container.shown_outline()};
    rings.insert(rings.end(), container.shown_holes().begin(), container.shown_holes().end());
    for (const auto& ring : rings) {
      std::vector<Vec2> pixels;
      for (Vec2 p : ring) pixels.push_back(fit_.to_pixel(p));
      json_ << "{\"ty\":\"sh\",\"ks\":" << still(shape_value(pixels, true, decimals_)) << "},";
    }
    json_ << "{\"ty\":\"st\",\"c\":" << still(colour({0.55, 0.55, 0.55, 1})) << ",\"o\":" << still("100")
          << ",\"w\":" << still(number(std::max(1.0, height_ / 400.0), 3)) << ",\"lc\":2,\"lj\":2,\"nm\":\"stroke\"},"
          << identity_group_transform << "]}]";
    tail();
  }

  // One shape layer of art moving through `keys`; within it, too, the first item is on top: the paths
  // from the last-painted one down. An element with placement keys is a layer whose transform moves,
  // turns and scales it through them, its points written in its own frame (docs/animation-formats.md,
  // "The element's frame"); other art sits at the least corner of its points over the whole animation,
  // rounded to the decimals kept, and the points are written from there: shorter numbers, the same pixels.
  void art_layer(const std::string& name, const ArtShape& art, const ElementKeys& keys) {
    placed_ = !keys.frames.empty();
    if (placed_) {
      origin_ = {0, 0};
      placed_head(name, keys);
    } else {
      origin_ = least_corner(
          keys, [&](Vec2 v) { return fit_.to_pixel(v); }, decimals_);
      head(4, name, origin_);
    }
    json_ << ",\"shapes\":[";
    for (int p = int(art.paths.size()) - 1; p >= 0; --p) {
      json_ << (p + 1 < int(art.paths.size()) ? ",\n" : "\n");
      path_group(art.paths[p], keys.paths[p], keys);
    }
    json_ << "]";
    tail();
  }

  void background(Rgba colour) {
    head(1, "background");
    json_ << ",\"sc\":" << json_string(hex(colour)) << ",\"sw\":" << width_ << ",\"sh\":" << height_;
    tail();
  }

 private:
  // A layer's head; its transform the identity, or a move to `at`.
  void head(int type, const std::string& name, Vec2 at = {0, 0}) {
    json_ << (index_ ? ",\n" : "\n");
    json_ << "{\"ddd\":0,\"ind\":" << ++index_ << ",\"ty\":" << type << ",\"nm\":" << json_string(name)
          << ",\"sr\":1,\"ks\":";
    if (at.x == 0 && at.y == 0)
      json_ << identity_layer_transform;
    else
      json_ << "{\"o\":{\"a\":0,\"k\":100},\"r\":{\"a\":0,\"k\":0},\"p\":{\"a\":0,\"k\":[" << number(at.x, decimals_)
            << "," << number(at.y, decimals_)
            << ",0]},\"a\":{\"a\":0,\"k\":[0,0,0]},\"s\":{\"a\":0,\"k\":[100,100,100]}}";
    json_ << ",\"ao\":0";
  }
  void tail() { json_ << ",\"ip\":0,\"op\":" << frames_ << ",\"st\":0,\"bm\":0}"; }

  // A placed element's layer head: its transform keyed through the placements, position in pixels,
  // rotation in degrees, scale in percent, each to as many decimals as keep the art's farthest point within
  // the precision kept (decimals_for).
  void placed_head(const std::string& name, const ElementKeys& keys) {
    json_ << (index_ ? ",\n" : "\n");
    json_ << "{\"ddd\":0,\"ind\":" << ++index_ << ",\"ty\":4,\"nm\":" << json_string(name)
          << ",\"sr\":1,\"ks\":{\"o\":{\"a\":0,\"k\":100},\"r\":";
    const double reach = farthest_local(keys) * fit_.scale;
    const int degrees = decimals_for(decimals_, reach * M_PI / 180), percent = decimals_for(decimals_, reach / 100);
    write_keyframes(
        json_, keys.frames, interpolation_, false,
        [&](std::size_t k) { return number(keys.placements[k].angle * 180 / M_PI, degrees); }, keys.ease);
    json_ << ",\"p\":";
    vector_property(keys, [&](std::size_t k) {
      const Vec2 p = fit_.to_pixel(keys.placements[k].position);
      return number(p.x, decimals_) + "," + number(p.y, decimals_) + ",0";
    });
    json_ << ",\"a\":{\"a\":0,\"k\":[0,0,0]},\"s\":";
    vector_property(keys, [&](std::size_t k) {
      const std::string s = number(100 * keys.placements[k].scale, percent);
      return s + "," + s + ",100";
    });
    json_ << "},\"ao\":0";
  }
  // A vector property keyed at the placements' frames ("s": [x, y, z]) or, with one key, still.
  template <class Value>
  void vector_property(const ElementKeys& keys, Value value) {
    if (keys.frames.size() == 1)
      json_ << "{\"a\":0,\"k\":[" << value(0) << "]}";
    else
      write_keyframes(json_, keys.frames, interpolation_, false, value, keys.ease);
  }

  // A group's fill and stroke paint every shape above them in it as one path, so holes and even–odd
  // fills come out as in the frames; the later-painted of the two comes first.
  void path_group(const ArtPath& path, const PathKeys& path_keys, const ElementKeys& keys) {
    json_ << "{\"ty\":\"gr\",\"nm\":" << json_string(path.id) << ",\"it\":[";
    for (int q = 0; q < int(path.polylines.size()); ++q) {
      if (!drawn(path.polylines[q])) continue;
      json_ << "{\"ty\":\"sh\",\"nm\":\"polyline " << q << "\",\"ks\":";
      write_keyframes(
          json_, path_keys.frames, interpolation_, true,
          [&](std::size_t k) {
            const auto to = [&](Vec2 v) { return placed_ ? v * fit_.scale : fit_.to_pixel(v) - origin_; };
            if (!path_keys.curves.empty()) return bezier_shape_value(path_keys.curves[k][q], to, decimals_);
            std::vector<Vec2> pixels = path_keys.lines[k][q];
            for (Vec2& v : pixels) v = to(v);
            return shape_value(pixels, path.polylines[q].closed, decimals_);
          },
          path_keys.ease);
      json_ << "},";
    }
    const bool fills = path.fill.enabled, strokes = path.stroke.enabled && path.stroke_width > 0;
    if (path.paint_order == PaintOrder::fill_then_stroke) {
      if (strokes) stroke(path, keys);
      if (fills) fill(path);
    } else {
      if (fills) fill(path);
      if (strokes) stroke(path, keys);
    }
    if (path_keys.place_frames.empty())
      json_ << identity_group_transform;
    else
      group_transform(path_keys);
    json_ << "]}";
  }
  // A path's own frame within its layer: its position (pixels of the layer), scale and angle keyed.
  void group_transform(const PathKeys& path) {
    const int degrees = decimals_for(decimals_, farthest_in_path(path) * fit_.scale * M_PI / 180);
    json_ << "{\"ty\":\"tr\",\"p\":";
    if (path.place_frames.size() == 1) {
      const Vec2 p = path.placements[0].position * fit_.scale;
      json_ << "{\"a\":0,\"k\":[" << number(p.x, decimals_) << "," << number(p.y, decimals_) << "]}";
    } else {
      write_keyframes(
          json_, path.place_frames, interpolation_, false,
          [&](std::size_t k) {
            const Vec2 p = path.placements[k].position * fit_.scale;
            return number(p.x, decimals_) + "," + number(p.y, decimals_);
          },
          path.place_ease);
    }
    json_ << ",\"a\":{\"a\":0,\"k\":[0,0]},\"s\":";
    const int percent = decimals_for(decimals_, farthest_in_path(path) * fit_.scale / 100);
    if (path.place_frames.size() == 1) {
      const std::string s = number(100 * path.placements[0].scale, percent);
      json_ << "{\"a\":0,\"k\":[" << s << "," << s << "]}";
    } else {
      write_keyframes(
          json_, path.place_frames, interpolation_, false,
          [&](std::size_t k) {
            const std::string s = number(100 * path.placements[k].scale, percent);
            return s + "," + s;
          },
          path.place_ease);
    }
    json_ << ",\"r\":";
    write_keyframes(
        json_, path.place_frames, interpolation_, false,
        [&](std::size_t k) { return number(path.placements[k].angle * 180 / M_PI, degrees); }, path.place_ease);
    json_ << ",\"o\":{\"a\":0,\"k\":100},\"sk\":{\"a\":0,\"k\":0},\"sa\":{\"a\":0,\"k\":0},\"nm\":"
             "\"transform\"}";
  }
  void fill(const ArtPath& path) {
    json_ << "{\"ty\":\"fl\",\"c\":" << still(colour(path.fill.color))
          << ",\"o\":" << still(number(100 * std::clamp(path.fill.color.a, 0.0, 1.0), 2))
          << ",\"r\":" << (path.fill_rule == FillRule::evenodd ? "2" : "1") << ",\"nm\":\"fill\"},";
  }
  // The width follows the element's scale, keyed with its points; round joins and caps, as draw_art.
  void stroke(const ArtPath& path, const ElementKeys& keys) {
    json_ << "{\"ty\":\"st\",\"c\":" << still(colour(path.stroke.color))
          << ",\"o\":" << still(number(100 * std::clamp(path.stroke.color.a, 0.0, 1.0), 2)) << ",\"w\":";
    write_keyframes(
        json_, keys.stroke_frames, interpolation_, false,
        [&](std::size_t k) { return number(path.stroke_width * keys.stroke_scales[k] * fit_.scale, decimals_); },
        keys.stroke_ease);
    json_ << ",\"lc\":2,\"lj\":2,\"nm\":\"stroke\"},";
  }

  std::ostream& json_;
  Interpolation interpolation_;
  int decimals_, width_ = 0, height_ = 0, frames_ = 0, index_ = 0;
  PixelFit fit_;
  Vec2 origin_{0, 0};    // where the art layer being written sits, unless placed
  bool placed_ = false;  // whether its points are in its element's frame (ElementKeys::frames)
};

}  // namespace

// The layers from the top: the container's outline (drawn last in the frames), the elements from the
// last-drawn one down, the container's art (drawn first), the background.
void write_lottie(const World& world, const SimState& state, const FrameOutput& out,
                  const std::vector<std::string>& ids, std::ostream& json, const std::filesystem::path& file) {
  LottieLayers layers(json, world, out);
  layers.document_head(out.fps);
  if (out.style.container == ContainerDrawing::outline) layers.container_outline(world.container);
  for (int e = drawn_count(world) - 1; e >= 0; --e) {
    const ArtShape& art = world.library[world.elements[drawn_source(world, e)].library].art.art;
    layers.art_layer(ids[e], art, drawn_keys(world, state, e, out));
    check_written(json, file);
  }
  if (out.style.container == ContainerDrawing::fill)
    layers.art_layer("container", world.container.art, still_keys(own_points(world.container.art)));
  if (out.style.background.a > 0) layers.background(out.style.background);
  layers.document_tail();
  check_written(json, file);
}

// ---- SVG with SMIL ------------------------------------------------------------------------------------

namespace {

// The container art's coordinates, as the SVG frames; the view box is exactly the PNG frames' picture (the
// same pixel fit as draw_frame), so that frame i at time i / fps matches frame_i.png.
struct SvgView {
  explicit SvgView(const ArtFrame& art_frame) : frame(art_frame) {}
  const ArtFrame& frame;
  int width = 0, height = 0, decimals = 0, precision = 2;  // decimals of an art unit, and of a pixel (--precision)
  double pixels_per_art_unit = 1.0;
  Vec2 min;
  double w = 0.0, h = 0.0;
  std::string n(double v) const { return number(v, decimals); }
};

SvgView svg_view(const World& world, const FrameOutput& out) {
  SvgView view(world.container.frame);
  const Box box = world.container.shown_bounds();
  view.height = out.style.size, view.width = raster_width(box, view.height);
  const PixelFit fit = fit_to_picture(view.width, view.height, box, 0.02 * view.height);
  view.pixels_per_art_unit = fit.scale * view.frame.scale;
  view.min = view.frame.to_art((Vec2{0, 0} - fit.offset) * (1.0 / fit.scale));
  view.w = view.width / view.pixels_per_art_unit, view.h = view.height / view.pixels_per_art_unit;
  view.decimals = decimals_for(out.precision, view.pixels_per_art_unit);
  view.precision = out.precision;
  return view;
}

// A path's d, its points as `to` writes them (in the art's coordinates less an origin, or a placed
// element's own frame): its polylines, or with `curves` (BezierLine, one per polyline) their cubic
// segments, C for a curved one and L for a straight one, so that every key of a path writes the same
// commands.
template <class Map>
void write_svg_path_data(std::ostream& svg, const SvgView& view, const ArtPath& path,
                         const std::vector<std::vector<Vec2>>& lines, Map to,
                         const std::vector<BezierLine>* curves = nullptr) {
  bool first = true;
  const auto point = [&](Vec2 v) {
    const Vec2 a = to(v);
    svg << view.n(a.x) << ' ' << view.n(a.y);
  };
  for (std::size_t q = 0; q < path.polylines.size(); ++q) {
    if (!drawn(path.polylines[q])) continue;
    if (curves != nullptr) {
      const BezierLine& line = (*curves)[q];
      const std::size_t n = line.points.size();
      svg << (first ? "M" : " M");
      point(line.points[0]);
      for (std::size_t k = 0; k < (line.closed ? n : n - 1); ++k) {
        const std::size_t next = (k + 1) % n;
        const bool straight = line.after[k] == line.points[k] && line.before[next] == line.points[next];
        if (straight && next == 0) break;  // Z closes it
        if (straight) {
          svg << " L";
        } else {
          svg << " C";
          point(line.after[k]);
          svg << ' ';
          point(line.before[next]);
          svg << ' ';
        }
        point(line.points[next]);
      }
    } else {
      for (std::size_t k = 0; k < lines[q].size(); ++k) {
        svg << (k ? " L" : (first ? "M" : " M"));
        point(lines[q][k]);
      }
    }
    if (path.polylines[q].closed) svg << " Z";
    first = false;
  }
}

// The backdrop (none when the background is transparent), the container's art when it is filled, and the
// container's path, stroked grey when it is outlined: the SVG frames' order.
void write_svg_head(std::ostream& svg, const SvgView& view, const World& world, const FrameStyle& style) {
  const int d = view.decimals + 2;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << number(view.min.x, d) << ' ' << number(view.min.y, d)
      << ' ' << number(view.w, d) << ' ' << number(view.h, d) << "\" width=\"" << view.width << "\" height=\""
      << view.height << "\">\n";
  if (style.background.a > 0) {
    svg << "<rect id=\"background\" x=\"" << view.n(view.min.x) << "\" y=\"" << view.n(view.min.y) << "\" width=\""
        << view.n(view.w) << "\" height=\"" << view.n(view.h) << "\" fill=\"" << hex(style.background) << "\"";
    if (style.background.a < 1) svg << " fill-opacity=\"" << number(style.background.a, 4) << "\"";
    svg << "/>\n";
  }
  if (style.container == ContainerDrawing::fill) {
    const ArtShape& art = world.container.art;
    const ArtPoints points = own_points(art);
    svg << "<g id=\"container-art\">\n";
    for (std::size_t p = 0; p < art.paths.size(); ++p) {
      svg << "<path d=\"";
      write_svg_path_data(svg, view, art.paths[p], points[p], [&](Vec2 v) { return view.frame.to_art(v); });
      svg << "\"" << svg_paint(art.paths[p], view.n(art.paths[p].stroke_width / view.frame.scale)) << "/>\n";
    }
    svg << "</g>\n";
  }
  std::vector<std::vector<Vec2>> rings{world.container.shown_outline()};
  rings.insert(rings.end(), world.container.shown_holes().begin(), world.container.shown_holes().end());
  svg << "<path id=\"container\" d=\"";
  for (std::size_t r = 0; r < rings.size(); ++r) {
    for (std::size_t k = 0; k < rings[r].size(); ++k) {
      const Vec2 a = view.frame.to_art(rings[r][k]);
      svg << (k ? " L" : (r ? " M" : "M")) << view.n(a.x) << ' ' << view.n(a.y);
    }
    svg << " Z";
  }
  svg << "\" fill-rule=\"evenodd\" fill=\"none\"";
  if (style.container == ContainerDrawing::outline)
    svg << " stroke=\"#8c8c8c\" stroke-width=\"" << view.n(std::max(1.0, style.size / 400.0) / view.pixels_per_art_unit)
        << "\"";
  else
    svg << " stroke=\"none\"";
  svg << "/>\n";
}

// One cycle lasts N / fps seconds and frame i shows at i / fps, so a key at frame f has keyTime f / N.
// Linear keys end at frame N (element_keys), as calcMode="linear" needs a last keyTime of 1; where an
// interval eases (Ease), calcMode="spline" with each interval's keySplines, "0 0 1 1" for a straight one.
// Held keys (calcMode="discrete") are the N frames.
std::string smil_timing(const std::vector<double>& frames, int count, double fps, Interpolation interpolation,
                        const std::vector<Ease>& ease = {}) {
  std::string key_times;
  for (double f : frames) {
    if (!key_times.empty()) key_times += ';';
    key_times += number(f / count, key_decimals + 6);
  }
  const bool eased = std::any_of(ease.begin(), ease.end(), [](const Ease& e) { return !e.linear; });
  std::string mode = interpolation == Interpolation::linear ? (eased ? "spline" : "linear") : "discrete";
  std::string timing = "dur=\"" + number(count / fps, 6) + "s\" repeatCount=\"indefinite\" calcMode=\"" + mode +
                       "\" keyTimes=\"" + key_times + "\"";
  if (eased && interpolation == Interpolation::linear) {
    timing += " keySplines=\"";
    for (std::size_t k = 0; k < ease.size(); ++k) {
      if (k) timing += ';';
      if (ease[k].linear) {
        timing += "0 0 1 1";
      } else {
        timing += "0.3333 ";
        timing += number(ease[k].y1, 4);
        timing += " 0.6667 ";
        timing += number(ease[k].y2, 4);
      }
    }
    timing += "\"";
  }
  return timing;
}

// A path's own d and stroke width are its first key's, what a reader without SMIL shows; <animate> moves
// them through the keys.
template <class Map>
void write_animated_path(std::ostream& svg, const SvgView& view, const ArtPath& path, const PathKeys& keys,
                         const ElementKeys& element, Map to, const std::string& shape_timing,
                         const std::string& stroke_timing, int count, double fps, Interpolation interpolation) {
  const bool strokes = path.stroke.enabled && path.stroke_width > 0;
  auto stroke_width = [&](std::size_t k) {
    return view.n(path.stroke_width * element.stroke_scales[k] / view.frame.scale);
  };
  const int degrees =
      decimals_for(view.precision, farthest_in_path(keys) / view.frame.scale * view.pixels_per_art_unit * M_PI / 180);
  const auto translate = [&](std::size_t k) {
    const Vec2 a = keys.placements[k].position * (1.0 / view.frame.scale);
    return view.n(a.x) + " " + view.n(a.y);
  };
  const auto rotate = [&](std::size_t k) { return number(keys.placements[k].angle * 180 / M_PI, degrees); };
  const int factor = decimals_for(view.precision, farthest_in_path(keys) / view.frame.scale * view.pixels_per_art_unit);
  const auto scale = [&](std::size_t k) { return number(keys.placements[k].scale, factor); };
  svg << "<path";
  if (!keys.placements.empty())
    svg << " transform=\"translate(" << translate(0) << ") rotate(" << rotate(0) << ") scale(" << scale(0) << ")\"";
  const auto curves = [&](std::size_t k) { return keys.curves.empty() ? nullptr : &keys.curves[k]; };
  svg << " d=\"";
  write_svg_path_data(svg, view, path, keys.lines[0], to, curves(0));
  svg << "\"" << svg_paint(path, stroke_width(0));
  if (keys.frames.size() == 1 && element.stroke_frames.size() == 1 && keys.place_frames.size() <= 1) {
    svg << "/>\n";
    return;
  }
  svg << ">\n";
  if (keys.place_frames.size() > 1) {
    const std::string timing = smil_timing(keys.place_frames, count, fps, interpolation, keys.place_ease);
    const auto animate = [&](const char* type, const char* additive, auto value) {
      svg << "<animateTransform attributeName=\"transform\" type=\"" << type << "\" additive=\"" << additive << "\" "
          << timing << " values=\"";
      for (std::size_t k = 0; k < keys.place_frames.size(); ++k) svg << (k ? ";" : "") << value(k);
      svg << "\"/>\n";
    };
    animate("translate", "replace", translate);
    animate("rotate", "sum", rotate);
    animate("scale", "sum", scale);
  }
  if (keys.frames.size() > 1) {
    svg << "<animate attributeName=\"d\" " << shape_timing << " values=\"";
    for (std::size_t k = 0; k < keys.frames.size(); ++k) {
      if (k) svg << ';';
      write_svg_path_data(svg, view, path, keys.lines[k], to, curves(k));
    }
    svg << "\"/>\n";
  }
  if (strokes && element.stroke_frames.size() > 1) {
    svg << "<animate attributeName=\"stroke-width\" " << stroke_timing << " values=\"";
    for (std::size_t k = 0; k < element.stroke_frames.size(); ++k) svg << (k ? ";" : "") << stroke_width(k);
    svg << "\"/>\n";
  }
  svg << "</path>\n";
}

// A placed element's group (docs/animation-formats.md, "The element's frame"): its transform
// translate(x y) rotate(degrees) scale(s) at the first placement, what a reader without SMIL shows, and
// one <animateTransform> for each part through the placements (the first replacing the attribute, the
// others added after it, so that they compose in that order); the angle and scale to as many decimals as
// keep the art's farthest point within the precision kept.
void write_placed_group(std::ostream& svg, const SvgView& view, const std::string& id, const ElementKeys& keys,
                        const FrameOutput& out) {
  const double reach = farthest_local(keys) / view.frame.scale * view.pixels_per_art_unit;
  const int degrees = decimals_for(out.precision, reach * M_PI / 180), factor = decimals_for(out.precision, reach);
  const auto translate = [&](std::size_t k) {
    const Vec2 a = view.frame.to_art(keys.placements[k].position);
    return view.n(a.x) + " " + view.n(a.y);
  };
  const auto rotate = [&](std::size_t k) { return number(keys.placements[k].angle * 180 / M_PI, degrees); };
  const auto scale = [&](std::size_t k) { return number(keys.placements[k].scale, factor); };
  svg << "<g id=\"" << xml_escaped(id) << "\" transform=\"translate(" << translate(0) << ") rotate(" << rotate(0)
      << ") scale(" << scale(0) << ")\">\n";
  if (keys.frames.size() == 1) return;
  const std::string timing = smil_timing(keys.frames, out.count, out.fps, out.interpolation, keys.ease);
  const auto animate = [&](const char* type, const char* additive, auto value) {
    svg << "<animateTransform attributeName=\"transform\" type=\"" << type << "\" additive=\"" << additive << "\" "
        << timing << " values=\"";
    for (std::size_t k = 0; k < keys.frames.size(); ++k) svg << (k ? ";" : "") << value(k);
    svg << "\"/>\n";
  };
  animate("translate", "replace", translate);
  animate("rotate", "sum", rotate);
  animate("scale", "sum", scale);
}

}  // namespace

void write_svg_animation(const World& world, const SimState& state, const FrameOutput& out,
                         const std::vector<std::string>& ids, const std::filesystem::path& file) {
  std::ostringstream svg;  // written whole and checked by write_file_atomically
  const SvgView view = svg_view(world, out);
  write_svg_head(svg, view, world, out.style);
  for (int e = 0; e < drawn_count(world); ++e) {
    const ArtShape& art = world.library[world.elements[drawn_source(world, e)].library].art.art;
    const ElementKeys keys = drawn_keys(world, state, e, out);
    const std::string stroke_timing =
        smil_timing(keys.stroke_frames, out.count, out.fps, out.interpolation, keys.stroke_ease);
    const auto write_paths = [&](auto to) {
      for (int p = 0; p < int(art.paths.size()); ++p) {
        const PathKeys& path = keys.paths[p];
        write_animated_path(svg, view, art.paths[p], path, keys, to,
                            smil_timing(path.frames, out.count, out.fps, out.interpolation, path.ease), stroke_timing,
                            out.count, out.fps, out.interpolation);
      }
    };
    if (keys.frames.empty()) {
      const Vec2 origin = least_corner(
          keys, [&](Vec2 v) { return view.frame.to_art(v); }, view.decimals);
      svg << "<g id=\"" << xml_escaped(ids[e]) << "\" transform=\"translate(" << view.n(origin.x) << ' '
          << view.n(origin.y) << ")\">\n";
      write_paths([&](Vec2 v) { return view.frame.to_art(v) - origin; });
    } else {
      write_placed_group(svg, view, ids[e], keys, out);
      write_paths([&](Vec2 v) { return v * (1.0 / view.frame.scale); });
    }
    svg << "</g>\n";
    check_written(svg, file);
  }
  svg << "</svg>\n";
  check_written(svg, file);
  write_file_atomically(file, svg.str());
}

}  // namespace animpak::frame_writers
