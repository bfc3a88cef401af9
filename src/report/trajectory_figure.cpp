// The trajectory figure (animpak/report.hpp): SVG text written here, plots by svg_plot.hpp.
#include "animpak/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <sstream>

#include "animpak/error.hpp"
#include "animpak/xml_text.hpp"
#include "svg_plot.hpp"

namespace animpak {
namespace {

// Colours told apart by colour-blind readers too (blue, orange, then green, purple, grey).
const char* const kRunColors[] = {"#1f6fb2", "#e8710a", "#2a9d55", "#7b3fa0", "#666666"};

const char* run_color(std::size_t run) { return kRunColors[std::min<std::size_t>(run, std::size(kRunColors) - 1)]; }

double percentile(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  const double at = q * double(values.size() - 1);
  const std::size_t lo = std::size_t(std::floor(at)), hi = std::min(lo + 1, values.size() - 1);
  return values[lo] + (values[hi] - values[lo]) * (at - double(lo));
}

}  // namespace

TrajectoryStats trajectory_stats(const TrajectoryRun& run, double width, bool loop) {
  const std::size_t n = run.path.size();
  if (n < 3 || run.t.size() != n) throw InputError("trajectory: at least three times are needed (--samples)");
  const double dt = loop ? 1.0 / double(n) : (run.t.back() - run.t.front()) / double(n - 1);
  for (std::size_t i = 1; i < n; ++i)
    if (std::abs(run.t[i] - run.t[i - 1] - dt) > 1e-9)
      throw InputError("trajectory: the times are not evenly spaced over the loop");
  TrajectoryStats stats;
  const double unit = width > 0.0 ? 1.0 / width : 1.0;
  for (std::size_t i = 1; i < n; ++i) stats.length += norm(run.path[i] - run.path[i - 1]) * unit;
  const Vec2 after = run.after.value_or(run.path.front()), before = run.before.value_or(run.path.back());
  if (loop) stats.length += norm(after - run.path.back()) * unit;
  std::vector<double> acceleration;
  for (std::size_t i = 0; i < n; ++i) {
    if (!loop && (i == 0 || i + 1 == n)) continue;
    const Vec2 prev = i == 0 ? before : run.path[i - 1], next = i + 1 == n ? after : run.path[i + 1];
    acceleration.push_back(norm(next - run.path[i] * 2.0 + prev) * unit / (dt * dt));
  }
  stats.acceleration_median = percentile(acceleration, 0.5);
  stats.acceleration_p99 = percentile(acceleration, 0.99);
  return stats;
}

namespace {

// A coordinate as SVG reads it: fixed decimals, no thousands separator (report_number's commas would
// split a points list).
std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// Maps a box of the frames' coordinates into a pixel rectangle, keeping the aspect, centred.
struct ViewMap {
  Box box;
  double scale = 1.0, ox = 0.0, oy = 0.0;
  ViewMap(const Box& b, double x, double y, double w, double h) : box(b) {
    const double bw = std::max(b.width(), 1e-9), bh = std::max(b.height(), 1e-9);
    scale = std::min(w / bw, h / bh);
    ox = x + (w - bw * scale) / 2, oy = y + (h - bh * scale) / 2;
  }
  std::string point(Vec2 p) const {
    return fixed(ox + (p.x - box.min.x) * scale, 2) + ',' + fixed(oy + (p.y - box.min.y) * scale, 2);
  }
  std::string points(const std::vector<Vec2>& list, bool closed) const {
    std::string text;
    for (const Vec2& p : list) text += (text.empty() ? "" : " ") + point(p);
    if (closed && !list.empty()) text += " " + point(list.front());
    return text;
  }
};

// The box grown by `fraction` of its longer side on every side.
Box padded(Box b, double fraction) {
  const double pad = fraction * std::max({b.width(), b.height(), 1e-9});
  b.min = {b.min.x - pad, b.min.y - pad}, b.max = {b.max.x + pad, b.max.y + pad};
  return b;
}

}  // namespace

std::string trajectory_svg(const TrajectoryFigure& figure) {
  Box whole, near;
  for (const Vec2& p : figure.outline) whole.add(p);
  for (const TrajectoryRun& run : figure.runs) {
    for (const Vec2& p : run.path) whole.add(p), near.add(p);
    for (const auto& line : run.outline_at_0)
      for (const Vec2& p : line) near.add(p);
  }
  if (whole.empty()) throw InputError("trajectory: nothing to draw (no container outline and no path)");
  Box container;
  for (const Vec2& p : figure.outline) container.add(p);
  const double unit = container.empty() ? whole.width() : container.width();  // the statistics' container width
  // A path that keeps to a small part of the container is drawn close up, the whole container beside it.
  near = padded(near, 0.08);
  const bool close_up = !near.empty() && near.width() < 0.6 * whole.width() && near.height() < 0.6 * whole.height();

  constexpr double panel = 470, gap = 14, plot_w = 440, plot_h = 230, title_h = 30, line_h = 20, pad = 10;
  constexpr double inset = 130, head = 22;
  const Box& shown = close_up ? near : whole;
  const double view_w = std::clamp(panel * shown.width() / std::max(shown.height(), 1e-9), 300.0, 620.0);
  const ViewMap view(shown, pad, head, view_w - 2 * pad, panel - head - pad);
  const double W = view_w + gap + plot_w, H = title_h + panel + 12 + line_h * double(figure.runs.size()) + 8;

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " << fixed(W, 0) << ' ' << fixed(H, 0)
      << "\" width=\"" << fixed(W, 0) << "\" height=\"" << fixed(H, 0)
      << "\" font-family=\"system-ui,-apple-system,'Segoe UI',sans-serif\">\n<style>" << kPlotStyle
      << "svg.view .container{fill:none;stroke:#999;stroke-width:1}svg.view .path{fill:none;stroke-width:1.6}"
         "svg.view .art{fill:none;stroke-width:.8;opacity:.3}svg.view .zoom{fill:none;stroke:#c33;stroke-width:1}"
         ".stats{font-size:12px;fill:#333}.heading{font-size:15px;font-weight:600;fill:#222}</style>\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"#fafafa\"/>\n<text class=\"heading\" x=\"4\" y=\"20\">"
      << xml_escaped(figure.element) << ": its path through the loop</text>\n";

  // The top view: container, paths, the element's art at t = 0 and a dot where it starts; close up, with
  // the whole container in a corner and the close-up's box marked on it.
  const auto draw_runs = [&](const ViewMap& map, bool with_art, double dot) {
    for (std::size_t r = 0; r < figure.runs.size(); ++r) {
      const TrajectoryRun& run = figure.runs[r];
      if (with_art)
        for (const auto& line : run.outline_at_0)
          svg << "<polyline class=\"art\" data-run=\"" << r << "\" stroke=\"" << run_color(r) << "\" points=\""
              << map.points(line, false) << "\"/>\n";
      std::vector<Vec2> path = run.path;
      if (figure.loop && !path.empty()) path.push_back(run.after.value_or(path.front()));
      svg << "<polyline class=\"path\" data-run=\"" << r << "\" stroke=\"" << run_color(r) << "\" points=\""
          << map.points(path, false) << "\"/>\n";
      if (!run.path.empty()) {
        const std::string start = map.point(run.path.front());
        const std::size_t comma = start.find(',');
        svg << "<circle cx=\"" << start.substr(0, comma) << "\" cy=\"" << start.substr(comma + 1) << "\" r=\"" << dot
            << "\" fill=\"" << run_color(r) << "\"/>\n";
      }
    }
  };
  svg << "<svg class=\"view plot\" id=\"view\" x=\"0\" y=\"" << title_h << "\" width=\"" << fixed(view_w, 2)
      << "\" height=\"" << panel << "\" viewBox=\"0 0 " << fixed(view_w, 2) << ' ' << panel
      << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"#fff\" stroke=\"#ddd\"/>\n"
      << "<text class=\"title\" x=\"8\" y=\"16\">"
      << (close_up ? "close up, seen from above (frames' coordinates)" : "seen from above (frames' coordinates)")
      << "</text>\n<svg x=\"0\" y=\"" << head << "\" width=\"" << fixed(view_w, 2) << "\" height=\"" << panel - head
      << "\" viewBox=\"0 " << head << ' ' << fixed(view_w, 2) << ' ' << panel - head
      << "\">\n";  // clips the close-up's container outline to the panel
  svg << "<polyline class=\"container\" points=\"" << view.points(figure.outline, true) << "\"/>\n";
  for (const auto& hole : figure.holes)
    svg << "<polyline class=\"container\" points=\"" << view.points(hole, true) << "\"/>\n";
  draw_runs(view, true, 3.0);
  svg << "</svg>\n";
  if (close_up) {
    const double x0 = view_w - inset - 6, y0 = panel - inset - 6;
    const ViewMap map(whole, x0 + 4, y0 + 4, inset - 8, inset - 8);
    svg << "<g class=\"inset\"><rect x=\"" << fixed(x0, 2) << "\" y=\"" << fixed(y0, 2) << "\" width=\"" << inset
        << "\" height=\"" << inset << "\" fill=\"#fff\" stroke=\"#bbb\"/>\n"
        << "<polyline class=\"container\" points=\"" << map.points(figure.outline, true) << "\"/>\n";
    for (const auto& hole : figure.holes)
      svg << "<polyline class=\"container\" points=\"" << map.points(hole, true) << "\"/>\n";
    draw_runs(map, false, 1.5);
    svg << "<polyline class=\"zoom\" points=\""
        << map.points({near.min, {near.max.x, near.min.y}, near.max, {near.min.x, near.max.y}}, true) << "\"/></g>\n";
  }
  svg << "</svg>\n";

  // x(t) and y(t), one line per run.
  std::vector<Series> xs, ys;
  for (std::size_t r = 0; r < figure.runs.size(); ++r) {
    const TrajectoryRun& run = figure.runs[r];
    Series x{run.label, run.t, {}, run_color(r)}, y{run.label, run.t, {}, run_color(r)};
    for (const Vec2& p : run.path) x.y.push_back(p.x), y.y.push_back(p.y);
    xs.push_back(std::move(x)), ys.push_back(std::move(y));
  }
  const auto placed = [&](const std::string& text, double y) {
    // plot() writes a standalone <svg>; placing it needs x and y on that element.
    return "<g transform=\"translate(" + fixed(view_w + gap, 2) + " " + fixed(y, 2) + ")\">" + text + "</g>\n";
  };
  svg << placed(plot({"plot-x", "x against time", "time t (loops)", "x", 0.0, 1.0, false, std::nullopt, "no path"}, xs),
                title_h);
  svg << placed(plot({"plot-y", "y against time (y grows downwards)", "time t (loops)", "y", 0.0, 1.0, false,
                      std::nullopt, "no path"},
                     ys),
                title_h + panel - plot_h);

  // One legend line per run, with its statistics.
  double y = title_h + panel + 12 + 14;
  for (std::size_t r = 0; r < figure.runs.size(); ++r, y += line_h) {
    const TrajectoryStats stats = trajectory_stats(figure.runs[r], unit, figure.loop);
    svg << "<rect x=\"4\" y=\"" << y - 10 << "\" width=\"12\" height=\"12\" fill=\"" << run_color(r)
        << "\"/><text class=\"stats\" x=\"22\" y=\"" << y << "\" data-run=\"" << r << "\">"
        << xml_escaped(figure.runs[r].label) << ": path " << report_number(stats.length, 2)
        << " container widths per loop; acceleration median " << report_number(stats.acceleration_median, 1)
        << ", 99th percentile " << report_number(stats.acceleration_p99, 1) << " container widths per loop²</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace animpak
