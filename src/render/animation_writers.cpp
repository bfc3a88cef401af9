// The animated vector formats: a Lottie document and an SVG animated with SMIL, both keyed from the frames'
// own replayed art (frame_art) through a scratch file of its coordinates. docs/animation-formats.md
// describes both documents.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "animpak/error.hpp"
#include "animpak/version.hpp"
#include "frame_writers.hpp"

namespace animpak::frame_writers {

GeometryLog::GeometryLog(const World& world, std::filesystem::path file) : world_(world), file_(std::move(file)) {
  for (const ElementInstance& e : world.elements) {
    const ArtShape& art = world.library[e.library].art.art;
    scale_at_.push_back(stride_++);
    auto& paths = line_at_.emplace_back(art.paths.size());
    for (std::size_t p = 0; p < art.paths.size(); ++p)
      for (const Polyline& line : art.paths[p].polylines) {
        paths[p].push_back(stride_);
        stride_ += 2 * line.points.size();
      }
  }
  io_.open(file_, std::ios::in | std::ios::out | std::ios::binary | std::ios::trunc);
  if (!io_) throw InputError(file_.string() + ": cannot create the scratch file; check that the folder is writable");
}

GeometryLog::~GeometryLog() {
  io_.close();
  std::error_code ignored;  // a scratch file left behind costs disk space only
  std::filesystem::remove(file_, ignored);
}

void GeometryLog::append(const std::vector<ElementArt>& art, int frame) {
  if (frame != frames_ || art.size() != world_.elements.size())
    throw std::logic_error("GeometryLog::append: frames must come in order, every element in each");
  numbers_.assign(stride_, 0.0);
  for (std::size_t e = 0; e < art.size(); ++e) {
    const ArtShape& shape = world_.library[world_.elements[e].library].art.art;
    const std::string where = "element " + world_.elements[e].name + ", frame " + std::to_string(frame);
    const std::string why = ": Lottie and animated SVG key each path from frame to frame, so every frame needs the art's "
                            "own paths and point counts";
    if (art[e].points.size() != shape.paths.size())
      throw InputError(where + ": " + std::to_string(art[e].points.size()) + " paths replayed, the art has " +
                       std::to_string(shape.paths.size()) + why);
    numbers_[scale_at_[e]] = art[e].stroke_scale;
    for (std::size_t p = 0; p < shape.paths.size(); ++p) {
      const auto& lines = shape.paths[p].polylines;
      const auto& replayed = art[e].points[p];
      if (replayed.size() != lines.size())
        throw InputError(where + ", path " + shape.paths[p].id + ": " + std::to_string(replayed.size()) +
                         " polylines replayed, the art has " + std::to_string(lines.size()) + why);
      for (std::size_t q = 0; q < lines.size(); ++q) {
        if (replayed[q].size() != lines[q].points.size())
          throw InputError(where + ", path " + shape.paths[p].id + ", polyline " + std::to_string(q) + ": " +
                           std::to_string(replayed[q].size()) + " points replayed, the art has " +
                           std::to_string(lines[q].points.size()) + why);
        double* at = &numbers_[line_at_[e][p][q]];
        for (const Vec2& v : replayed[q]) *at++ = v.x, *at++ = v.y;
      }
    }
  }
  io_.seekp(static_cast<std::streamoff>(frame) * static_cast<std::streamoff>(stride_ * sizeof(double)));
  io_.write(reinterpret_cast<const char*>(numbers_.data()), static_cast<std::streamsize>(stride_ * sizeof(double)));
  if (!io_) throw InputError(file_.string() + ": writing the scratch file failed; check free disk space");
  ++frames_;
}

void GeometryLog::read(int frame, std::size_t offset, std::size_t count) {
  numbers_.resize(count);
  io_.seekg(static_cast<std::streamoff>((static_cast<std::size_t>(frame) * stride_ + offset) * sizeof(double)));
  io_.read(reinterpret_cast<char*>(numbers_.data()), static_cast<std::streamsize>(count * sizeof(double)));
  if (!io_) throw InputError(file_.string() + ": reading the scratch file back failed");
}

double GeometryLog::stroke_scale(int frame, int element) {
  read(frame, scale_at_[element], 1);
  return numbers_[0];
}

const std::vector<Vec2>& GeometryLog::points(int frame, int element, int path, int line) {
  const std::size_t n = world_.library[world_.elements[element].library].art.art.paths[path].polylines[line].points.size();
  read(frame, line_at_[element][path][line], 2 * n);
  points_.resize(n);
  for (std::size_t k = 0; k < n; ++k) points_[k] = {numbers_[2 * k], numbers_[2 * k + 1]};
  return points_;
}

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
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (static_cast<unsigned char>(c) < 0x20) {
      char code[8];
      std::snprintf(code, sizeof code, "\\u%04x", c);
      out += code;
    } else out += c;
  }
  return out + "\"";
}

