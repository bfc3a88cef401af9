// Inline SVG line plots (svg_plot.hpp).
#include "svg_plot.hpp"

#include "animpak/report.hpp"  // report_number

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "animpak/xml_text.hpp"

namespace animpak {

const char* const kPlotStyle = R"(
svg.plot{background:#fff;border:1px solid #ddd}
svg.plot .title{font-size:13px;font-weight:600;fill:#333}svg.plot .tick,svg.plot .label{font-size:11px;fill:#555}
svg.plot .legend{font-size:11px}svg.plot .grid{stroke:#eee}svg.plot .axis{stroke:#999}
svg.plot polyline{fill:none;stroke-width:1.6}svg.plot polyline.extra{stroke-width:1;opacity:.7}
svg.plot polyline.reference{stroke-dasharray:5 4;stroke-width:1.2}svg.plot .cursor{stroke:#c33;stroke-width:1}
)";

double tick_step(double range, int count) {
  const double raw = range / count, power = std::pow(10.0, std::floor(std::log10(raw))), f = raw / power;
  return (f < 1.5 ? 1.0 : f < 3.5 ? 2.0 : f < 7.5 ? 5.0 : 10.0) * power;
}

// An inline SVG line plot: axes with round ticks, one polyline per run of values (a null breaks the line),
// the main series' points as dots, a legend; a hidden cursor line the page's script moves to a frame time.
std::string plot(const PlotSpec& spec, const std::vector<Series>& series) {
  constexpr double W = 440, H = 230, left = 54, right = 14, top = 30, bottom = 40;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Series& s : series)
    for (const auto& y : s.y)
      if (y && std::isfinite(*y)) lo = std::min(lo, *y), hi = std::max(hi, *y);
  if (!std::isfinite(lo)) lo = 0.0, hi = 1.0;
  if (spec.y_floor) lo = std::min(lo, *spec.y_floor);
  if (hi - lo < 1e-12) {
    const double pad = std::max(std::abs(hi) * 0.1, 0.05);
    lo -= pad, hi += pad;
  }
  const double step = tick_step(hi - lo, 4);
  lo = std::floor(lo / step + 1e-9) * step, hi = std::ceil(hi / step - 1e-9) * step;
  // On a log axis x is placed by its logarithm.
  const auto tx = [&](double x) { return spec.log_x ? std::log10(x) : x; };
  const double xs = (W - left - right) / (tx(spec.x_max) - tx(spec.x_min)), ys = (H - top - bottom) / (hi - lo);
  const auto px = [&](double x) { return left + (tx(x) - tx(spec.x_min)) * xs; };
  const auto py = [&](double y) { return H - bottom - (y - lo) * ys; };
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(2);
  out << "<svg class=\"plot\" id=\"" << spec.id << "\" viewBox=\"0 0 " << W << ' ' << H << "\" width=\"" << W
      << "\" height=\"" << H << "\" role=\"img\" aria-label=\"" << xml_escaped(spec.title) << "\"";
  if (spec.time_axis)
    out << " data-time=\"1\" data-x0=\"" << px(spec.x_min) << "\" data-x1=\"" << px(spec.x_max) << "\"";
  out << ">\n<text class=\"title\" x=\"" << left << "\" y=\"16\">" << xml_escaped(spec.title) << "</text>\n";
  // Grid and ticks.
  for (double y = lo; y <= hi + step * 1e-6; y += step) {
    out << "<line class=\"grid\" x1=\"" << left << "\" x2=\"" << W - right << "\" y1=\"" << py(y) << "\" y2=\"" << py(y)
        << "\"/><text class=\"tick\" x=\"" << left - 6 << "\" y=\"" << py(y) + 4 << "\" text-anchor=\"end\">"
        << report_number(y, step < 1 ? int(std::ceil(-std::log10(step) - 1e-9)) : 0) << "</text>\n";
  }
  if (spec.log_x) {
    for (int k = int(std::ceil(std::log10(spec.x_min) - 1e-9)); k <= int(std::floor(std::log10(spec.x_max) + 1e-9));
         ++k)
      out << "<text class=\"tick\" x=\"" << px(std::pow(10.0, k)) << "\" y=\"" << H - bottom + 16
          << "\" text-anchor=\"middle\">" << report_number(std::pow(10.0, k), std::max(0, -k)) << "</text>\n";
  } else {
    const double xstep = tick_step(spec.x_max - spec.x_min, 4);
    for (double x = std::ceil(spec.x_min / xstep - 1e-9) * xstep; x <= spec.x_max + xstep * 1e-6; x += xstep)
      out << "<text class=\"tick\" x=\"" << px(x) << "\" y=\"" << H - bottom + 16 << "\" text-anchor=\"middle\">"
          << report_number(x, xstep < 1 ? int(std::ceil(-std::log10(xstep) - 1e-9)) : 0) << "</text>\n";
  }
  out << "<line class=\"axis\" x1=\"" << left << "\" x2=\"" << left << "\" y1=\"" << top - 4 << "\" y2=\"" << H - bottom
      << "\"/><line class=\"axis\" x1=\"" << left << "\" x2=\"" << W - right << "\" y1=\"" << H - bottom << "\" y2=\""
      << H - bottom << "\"/>\n";
  out << "<text class=\"label\" x=\"" << (left + W - right) / 2 << "\" y=\"" << H - 6 << "\" text-anchor=\"middle\">"
      << xml_escaped(spec.x_label) << "</text><text class=\"label\" transform=\"translate(13 " << (top + H - bottom) / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << xml_escaped(spec.y_label) << "</text>\n";
  double legend_x = W - right;
  for (auto s = series.rbegin(); s != series.rend(); ++s) {
    out << "<text class=\"legend\" x=\"" << legend_x << "\" y=\"16\" text-anchor=\"end\" fill=\"" << s->color << "\">"
        << xml_escaped(s->name) << "</text>\n";
    legend_x -= 7.0 * double(s->name.size()) + 12.0;
  }
  for (const Series& s : series) {
    std::ostringstream points;
    points.setf(std::ios::fixed);
    points.precision(2);
    int run = 0;
    const auto flush = [&] {
      if (run > 0)
        out << "<polyline class=\"series " << s.role << "\" data-series=\"" << xml_escaped(s.name) << "\" stroke=\""
            << s.color << "\" points=\"" << points.str() << "\"/>\n";
      points.str("");
      run = 0;
    };
    for (std::size_t i = 0; i < s.y.size() && i < s.x.size(); ++i) {
      if (!s.y[i] || !std::isfinite(*s.y[i])) {
        flush();
        continue;
      }
      points << (run ? " " : "") << px(s.x[i]) << ',' << py(*s.y[i]);
      ++run;
    }
    flush();
    if (s.role == "main" && s.y.size() <= 200)
      for (std::size_t i = 0; i < s.y.size() && i < s.x.size(); ++i)
        if (s.y[i] && std::isfinite(*s.y[i]))
          out << "<circle class=\"dot\" cx=\"" << px(s.x[i]) << "\" cy=\"" << py(*s.y[i]) << "\" r=\"1.8\" fill=\""
              << s.color << "\"/>";
    out << "\n";
  }
  const bool empty = std::none_of(series.begin(), series.end(), [](const Series& s) {
    return s.role != "reference" && std::any_of(s.y.begin(), s.y.end(), [](const auto& y) { return y.has_value(); });
  });
  if (empty)
    out << "<text class=\"label empty\" x=\"" << (left + W - right) / 2 << "\" y=\"" << (top + H - bottom) / 2
        << "\" text-anchor=\"middle\">" << xml_escaped(spec.empty_note) << "</text>\n";
  if (spec.time_axis)
    out << "<line class=\"cursor\" x1=\"0\" x2=\"0\" y1=\"" << top - 4 << "\" y2=\"" << H - bottom
        << "\" visibility=\"hidden\"/>\n";
  out << "</svg>\n";
  return out.str();
}

std::string report_number(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", std::max(decimals, 0), value);
  std::string digits = text, sign;
  // No "-0.0": a value that rounds to zero has no sign.
  if (digits[0] == '-') {
    digits = digits.substr(1);
    if (digits.find_first_not_of("0.") != std::string::npos) sign = "-";
  }
  const std::size_t point = std::min(digits.find('.'), digits.size());
  std::string grouped;
  for (std::size_t i = 0; i < point; ++i) {
    if (i > 0 && (point - i) % 3 == 0) grouped += ',';
    grouped += digits[i];
  }
  return sign + grouped + digits.substr(point);
}

}  // namespace animpak
