#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iomanip>
#include <set>
#include <sstream>

#include "animpak/error.hpp"
#include "animpak/file_io.hpp"
#include "animpak/render.hpp"
#include "animpak/xml_text.hpp"
#include "frame_writers.hpp"

namespace animpak {
namespace frame_writers {

std::string hex(Rgba c) {
  char s[8];
  auto channel = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
  std::snprintf(s, sizeof s, "#%02x%02x%02x", channel(c.r), channel(c.g), channel(c.b));
  return s;
}

// One id per element, its name: unguided copies are named "star#3" and guided elements get unique
// user names (the scene parser rejects repeats), but a guided "star#3" or "container" could still meet
// another id, so a repeat gets "-2", "-3", … appended.
std::vector<std::string> element_ids(const World& world) {
  std::set<std::string> taken{"container", "container-art", "background"};
  std::vector<std::string> ids;
  for (int i = 0; i < drawn_count(world); ++i) {
    const std::string name = drawn_name(world, i);
    std::string id = name;
    for (int k = 2; taken.count(id); ++k) id = name + "-" + std::to_string(k);
    taken.insert(id);
    ids.push_back(id);
  }
  return ids;
}

std::string svg_paint(const ArtPath& path, const std::string& stroke_width) {
  std::ostringstream out;
  out << std::setprecision(4) << " fill=\"" << (path.fill.enabled ? hex(path.fill.color) : "none") << "\"";
  if (path.fill.enabled && path.fill.color.a < 1) out << " fill-opacity=\"" << path.fill.color.a << "\"";
  if (path.fill_rule == FillRule::evenodd) out << " fill-rule=\"evenodd\"";
  if (path.stroke.enabled && path.stroke_width > 0)
    out << " stroke=\"" << hex(path.stroke.color) << "\" stroke-width=\"" << stroke_width
        << "\" stroke-linejoin=\"round\" stroke-linecap=\"round\"";
  if (path.stroke.enabled && path.stroke.color.a < 1) out << " stroke-opacity=\"" << path.stroke.color.a << "\"";
  if (path.paint_order == PaintOrder::stroke_then_fill) out << " paint-order=\"stroke\"";
  return out.str();
}

}  // namespace frame_writers

namespace {

using frame_writers::hex;
using frame_writers::svg_paint;

std::string frame_name(int i, const char* ext) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.%s", i, ext);
  return name;
}

// The path data of polylines mapped by `to`: "M x y L x y … Z".
template <class Map>
void write_path_data(std::ostream& out, const std::vector<std::vector<Vec2>>& polylines,
                     const std::vector<bool>& closed, Map to) {
  for (std::size_t q = 0; q < polylines.size(); ++q) {
    for (std::size_t k = 0; k < polylines[q].size(); ++k) {
      const Vec2 p = to(polylines[q][k]);
      out << (k ? " L" : (q ? " M" : "M")) << p.x << ' ' << p.y;
    }
    if (closed[q]) out << " Z";
  }
}

// One art path: its polylines mapped by `to`, its paint, strokes `stroke_width` wide.
template <class Map>
void write_svg_path(std::ostream& out, const ArtPath& path, const std::vector<std::vector<Vec2>>& points, Map to,
                    double stroke_width) {
  std::vector<bool> closed;
  for (const Polyline& line : path.polylines) closed.push_back(line.closed);
  std::ostringstream width;
  width << std::setprecision(10) << stroke_width;
  out << "<path d=\"";
  write_path_data(out, points, closed, to);
  out << "\"" << svg_paint(path, width.str()) << "/>\n";
}

// The backdrop (none when the background is transparent), the container's art when it is filled, and the
// container (outline and holes, even–odd), stroked grey when it is outlined.
void write_svg_container(std::ostream& out, const World& world, const FrameStyle& style, double x, double y, double w,
                         double h) {
  auto to_art = [&](Vec2 p) { return world.container.frame.to_art(p); };
  if (style.background.a > 0) {
    out << "<rect id=\"background\" x=\"" << x << "\" y=\"" << y << "\" width=\"" << w << "\" height=\"" << h
        << "\" fill=\"" << hex(style.background) << "\"";
    if (style.background.a < 1) out << " fill-opacity=\"" << style.background.a << "\"";
    out << "/>\n";
  }
  if (style.container == ContainerDrawing::fill) {
    const ArtShape& art = world.container.art;
    const ArtPoints points = own_points(art);
    out << "<g id=\"container-art\">\n";
    for (std::size_t p = 0; p < art.paths.size(); ++p)
      write_svg_path(out, art.paths[p], points[p], to_art, art.paths[p].stroke_width / world.container.frame.scale);
    out << "</g>\n";
  }
  std::vector<std::vector<Vec2>> rings{world.container.shown_outline()};
  rings.insert(rings.end(), world.container.shown_holes().begin(), world.container.shown_holes().end());
  out << "<path id=\"container\" d=\"";
  write_path_data(out, rings, std::vector<bool>(rings.size(), true), to_art);
  out << "\" fill-rule=\"evenodd\" fill=\"none\"";
  // draw_frame's grey line, max(1, size / 400) pixels wide.
  if (style.container == ContainerDrawing::outline)
    out << " stroke=\"#8c8c8c\" stroke-width=\"" << std::max(1.0, style.size / 400.0) * h / style.size << "\"";
  else
    out << " stroke=\"none\"";
  out << "/>\n";
}

// One SVG frame in the container art's coordinates, so that it lays over the container's own art: the
// container first, then one group per element, id its name, holding its paths in drawing order with their
// paint. Strokes have round joins and caps as draw_art paints them.
void write_svg(const World& world, const std::vector<ElementArt>& art, const FrameStyle& style,
               const std::vector<std::string>& ids, const std::filesystem::path& file) {
  std::ostringstream out;  // written whole and checked by write_file_atomically
  const ArtFrame& frame = world.container.frame;
  auto to_art = [&](Vec2 p) { return frame.to_art(p); };
  Box box;
  for (Vec2 p : world.container.shown_outline()) box.add(to_art(p));
  // The margin of draw_frame's pictures: 2 % of the height on every side.
  const double margin = 0.02 * box.height();
  const double x = box.min.x - margin, y = box.min.y - margin, w = box.width() + 2 * margin,
               h = box.height() + 2 * margin;
  out << std::setprecision(10);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << x << ' ' << y << ' ' << w << ' ' << h
      << "\" width=\"" << raster_width({{x, y}, {x + w, y + h}}, style.size) << "\" height=\"" << style.size << "\">\n";
  write_svg_container(out, world, style, x, y, w, h);
  for (std::size_t i = 0; i < art.size(); ++i) {
    const ArtShape& shape = world.library[world.elements[drawn_source(world, int(i))].library].art.art;
    out << "<g id=\"" << xml_escaped(ids[i]) << "\">\n";
    for (std::size_t p = 0; p < shape.paths.size(); ++p)
      write_svg_path(out, shape.paths[p], art[i].points[p], to_art,
                     shape.paths[p].stroke_width * art[i].stroke_scale / frame.scale);
    out << "</g>\n";
  }
  out << "</svg>\n";
  write_file_atomically(file, out.str());
}

void run_ffmpeg(const std::string& args, const std::filesystem::path& target) {
  const std::string command = "ffmpeg -nostdin -hide_banner -loglevel error -y " + args + " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) throw InputError(target.string() + ": cannot start ffmpeg; install it (scripts/install-deps.sh)");
  std::string log;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe)) log += buffer;
  const int status = ::pclose(pipe);
  if (status != 0)
    throw InputError(target.string() + ": ffmpeg failed (" + (log.empty() ? "is ffmpeg installed?" : log) +
                     "); the PNG frames are kept in " + target.parent_path().string() + "/frames");
  // ffmpeg's own writes are not ours to check: its file must be there, not empty, and on disk.
  sync_written_file(target);
}