void check_written(const std::ofstream& out, const std::filesystem::path& file) {
  if (!out) throw InputError(file.string() + ": writing failed; check free disk space");
}

// Polylines with no point draw nothing (Picture::draw_art skips them); the formats leave them out too.
bool drawn(const Polyline& line) { return !line.points.empty(); }

// ---- Lottie -------------------------------------------------------------------------------------------

// A static property; Lottie's "a": 0.
std::string still(const std::string& value) { return "{\"a\":0,\"k\":" + value + "}"; }

// The transform every layer and group needs, the identity.
constexpr const char* identity_layer_transform =
    "{\"o\":{\"a\":0,\"k\":100},\"r\":{\"a\":0,\"k\":0},\"p\":{\"a\":0,\"k\":[0,0,0]},"
    "\"a\":{\"a\":0,\"k\":[0,0,0]},\"s\":{\"a\":0,\"k\":[100,100,100]}}";
constexpr const char* identity_group_transform =
    "{\"ty\":\"tr\",\"p\":{\"a\":0,\"k\":[0,0]},\"a\":{\"a\":0,\"k\":[0,0]},\"s\":{\"a\":0,\"k\":[100,100]},"
    "\"r\":{\"a\":0,\"k\":0},\"o\":{\"a\":0,\"k\":100},\"sk\":{\"a\":0,\"k\":0},\"sa\":{\"a\":0,\"k\":0},\"nm\":\"transform\"}";

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

// Keyframes of one property over the N frames, value(i) at frame i, plus a last key at frame N holding
// frame 0's value: a linear last interval runs from frame N − 1 back to frame 0, so the loop is seamless.
// Keys carry no end value ("e"): each interval ends on the next key's start, as Bodymovin 5.5 and later
// write it, and players draw such a file exactly as one with end values.
// `shape` properties take scalar easing, others one entry per dimension.
template <class Value>
void write_keyframes(std::ostream& json, int frames, Interpolation interpolation, bool shape, Value value) {
  if (frames == 1) {
    json << still(value(0));
    return;
  }
  const std::string easing = shape ? "\"i\":{\"x\":1,\"y\":1},\"o\":{\"x\":0,\"y\":0}"
                                   : "\"i\":{\"x\":[1],\"y\":[1]},\"o\":{\"x\":[0],\"y\":[0]}";
  json << "{\"a\":1,\"k\":[";
  for (int i = 0; i < frames; ++i)
    json << "{\"t\":" << i << ",\"s\":[" << value(i) << "],"
         << (interpolation == Interpolation::hold ? "\"h\":1" : easing) << "},";
  json << "{\"t\":" << frames << ",\"s\":[" << value(0) << "]}]}";
}

// The decimals that keep a coordinate within 10^−precision pixels when one unit is `pixels_per_unit`
// pixels.
int decimals_for(int precision, double pixels_per_unit) {
  return std::clamp(static_cast<int>(std::ceil(precision + std::log10(std::max(pixels_per_unit, 1e-12)) - 1e-9)), 0, 12);
}

}  // namespace

