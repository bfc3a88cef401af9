// The picture `animpak render --contact-plot` writes: every frame's spherical contact function H(r), r in
// element radii, thin and light, and their mean bold (docs/quality.md, "Evenness"). The picture's world is
// its own pixel grid, so the data-to-pixel mapping (y up) is done here and Picture only draws.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "animpak/render.hpp"

namespace animpak {
namespace {

constexpr int plot_width = 640, plot_height = 420;
constexpr double margin_left = 64, margin_right = 24, margin_top = 40, margin_bottom = 56;  // around the axes, pixels
constexpr Rgba axis_ink{0.15, 0.15, 0.15, 1}, grid_ink{0.88, 0.88, 0.88, 1};
constexpr Rgba frame_ink{0.55, 0.68, 0.88, 0.5}, mean_ink{0.12, 0.39, 0.75, 1};

std::string tick_label(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%g", v);
  return s;
}

struct Axes {
  double x_max;
  Vec2 at(double x, double y) const {
    return {margin_left + (plot_width - margin_left - margin_right) * x / x_max,
            plot_height - margin_bottom - (plot_height - margin_top - margin_bottom) * y};
  }
};

void draw_axes(Picture& pic, const Axes& a) {
  const double xs = a.x_max > 2.0 ? 0.5 : 0.25;
  for (double x = 0; x <= a.x_max * (1 + 1e-9); x += xs) {
    pic.draw_polyline({a.at(x, 0), a.at(x, 1)}, grid_ink, 1.0);
    pic.draw_text(a.at(x, 0) + Vec2{0, 8}, tick_label(x), 13, axis_ink, {0.5, 0.0});
  }
  for (int k = 0; k <= 5; ++k) {
    pic.draw_polyline({a.at(0, k / 5.0), a.at(a.x_max, k / 5.0)}, grid_ink, 1.0);
    pic.draw_text(a.at(0, k / 5.0) - Vec2{8, 0}, tick_label(k / 5.0), 13, axis_ink, {1.0, 0.5});
  }
  pic.draw_polyline({a.at(0, 1), a.at(0, 0), a.at(a.x_max, 0)}, axis_ink, 1.5);
  pic.draw_text(a.at(a.x_max / 2, 0) + Vec2{0, 30}, "r / element radius", 15, axis_ink, {0.5, 0.0});
  pic.draw_text({margin_left, margin_top - 14}, "H(r): share of the container farther than r from art and wall", 14,
                axis_ink, {0.0, 1.0});
}

std::vector<Vec2> curve(const Axes& a, const std::vector<double>& h) {
  std::vector<Vec2> px;
  for (std::size_t k = 0; k < h.size(); ++k) px.push_back(a.at(double(k) * contact_step, h[k]));
  return px;
}

}  // namespace

void write_contact_plot(const std::vector<FrameMetrics>& frames, const std::filesystem::path& file) {
  const std::vector<double> mean = mean_contact(frames);
  // The last sample is H's first 0; the axis ends on the next half radius.
  const double r_max = mean.size() > 1 ? double(mean.size() - 1) * contact_step : 1.0;
  const Axes axes{std::max(0.5, std::ceil(r_max * 2.0) / 2.0)};
  Box pixels;
  pixels.add({0, 0});
  pixels.add({double(plot_width), double(plot_height)});
  Picture pic(plot_width, plot_height, pixels, {1, 1, 1, 1}, 0.0);
  draw_axes(pic, axes);
  for (const FrameMetrics& m : frames) pic.draw_polyline(curve(axes, m.contact), frame_ink, 1.0);
  pic.draw_polyline(curve(axes, mean), mean_ink, 2.5);
  pic.write(file);
}

}  // namespace animpak