std::string quoted(const std::filesystem::path& p) {
  std::string s = "'";
  for (char c : p.string()) s += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return s + "'";
}

}  // namespace

std::string art_svg(const ArtShape& art, int size) {
  Box box = art.bounds();
  double widest = 0.0;
  for (const ArtPath& path : art.paths) widest = std::max(widest, path.stroke_width);
  const double pad = std::max(0.5 * widest, 0.01 * std::max(box.width(), box.height()));
  const double x = box.min.x - pad, y = box.min.y - pad, w = std::max(box.width() + 2 * pad, 1e-9),
               h = std::max(box.height() + 2 * pad, 1e-9);
  const double k = size / std::max(w, h);
  std::ostringstream out;
  out << std::setprecision(7) << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << x << ' ' << y << ' ' << w
      << ' ' << h << "\" width=\"" << std::max(1L, std::lround(w * k)) << "\" height=\""
      << std::max(1L, std::lround(h * k)) << "\">\n";
  const ArtPoints points = own_points(art);
  for (std::size_t p = 0; p < art.paths.size(); ++p)
    write_svg_path(
        out, art.paths[p], points[p], [](Vec2 q) { return q; }, art.paths[p].stroke_width);
  out << "</svg>";
  return out.str();
}

std::string animation_file_name(FrameFormat format) {
  switch (format) {
    case FrameFormat::lottie:
      return "animation.json";
    case FrameFormat::dotlottie:
      return "animation.lottie";
    case FrameFormat::svg_anim:
      return "animation.svg";
    default:
      return "";
  }
}