void write_lottie(const World& world, GeometryLog& log, const FrameOutput& out, const std::vector<std::string>& ids,
                  const std::filesystem::path& file) {
  std::ofstream json(file);
  if (!json) throw InputError(file.string() + ": cannot write; check that the folder is writable");
  // The PNG frames' pixels: the same size, margin and fit (draw_frame), so frame i here is frame_i.png.
  const Box box = world.container.bounds();
  const int height = out.style.size, width = raster_width(box, height);
  const PixelFit fit = fit_to_picture(width, height, box, 0.02 * height);
  const int frames = log.frames(), decimals = std::clamp(out.precision, 0, 12);

  json << "{\"v\":\"5.7.4\",\"fr\":" << number(out.fps, 6) << ",\"ip\":0,\"op\":" << frames << ",\"w\":" << width
       << ",\"h\":" << height << ",\"nm\":\"animpak\",\"ddd\":0,\"meta\":{\"g\":\"animpak "
       << animpak_version << "\"},\"assets\":[],\"layers\":[";
  // Lottie draws layers[0] on top: the container (drawn last in the frames), then the elements from the
  // last-drawn one down, then the background.
  int index = 0;
  auto layer_head = [&](int type, const std::string& name) {
    json << (index ? ",\n" : "\n");
    json << "{\"ddd\":0,\"ind\":" << ++index << ",\"ty\":" << type
         << ",\"nm\":" << json_string(name) << ",\"sr\":1,\"ks\":" << identity_layer_transform << ",\"ao\":0";
  };
  auto layer_tail = [&] { json << ",\"ip\":0,\"op\":" << frames << ",\"st\":0,\"bm\":0}"; };

  if (out.style.draw_container) {
    layer_head(4, "container");
    json << ",\"shapes\":[{\"ty\":\"gr\",\"nm\":\"outline\",\"it\":[";
    std::vector<std::vector<Vec2>> rings{world.container.outline};
    rings.insert(rings.end(), world.container.holes.begin(), world.container.holes.end());
    for (const auto& ring : rings) {
      std::vector<Vec2> pixels;
      for (Vec2 p : ring) pixels.push_back(fit.to_pixel(p));
      json << "{\"ty\":\"sh\",\"ks\":" << still(shape_value(pixels, true, decimals)) << "},";
    }
    // draw_frame's grey line, max(1, size / 400) pixels wide.
    json << "{\"ty\":\"st\",\"c\":" << still(colour({0.55, 0.55, 0.55, 1})) << ",\"o\":" << still("100")
         << ",\"w\":" << still(number(std::max(1.0, out.style.size / 400.0), 3))
         << ",\"lc\":2,\"lj\":2,\"nm\":\"stroke\"}," << identity_group_transform << "]}]";
    layer_tail();
  }

  for (int e = int(world.elements.size()) - 1; e >= 0; --e) {
    const ArtShape& art = world.library[world.elements[e].library].art.art;
    layer_head(4, ids[e]);
    json << ",\"shapes\":[";
    // Within a layer, too, the first item is on top: the paths from the last-painted one down.
    for (int p = int(art.paths.size()) - 1; p >= 0; --p) {
      const ArtPath& path = art.paths[p];
      json << (p + 1 < int(art.paths.size()) ? ",\n" : "\n") << "{\"ty\":\"gr\",\"nm\":" << json_string(path.id)
           << ",\"it\":[";
      for (int q = 0; q < int(path.polylines.size()); ++q) {
        if (!drawn(path.polylines[q])) continue;
        json << "{\"ty\":\"sh\",\"nm\":\"polyline " << q << "\",\"ks\":";
        write_keyframes(json, frames, out.interpolation, true, [&](int i) {
          std::vector<Vec2> pixels = log.points(i, e, p, q);
          for (Vec2& v : pixels) v = fit.to_pixel(v);
          return shape_value(pixels, path.polylines[q].closed, decimals);
        });
        json << "},";
      }
      // A group's fill and stroke paint every shape above them in it as one path; the later of the two is
      // painted first.
      const std::string fill = "{\"ty\":\"fl\",\"c\":" + still(colour(path.fill.color)) + ",\"o\":" +
                               still(number(100 * std::clamp(path.fill.color.a, 0.0, 1.0), 2)) +
                               ",\"r\":" + (path.fill_rule == FillRule::evenodd ? "2" : "1") + ",\"nm\":\"fill\"},";
      auto stroke = [&] {
        json << "{\"ty\":\"st\",\"c\":" << still(colour(path.stroke.color))
             << ",\"o\":" << still(number(100 * std::clamp(path.stroke.color.a, 0.0, 1.0), 2)) << ",\"w\":";
        write_keyframes(json, frames, out.interpolation, false, [&](int i) {
          return number(path.stroke_width * log.stroke_scale(i, e) * fit.scale, decimals);
        });
        // Round joins and caps, as draw_art strokes.
        json << ",\"lc\":2,\"lj\":2,\"nm\":\"stroke\"},";
      };
      const bool fills = path.fill.enabled, strokes = path.stroke.enabled && path.stroke_width > 0;
      if (path.paint_order == PaintOrder::fill_then_stroke) {
        if (strokes) stroke();
        if (fills) json << fill;
      } else {
        if (fills) json << fill;
        if (strokes) stroke();
      }
      json << identity_group_transform << "]}";
    }
    json << "]";
    layer_tail();
    check_written(json, file);
  }

  if (out.style.background.a > 0) {
    layer_head(1, "background");
    json << ",\"sc\":" << json_string(hex(out.style.background)) << ",\"sw\":" << width << ",\"sh\":" << height;
    layer_tail();
  }
  json << "\n]}\n";
  check_written(json, file);
}

