#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "animpak/error.hpp"
#include "animpak/render.hpp"

namespace animpak {
namespace {

std::string frame_name(int i, const char* ext) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.%s", i, ext);
  return name;
}

std::string hex(Rgba c) {
  char s[8];
  auto channel = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
  std::snprintf(s, sizeof s, "#%02x%02x%02x", channel(c.r), channel(c.g), channel(c.b));
  return s;
}

// One SVG frame in unit coordinates: every element's paths replayed, with their paint.
void write_svg(const World& world, const SimState& state, double tf, const FrameStyle& style,
               const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) throw InputError(file.string() + ": cannot write; check that the folder is writable");
  out << std::setprecision(6);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 1 1\" width=\"" << style.size << "\" height=\""
      << style.size << "\">\n<rect width=\"1\" height=\"1\" fill=\"" << hex(style.background) << "\"/>\n";
  for (std::size_t i = 0; i < world.elements.size(); ++i) {
    const SpacetimeElement& lib = world.library[world.elements[i].library];
    const std::vector<Vec2> positions = element_at(world, state, int(i), tf);
    const double stroke_scale = element_scale(world, int(i), positions);
    const ArtPoints points = replay_art(lib.binding, lib.slice, positions);
    for (std::size_t p = 0; p < lib.art.art.paths.size(); ++p) {
      const ArtPath& path = lib.art.art.paths[p];
      out << "<path d=\"";
      for (std::size_t q = 0; q < points[p].size(); ++q) {
        for (std::size_t k = 0; k < points[p][q].size(); ++k)
          out << (k ? " L" : "M") << points[p][q][k].x << ' ' << points[p][q][k].y;
        if (path.polylines[q].closed) out << " Z";
      }
      out << "\" fill=\"" << (path.fill.enabled ? hex(path.fill.color) : "none") << "\"";
      if (path.fill.enabled && path.fill.color.a < 1) out << " fill-opacity=\"" << path.fill.color.a << "\"";
      if (path.fill_rule == FillRule::evenodd) out << " fill-rule=\"evenodd\"";
      if (path.stroke.enabled && path.stroke_width > 0)
        out << " stroke=\"" << hex(path.stroke.color) << "\" stroke-width=\"" << path.stroke_width * stroke_scale
            << "\" stroke-linejoin=\"round\"";
      if (path.paint_order == PaintOrder::stroke_then_fill) out << " paint-order=\"stroke\"";
      out << "/>\n";
    }
  }
  out << "</svg>\n";
  if (!out) throw InputError(file.string() + ": writing failed; check free disk space");
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
}

std::string quoted(const std::filesystem::path& p) {
  std::string s = "'";
  for (char c : p.string()) s += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return s + "'";
}

}  // namespace

std::vector<FrameMetrics> write_frames(const World& world, const SimState& state, const FrameOutput& out) {
  auto wants = [&](FrameFormat f) { return std::find(out.formats.begin(), out.formats.end(), f) != out.formats.end(); };
  const std::filesystem::path frames = out.dir / "frames";
  std::filesystem::create_directories(frames);
  const bool raster = wants(FrameFormat::png) || wants(FrameFormat::gif) || wants(FrameFormat::mp4);
  std::vector<FrameMetrics> metrics;
  const std::vector<double> times = frame_times(out.count, world.loop);
  for (int i = 0; i < out.count; ++i) {
    if (raster) draw_frame(world, state, times[i], out.style).write(frames / frame_name(i, "png"));
    if (wants(FrameFormat::svg)) write_svg(world, state, times[i], out.style, frames / frame_name(i, "svg"));
    metrics.push_back(measure_frame(world, state, times[i]));
  }
  std::ostringstream rate;
  rate << out.fps;
  const std::string input = "-framerate " + rate.str() + " -i " + quoted(frames / "frame_%04d.png");
  if (wants(FrameFormat::gif)) {
    const auto gif = out.dir / "animation.gif";
    run_ffmpeg(input + " -filter_complex \"[0:v]split[a][b];[a]palettegen=reserve_transparent=0[p];[b][p]paletteuse\" " +
                   "-loop 0 " + quoted(gif),
               gif);
  }
  if (wants(FrameFormat::mp4)) {
    const auto mp4 = out.dir / "animation.mp4";
    run_ffmpeg(input + " -vf \"pad=ceil(iw/2)*2:ceil(ih/2)*2:color=white\" -c:v libx264 -pix_fmt yuv420p " + quoted(mp4),
               mp4);
  }
  return metrics;
}

}  // namespace animpak