namespace {

// The GIF palette keeps one entry for transparency when the background is transparent, and pixels less
// than half opaque take it (GIF has no partial alpha).
void write_gif(const std::string& input, const FrameOutput& out) {
  const auto gif = out.dir / "animation.gif";
  const bool transparent = out.style.background.a < 1;
  run_ffmpeg(input +
                 " -filter_complex \"[0:v]split[a][b];[a]palettegen=reserve_transparent=" + (transparent ? "1" : "0") +
                 "[p];[b][p]paletteuse" + (transparent ? "=alpha_threshold=128" : "") + "\" -loop 0 " + quoted(gif),
             gif);
}

void report(const FrameOutput& out, const std::string& stage, int done = 0, int total = 1) {
  if (out.on_progress) out.on_progress(stage, done, total);
}

void write_animations(const World& world, const SimState& state, const FrameOutput& out,
                      const std::vector<std::string>& ids, const std::function<bool(FrameFormat)>& wants) {
  if (wants(FrameFormat::lottie)) {
    report(out, animation_file_name(FrameFormat::lottie));
    const auto file = out.dir / animation_file_name(FrameFormat::lottie);
    std::ostringstream json;
    frame_writers::write_lottie(world, state, out, ids, json, file);
    write_file_atomically(file, json.str());
  }
  if (wants(FrameFormat::dotlottie)) {
    report(out, animation_file_name(FrameFormat::dotlottie));
    frame_writers::write_dotlottie(world, state, out, ids, out.dir / animation_file_name(FrameFormat::dotlottie));
  }
  if (wants(FrameFormat::svg_anim)) {
    report(out, animation_file_name(FrameFormat::svg_anim));
    frame_writers::write_svg_animation(world, state, out, ids, out.dir / animation_file_name(FrameFormat::svg_anim));
  }
}

}  // namespace

PackingQuality write_frames(const World& world, const SimState& state, const FrameOutput& out) {
  auto wants = [&](FrameFormat f) { return std::find(out.formats.begin(), out.formats.end(), f) != out.formats.end(); };
  const std::filesystem::path frames = out.dir / "frames";
  const bool raster = wants(FrameFormat::png) || wants(FrameFormat::gif) || wants(FrameFormat::mp4);
  // frames/ holds the PNG and SVG frames; the animated vector formats alone leave no empty folder.
  std::filesystem::create_directories(raster || wants(FrameFormat::svg) ? frames : out.dir);
  const std::vector<std::string> ids = frame_writers::element_ids(world);
  PackingQuality quality;
  const std::vector<double> times = frame_times(out.count, world.loop);
  std::vector<std::vector<Vec2>> centroids(world.elements.size());
  // The curve's tangents depend on the state alone: solved once for every frame and time between slices.
  const std::vector<std::vector<Vec2>> tangents = frame_tangents(world, state);
  for (int i = 0; i < out.count; ++i) {
    // One replay per frame, drawn, written and measured by every format alike.
    const std::vector<ElementArt> art = frame_art(world, state, times[i], tangents);
    for (std::size_t e = 0; e < centroids.size(); ++e) centroids[e].push_back(art_centroid(art[e]));
    if (raster) draw_frame(world, art, out.style).write(frames / frame_name(i, "png"));
    if (wants(FrameFormat::svg)) write_svg(world, art, out.style, ids, frames / frame_name(i, "svg"));
    quality.frames.push_back(measure_frame(world, art, times[i]));
    report(out, "frame", i + 1, out.count);
  }
  quality.motion = measure_motion(world, state, centroids, times);
  write_animations(world, state, out, ids, wants);
  report(out, "between slices");
  for (double t : between_slice_times(world.params.element.slices))
    quality.between_slices.push_back(
        measure_frame(world, frame_art(world, state, t, tangents), t, Measures::no_evenness));
  std::ostringstream rate;
  rate << out.fps;
  const std::string input = "-framerate " + rate.str() + " -i " + quoted(frames / "frame_%04d.png");
  if (wants(FrameFormat::gif)) {
    report(out, "animation.gif");
    write_gif(input, out);
  }
  if (wants(FrameFormat::mp4)) {
    report(out, "animation.mp4");
    const auto mp4 = out.dir / "animation.mp4";
    run_ffmpeg(
        input + " -vf \"pad=ceil(iw/2)*2:ceil(ih/2)*2:color=white\" -c:v libx264 -pix_fmt yuv420p " + quoted(mp4), mp4);
  }
  return quality;
}

}  // namespace animpak