// ---- SVG with SMIL ------------------------------------------------------------------------------------

namespace {

void write_svg_path_data(std::ostream& svg, GeometryLog& log, int frame, int element, int path_index, const ArtPath& path,
                         const ArtFrame& art_frame, int decimals) {
  bool first = true;
  for (int q = 0; q < int(path.polylines.size()); ++q) {
    if (!drawn(path.polylines[q])) continue;
    const std::vector<Vec2>& points = log.points(frame, element, path_index, q);
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Vec2 a = art_frame.to_art(points[k]);
      svg << (k ? " L" : (first ? "M" : " M")) << number(a.x, decimals) << ' ' << number(a.y, decimals);
    }
    if (path.polylines[q].closed) svg << " Z";
    first = false;
  }
}

}  // namespace

void write_svg_animation(const World& world, GeometryLog& log, const FrameOutput& out,
                         const std::vector<std::string>& ids, const std::filesystem::path& file) {
  std::ofstream svg(file);
  if (!svg) throw InputError(file.string() + ": cannot write; check that the folder is writable");
  // The container art's coordinates, as the SVG frames; the view box is exactly the PNG frames' picture
  // (the same pixel fit as draw_frame), so that frame i at time i / fps matches frame_i.png.
  const ArtFrame& art_frame = world.container.frame;
  const Box box = world.container.bounds();
  const int height = out.style.size, width = raster_width(box, height);
  const PixelFit fit = fit_to_picture(width, height, box, 0.02 * height);
  const double pixels_per_art_unit = fit.scale * art_frame.scale;
  const Vec2 view_min = art_frame.to_art((Vec2{0, 0} - fit.offset) * (1.0 / fit.scale));
  const double view_w = width / pixels_per_art_unit, view_h = height / pixels_per_art_unit;
  const int decimals = decimals_for(out.precision, pixels_per_art_unit);
  const int frames = log.frames();
  auto n = [&](double v) { return number(v, decimals); };

  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << number(view_min.x, decimals + 2) << ' '
      << number(view_min.y, decimals + 2) << ' ' << number(view_w, decimals + 2) << ' ' << number(view_h, decimals + 2)
      << "\" width=\"" << width << "\" height=\"" << height << "\">\n";
  svg << "<rect id=\"background\" x=\"" << n(view_min.x) << "\" y=\"" << n(view_min.y) << "\" width=\"" << n(view_w)
      << "\" height=\"" << n(view_h) << "\" fill=\"" << hex(out.style.background) << "\"";
  if (out.style.background.a < 1) svg << " fill-opacity=\"" << number(out.style.background.a, 4) << "\"";
  svg << "/>\n";

  std::vector<std::vector<Vec2>> rings{world.container.outline};
  rings.insert(rings.end(), world.container.holes.begin(), world.container.holes.end());
  svg << "<path id=\"container\" d=\"";
  for (std::size_t r = 0; r < rings.size(); ++r) {
    for (std::size_t k = 0; k < rings[r].size(); ++k) {
      const Vec2 a = art_frame.to_art(rings[r][k]);
      svg << (k ? " L" : (r ? " M" : "M")) << n(a.x) << ' ' << n(a.y);
    }
    svg << " Z";
  }
  svg << "\" fill-rule=\"evenodd\" fill=\"none\"";
  if (out.style.draw_container)
    svg << " stroke=\"#8c8c8c\" stroke-width=\"" << n(std::max(1.0, out.style.size / 400.0) / pixels_per_art_unit) << "\"";
  else svg << " stroke=\"none\"";
  svg << "/>\n";

  // One cycle lasts N / fps seconds; frame i shows at i / fps. Linear: N + 1 values, the last frame 0
  // again, so the path moves from frame N − 1 back to frame 0 as between any two frames. Discrete: N
  // values, each held for one frame.
  const bool linear = out.interpolation == Interpolation::linear;
  const int values = linear ? frames + 1 : frames;
  std::string key_times;
  for (int i = 0; i < values; ++i) {
    if (i) key_times += ';';
    key_times += number(double(i) / frames, 6);
  }
  const std::string timing = "dur=\"" + number(frames / out.fps, 6) + "s\" repeatCount=\"indefinite\" calcMode=\"" +
                             (linear ? "linear" : "discrete") + "\" keyTimes=\"" + key_times + "\"";
  const double art_per_unit = 1.0 / art_frame.scale;

  for (int e = 0; e < int(world.elements.size()); ++e) {
    const ArtShape& art = world.library[world.elements[e].library].art.art;
    svg << "<g id=\"" << xml_escaped(ids[e]) << "\">\n";
    for (int p = 0; p < int(art.paths.size()); ++p) {
      const ArtPath& path = art.paths[p];
      const bool strokes = path.stroke.enabled && path.stroke_width > 0;
      auto stroke_width = [&](int i) { return n(path.stroke_width * log.stroke_scale(i, e) * art_per_unit); };
      // Frame 0 as the path's own attributes: what a reader without SMIL shows.
      svg << "<path d=\"";
      write_svg_path_data(svg, log, 0, e, p, path, art_frame, decimals);
      svg << "\" fill=\"" << (path.fill.enabled ? hex(path.fill.color) : "none") << "\"";
      if (path.fill.enabled && path.fill.color.a < 1) svg << " fill-opacity=\"" << number(path.fill.color.a, 4) << "\"";
      if (path.fill_rule == FillRule::evenodd) svg << " fill-rule=\"evenodd\"";
      if (strokes)
        svg << " stroke=\"" << hex(path.stroke.color) << "\" stroke-width=\"" << stroke_width(0)
            << "\" stroke-linejoin=\"round\" stroke-linecap=\"round\"";
      if (path.stroke.enabled && path.stroke.color.a < 1)
        svg << " stroke-opacity=\"" << number(path.stroke.color.a, 4) << "\"";
      if (path.paint_order == PaintOrder::stroke_then_fill) svg << " paint-order=\"stroke\"";
      if (frames == 1) {
        svg << "/>\n";
        continue;
      }
      svg << ">\n<animate attributeName=\"d\" " << timing << " values=\"";
      for (int i = 0; i < values; ++i) {
        if (i) svg << ';';
        write_svg_path_data(svg, log, i % frames, e, p, path, art_frame, decimals);
      }
      svg << "\"/>\n";
      if (strokes) {
        svg << "<animate attributeName=\"stroke-width\" " << timing << " values=\"";
        for (int i = 0; i < values; ++i) svg << (i ? ";" : "") << stroke_width(i % frames);
        svg << "\"/>\n";
      }
      svg << "</path>\n";
    }
    svg << "</g>\n";
    check_written(svg, file);
  }
  svg << "</svg>\n";
  check_written(svg, file);
}

}  // namespace animpak::frame_writers
