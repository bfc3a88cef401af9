// The benchmark plot: ms per step against vertices. The picture's world is its own pixel grid, so
// the data-to-pixel mapping (y up) is done here and Picture only draws.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "animpak/render.hpp"
#include "animpak/report.hpp"

// LeakSanitizer reads this hook when it is linked in (sanitizer builds) and ignores it otherwise:
// fontconfig, loaded once by Cairo's toy text API, keeps its configuration for the process lifetime.
extern "C" const char* __lsan_default_suppressions() { return "leak:libfontconfig.so\n"; }

namespace animpak {
namespace {

constexpr int width = 960, height = 560;
constexpr double left = 80, right = 240, top = 40, bottom = 60;  // margins around the axes, pixels
constexpr Rgba ink{0.15, 0.15, 0.15, 1}, grid_ink{0.88, 0.88, 0.88, 1};
constexpr Rgba line_colours[] = {{0.12, 0.39, 0.75, 1}, {0.85, 0.33, 0.1, 1}, {0.2, 0.6, 0.25, 1},
                                 {0.55, 0.25, 0.65, 1}, {0.8, 0.6, 0.1, 1},   {0.1, 0.6, 0.65, 1}};
constexpr Rgba example_colour{0.45, 0.45, 0.45, 1};

// A 1-2-5 tick step giving about five ticks over [0, max].
double tick_step(double max) {
  const double raw = std::max(max, 1e-12) / 5.0;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * decade >= raw) return m * decade;
  return 10.0 * decade;
}

std::string number(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%g", v);
  return s;
}

struct Axes {
  double x_max, y_max;
  Vec2 at(double x, double y) const {
    return {left + (width - left - right) * x / x_max, height - bottom - (height - top - bottom) * y / y_max};
  }
};

void draw_axes(Picture& pic, const Axes& a) {
  const double xs = tick_step(a.x_max), ys = tick_step(a.y_max);
  for (double x = 0; x <= a.x_max * (1 + 1e-9); x += xs) {
    pic.draw_polyline({a.at(x, 0), a.at(x, a.y_max)}, grid_ink, 1.0);
    pic.draw_text(a.at(x, 0) + Vec2{0, 8}, (x == 0 ? std::string("0") : number(x / 1000.0) + "k"), 13, ink, {0.5, 0.0});
  }
  for (double y = 0; y <= a.y_max * (1 + 1e-9); y += ys) {
    pic.draw_polyline({a.at(0, y), a.at(a.x_max, y)}, grid_ink, 1.0);
    pic.draw_text(a.at(0, y) - Vec2{8, 0}, number(y), 13, ink, {1.0, 0.5});
  }
  pic.draw_polyline({a.at(0, a.y_max), a.at(0, 0), a.at(a.x_max, 0)}, ink, 1.5);
  pic.draw_text(a.at(a.x_max / 2, 0) + Vec2{0, 32}, "vertices", 15, ink, {0.5, 0.0});
  pic.draw_text({left, top - 12}, "ms per iteration", 15, ink, {0.5, 1.0});
}

void draw_square(Picture& pic, Vec2 c, Rgba colour) {
  const double r = 5;
  pic.draw_polyline({c + Vec2{-r, -r}, c + Vec2{r, -r}, c + Vec2{r, r}, c + Vec2{-r, r}, c + Vec2{-r, -r}}, colour,
                    2.0);
}

}  // namespace

void write_bench_plot(const std::vector<BenchRow>& rows, const std::filesystem::path& file) {
  Axes axes{1.0, 1e-3};  // not zero even with no rows, so the mapping stays finite
  for (const BenchRow& r : rows) {
    axes.x_max = std::max(axes.x_max, 1.05 * r.vertices);
    axes.y_max = std::max(axes.y_max, 1.1 * r.timing.ms_per_iter);
  }
  // Round the axes up to a whole tick so the last label sits on the corner.
  axes.x_max = std::ceil(axes.x_max / tick_step(axes.x_max)) * tick_step(axes.x_max);
  axes.y_max = std::ceil(axes.y_max / tick_step(axes.y_max)) * tick_step(axes.y_max);

  Box pixels;
  pixels.add({0, 0});
  pixels.add({double(width), double(height)});
  Picture pic(width, height, pixels, {1, 1, 1, 1}, 0.0);
  draw_axes(pic, axes);

  // One line per device and synthetic series ("reference, constant"), in row order.
  std::map<std::string, std::vector<Vec2>> lines;
  std::vector<std::string> order;
  for (const BenchRow& r : rows) {
    if (!r.synthetic()) continue;
    const std::string line = r.device + ", " + r.series;
    if (!lines.count(line)) order.push_back(line);
    lines[line].push_back({double(r.vertices), r.timing.ms_per_iter});
  }
  double legend_y = top + 10;
  const double legend_x = width - right + 20;
  for (std::size_t d = 0; d < order.size(); ++d) {
    const Rgba colour = line_colours[d % std::size(line_colours)];
    std::vector<Vec2> pts = lines[order[d]];
    std::sort(pts.begin(), pts.end(), [](Vec2 a, Vec2 b) { return a.x < b.x; });
    std::vector<Vec2> px;
    for (Vec2 p : pts) px.push_back(axes.at(p.x, p.y));
    pic.draw_polyline(px, colour, 2.0);
    pic.draw_dots(px, colour, 4.5);
    pic.draw_polyline({{legend_x, legend_y}, {legend_x + 24, legend_y}}, colour, 2.0);
    pic.draw_dots({{legend_x + 12, legend_y}}, colour, 4.5);
    pic.draw_text({legend_x + 32, legend_y}, order[d], 14, ink, {0.0, 0.5});
    legend_y += 24;
  }
  // Example scenes are all small, so their squares cluster: labels are stacked to stay readable.
  int examples = 0;
  for (const BenchRow& r : rows)
    if (!r.synthetic()) {
      const Vec2 c = axes.at(r.vertices, r.timing.ms_per_iter);
      draw_square(pic, c, example_colour);
      pic.draw_text(c + Vec2{8, -8.0 - 14.0 * examples}, r.scene + " (" + r.device + ")", 11, example_colour,
                    {0.0, 1.0});
      ++examples;
    }
  if (examples > 0) {
    draw_square(pic, {legend_x + 12, legend_y}, example_colour);
    pic.draw_text({legend_x + 32, legend_y}, "scenes", 14, ink, {0.0, 0.5});
  }
  pic.write(file);
}

}  // namespace animpak
