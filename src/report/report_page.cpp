// The HTML of `animpak report` (animpak/report.hpp): text and inline SVG only, so the page needs no network and
// no file beside it. Every figure is stats.json's, shown in an element whose data-stat names its path there
// (and data-scale the factor it is shown at), so that a test can hold the page to the file.
#include "animpak/report.hpp"

#include "svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <sstream>

#include "animpak/error.hpp"
#include "animpak/stats.hpp"
#include "animpak/xml_text.hpp"

namespace animpak {
namespace {

using nlohmann::json;

// JSON inside a <script> element: "</" would end the element early.
std::string script_json(const json& value) {
  std::string text = value.dump();
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3))
    text.replace(at, 2, "<\\/");
  return text;
}

// One figure of stats.json in a <span data-stat>: `value` (the figure at `path` there, read through the model)
// times `scale` with `decimals` decimals and `unit` after it, or a dash for none (the page then carries no
// number to compare).
std::string stat(std::optional<double> value, const std::string& path, int decimals, double scale = 1.0,
                 const std::string& unit = "") {
  if (value && !std::isfinite(*value)) value.reset();
  if (!value) return "<span class=\"none\" data-stat-none=\"" + xml_escaped(path) + "\">–</span>";
  std::ostringstream out;
  out << "<span data-stat=\"" << xml_escaped(path) << "\"";
  if (scale != 1.0) out << " data-scale=\"" << scale << "\"";
  out << ">" << report_number(*value * scale, decimals) << unit << "</span>";
  return out.str();
}

// A number that is none in the model (NaN) as none.
std::optional<double> finite(double v) { return std::isfinite(v) ? std::optional<double>(v) : std::nullopt; }

// A count the file may lack.
std::optional<double> count_of(const std::optional<std::int64_t>& v) {
  return v ? std::optional<double>(double(*v)) : std::nullopt;
}

std::string text_of(const std::optional<std::string>& value) { return value ? xml_escaped(*value) : "–"; }

// A level drawn across a time plot.
Series level(const std::string& name, double value, const std::string& color) {
  return {name, {0.0, 1.0}, {value, value}, color, "reference"};
}

std::string row(const std::string& label, const std::string& value, const std::string& note = "") {
  return "<tr><th>" + label + "</th><td>" + value + "</td><td class=\"note\">" + note + "</td></tr>\n";
}

const char* kStyle = R"(
body{font:15px/1.45 system-ui,-apple-system,"Segoe UI",sans-serif;margin:0 auto;max-width:1120px;padding:16px 24px 40px;color:#222;background:#fafafa}
h1{font-size:24px;margin:8px 0 2px}h2{font-size:18px;margin:28px 0 8px;border-bottom:1px solid #ddd;padding-bottom:4px}
.sub{color:#666;margin:0 0 12px}
#stage{display:flex;gap:24px;flex-wrap:wrap;align-items:flex-start}#summary{flex:1 1 420px;min-width:320px}
#animation{background:#fff;border:1px solid #ddd;padding:6px;flex:0 1 520px}
#animation svg,#animation img{display:block;width:100%;height:auto;max-height:70vh}
.controls{display:flex;gap:10px;align-items:center;margin-top:6px}.controls input{flex:1}
#readout{font-variant-numeric:tabular-nums;color:#444;min-height:1.4em;margin-top:4px}
table{border-collapse:collapse}th,td{text-align:left;padding:3px 12px 3px 0;vertical-align:middle}
th{font-weight:600;color:#333}td{font-variant-numeric:tabular-nums;white-space:nowrap}td.note{color:#777;font-size:13px;white-space:normal}
#plots{display:flex;flex-wrap:wrap;gap:12px}
#elements td svg{display:block}
code{font-size:13px}
)";

// The page's one script: play and pause the animated SVG, and a slider that stops it at a frame, shows that
// frame's figures and moves a cursor over every time plot.
const char* kScript = R"(
(function () {
  var data = JSON.parse(document.getElementById('frame-data').textContent);
  var svg = document.querySelector('#animation svg');
  var scrub = document.getElementById('scrub'), play = document.getElementById('play');
  var readout = document.getElementById('readout');
  if (!svg) play.style.display = 'none';  // a GIF stands in: it cannot be paused
  function fixed(v, d, s) { return v === null || v === undefined ? '–' : (v * (s || 1)).toFixed(d); }
  function show(i) {
    readout.textContent = 'frame ' + i + ', t = ' + data.t[i].toFixed(3) + ': coverage ' +
      fixed(data.coverage[i], 1, 100) + ' %, channel CV ' + fixed(data.channel[i], 2) +
      ', wall ratio ' + fixed(data.wall[i], 2) + ', kink ' + fixed(data.kink[i], 1);
    var plots = document.querySelectorAll('svg.plot[data-time]');
    for (var k = 0; k < plots.length; ++k) {
      var p = plots[k], c = p.querySelector('.cursor');
      var x = Number(p.dataset.x0) + (Number(p.dataset.x1) - Number(p.dataset.x0)) * data.t[i];
      c.setAttribute('x1', x); c.setAttribute('x2', x); c.setAttribute('visibility', 'visible');
    }
  }
  function frameNow() {
    return data.frame_seconds > 0 ? Math.floor(svg.getCurrentTime() / data.frame_seconds + 1e-6) % data.t.length : 0;
  }
  scrub.addEventListener('input', function () {
    if (svg && svg.pauseAnimations) { svg.pauseAnimations(); svg.setCurrentTime(Number(scrub.value) * data.frame_seconds); }
    play.textContent = 'Play';
    show(Number(scrub.value));
  });
  play.addEventListener('click', function () {
    if (!svg || !svg.pauseAnimations) return;
    if (svg.animationsPaused()) { svg.unpauseAnimations(); play.textContent = 'Pause'; }
    else { svg.pauseAnimations(); play.textContent = 'Play'; scrub.value = frameNow(); show(frameNow()); }
  });
  // While it plays, the readout and the cursors follow the animation.
  function follow() {
    if (svg && svg.animationsPaused && !svg.animationsPaused()) { var i = frameNow(); scrub.value = i; show(i); }
    window.requestAnimationFrame(follow);
  }
  show(0);
  window.requestAnimationFrame(follow);
  document.body.dataset.ready = 'yes';
})();
)";

}  // namespace

std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const unsigned a = static_cast<unsigned char>(bytes[i]),
                   b = i + 1 < bytes.size() ? static_cast<unsigned char>(bytes[i + 1]) : 0u,
                   c = i + 2 < bytes.size() ? static_cast<unsigned char>(bytes[i + 2]) : 0u;
    const unsigned v = a << 16 | b << 8 | c;
    out += digits[v >> 18 & 63];
    out += digits[v >> 12 & 63];
    out += i + 1 < bytes.size() ? digits[v >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? digits[v & 63] : '=';
  }
  return out;
}

std::string report_page(const ReportInput& input) {
  const Stats& stats = input.stats;
  if (!stats.frames || stats.frames->empty())
    throw InputError(
        "stats.json: no frames (packed with --no-render, or by animpak-solve); run `animpak render DIR` first, "
        "which measures the frames the report plots");
  const std::vector<StatsFrame>& frames = *stats.frames;
  const std::size_t n = frames.size();
  std::vector<double> t(n);
  std::vector<std::optional<double>> coverage(n), channel(n), wall(n), kink(n);
  const std::optional<StatsMotion>& motion = stats.motion;
  const std::optional<double> median = motion ? finite(motion->acceleration_median) : std::nullopt;
  for (std::size_t i = 0; i < n; ++i) {
    t[i] = std::isfinite(frames[i].t) ? frames[i].t : double(i) / double(n);
    coverage[i] = finite(frames[i].coverage);
    channel[i] = finite(frames[i].channel_cv);
    if (frames[i].evenness) wall[i] = finite(frames[i].evenness->wall_ratio);
    if (motion && motion->frame_peak && i < motion->frame_peak->size() && std::isfinite((*motion->frame_peak)[i]) &&
        median && *median > 0.0)
      kink[i] = (*motion->frame_peak)[i] / *median;
  }
  const double t_max = std::max(1.0, t.empty() ? 1.0 : t.back());
  const std::optional<StatsQuality>& quality = stats.quality;
  const StatsSummary no_summary;
  const StatsSummary& fq = quality ? quality->frames : no_summary;
  const StatsSummary& bq = quality ? quality->between_slices : no_summary;
  // A summary figure, none when the file has no quality; an evenness figure, none when it has no evenness.
  const auto q = [&](double value) { return quality ? finite(value) : std::nullopt; };
  const auto fe = [&](double StatsEvennessSummary::*member) {
    return quality && fq.evenness ? finite((*fq.evenness).*member) : std::nullopt;
  };

  std::ostringstream page;
  page << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
       << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
       << "<title>animpak report: " << xml_escaped(input.title) << "</title><style>" << kStyle << kPlotStyle
       << "</style></head>\n<body>\n";
  page << "<h1>" << xml_escaped(input.title) << "</h1>\n<p class=\"sub\">" << stats.elements << " elements, "
       << stat(double(stats.vertices), "vertices", 0) << " vertices, packed in "
       << stat(double(stats.iterations), "iterations", 0) << " iterations by animpak " << xml_escaped(stats.animpak)
       << " on " << text_of(stats.device) << "</p>\n";

  // The animation and the slider.
  page << "<div id=\"stage\"><div id=\"animation-box\" style=\"flex:0 1 540px\"><div id=\"animation\">\n"
       << (input.animation_gif.empty()
               ? input.animation_svg
               : "<img id=\"animation-gif\" alt=\"the animation\" src=\"data:image/gif;base64," +
                     base64(input.animation_gif) + "\">")
       << "\n</div>\n"
       << (input.animation_note.empty()
               ? ""
               : "<p class=\"note\" id=\"animation-note\">" + xml_escaped(input.animation_note) + "</p>")
       << "<div class=\"controls\"><button id=\"play\" type=\"button\">Pause</button>"
       << "<input id=\"scrub\" type=\"range\" min=\"0\" max=\"" << n - 1 << "\" value=\"0\" aria-label=\"frame\">"
       << "</div><div id=\"readout\"></div></div>\n";

  // The summary: docs/quality.md says what each figure means; each data-stat is the figure's path in stats.json.
  const std::string fp = "quality.frames.", bp = "quality.between_slices.";
  const std::optional<StatsStillReference>& still = stats.still_reference;
  page << "<div id=\"summary\"><h2 style=\"margin-top:0\">Quality</h2><table>\n"
       << row("coverage",
              stat(q(fq.coverage_mean), fp + "coverage.mean", 1, 100, " %") + " (" +
                  stat(q(fq.coverage_min), fp + "coverage.min", 1, 100, " %") + " – " +
                  stat(q(fq.coverage_max), fp + "coverage.max", 1, 100, " %") + ")",
              "mean over the frames (lowest – highest)");
  if (still && std::isfinite(still->mean_over_still))
    page << row(
        "against standing still", stat(still->mean_over_still, "still_reference.mean_over_still", 2),
        "mean coverage over the still packing's " + stat(still->coverage, "still_reference.coverage", 1, 100, " %"));
  page << row("art outside",
              stat(q(double(fq.element_frames_outside)), fp + "element_frames_outside", 0) + " of " +
                  stat(q(double(fq.element_frames)), fp + "element_frames", 0),
              "element-frames; between slices " +
                  stat(q(double(bq.element_frames_outside)), bp + "element_frames_outside", 0) + " of " +
                  stat(q(double(bq.element_frames)), bp + "element_frames", 0))
       << row("overlapping", stat(q(double(fq.overlapping_pair_frames)), fp + "overlapping_pair_frames", 0),
              "pair-frames; between slices " +
                  stat(q(double(bq.overlapping_pair_frames)), bp + "overlapping_pair_frames", 0))
       << row("channel CV", stat(q(fq.channel_cv_mean), fp + "channel_cv.mean", 2),
              "mean over the frames; 0 is a channel of one width")
       << row("wall ratio", stat(fe(&StatsEvennessSummary::wall_ratio_median), fp + "wall_ratio.median", 2),
              "median frame; an even packing has about 0.5")
       << row("largest empty disc",
              stat(fe(&StatsEvennessSummary::empty_disc_median), fp + "empty_disc.median", 2, 1.0, " ρ"),
              "median frame, in element radii; worst " +
                  stat(fe(&StatsEvennessSummary::empty_disc_worst), fp + "empty_disc.worst", 2, 1.0, " ρ"))
       << row("kink", stat(motion ? finite(motion->kink) : std::nullopt, "motion.kink", 1),
              "acceleration's 99th percentile over its median")
       << row("slices show",
              stat(motion && motion->slice_ratio ? finite(*motion->slice_ratio) : std::nullopt, "motion.slice_ratio",
                   2),
              "acceleration next to a slice over elsewhere; 1 when they do not show");
  const std::vector<StatsMotion::Size> no_sizes;
  const std::vector<StatsMotion::Size>& sizes =
      motion && motion->size_over_script ? *motion->size_over_script : no_sizes;
  const auto ratio = [](const StatsMotion::Size& s) { return std::isfinite(s.ratio) ? s.ratio : 0.0; };
  std::size_t worst = 0;
  for (std::size_t e = 0; e < sizes.size(); ++e)
    if (ratio(sizes[e]) > ratio(sizes[worst])) worst = e;
  if (!sizes.empty())
    page << row(
        "size against the script",
        stat(finite(sizes[worst].ratio), "motion.size_over_script." + std::to_string(worst) + ".ratio", 2, 1.0, "×"),
        "the least steady element's largest over smallest area over its script");
  page << "</table></div></div>\n";

  // The plots.
  std::vector<double> between_t;
  std::vector<std::optional<double>> between_coverage;
  if (stats.between_slices)
    for (const StatsFrame& b : *stats.between_slices) {
      between_t.push_back(std::isfinite(b.t) ? b.t : 0.0);
      between_coverage.push_back(finite(b.coverage));
    }
  std::vector<std::optional<double>> coverage_percent = coverage, between_percent = between_coverage;
  for (auto& v : coverage_percent)
    if (v) *v *= 100.0;
  for (auto& v : between_percent)
    if (v) *v *= 100.0;
  page << "<h2>Per frame</h2>\n<div id=\"plots\">\n";
  std::vector<Series> coverage_series{{"frames", t, coverage_percent, "#1f6fb2"}};
  if (!between_t.empty()) coverage_series.push_back({"between slices", between_t, between_percent, "#8fb7dc", "extra"});
  if (still && std::isfinite(still->coverage))
    coverage_series.push_back(level("standing still", still->coverage * 100.0, "#777"));
  page << plot({"plot-coverage", "Coverage", "frame time t", "% of the container", 0.0, t_max, true, std::nullopt},
               coverage_series);
  page << plot({"plot-channel", "Channel CV", "frame time t", "std / mean", 0.0, t_max, true, 0.0},
               {{"frames", t, channel, "#2a8a4a"}});
  page << plot({"plot-wall", "Wall ratio", "frame time t", "wall gap / art gap", 0.0, t_max, true, 0.0},
               {{"frames", t, wall, "#a0522d"}, level("even: 0.5", 0.5, "#777")});
  std::vector<Series> kink_series{{"frames", t, kink, "#7b3fa0"}};
  if (motion && std::isfinite(motion->kink)) kink_series.push_back(level("kink", motion->kink, "#777"));
  page << plot({"plot-kink", "Kink per frame", "frame time t", "largest acceleration / median", 0.0, t_max, true, 0.0,
                "rendered before animpak 0.11.0: run animpak render DIR"},
               kink_series);
  const double contact_step =
      quality && fq.evenness && std::isfinite(fq.evenness->contact_step) ? fq.evenness->contact_step : 0.05;
  std::vector<Series> contact_series;
  double r_max = contact_step;
  if (quality && fq.evenness) {
    const auto contact_line = [&](const std::vector<double>& values, Series line) {
      for (std::size_t k = 0; k < values.size(); ++k) {
        line.x.push_back(double(k) * contact_step);
        line.y.push_back(finite(values[k]));
      }
      return line;
    };
    const Series mean = contact_line(fq.evenness->contact_mean, {"mean H(r)", {}, {}, "#c0392b"});
    r_max = std::max(r_max, mean.x.empty() ? 0.0 : mean.x.back());
    for (const StatsFrame& f : frames)
      if (f.evenness) contact_series.push_back(contact_line(f.evenness->contact, {"", {}, {}, "#e6a29a", "extra"}));
    contact_series.push_back(mean);
  }
  page << plot({"plot-contact", "Negative space: spherical contact H(r)", "r (element radii)", "share of the container",
                0.0, r_max, false, 0.0},
               contact_series);
  page << "</div>\n";

  // The elements.
  page << "<h2>Elements</h2>\n<table id=\"elements\"><tr><th></th><th>element</th><th>art</th><th>kind</th>"
       << "<th>growth g</th><th>size against the script</th></tr>\n";
  for (std::size_t e = 0; e < input.elements.size(); ++e) {
    const ReportElement& el = input.elements[e];
    const std::string g = "final_growth." + std::to_string(e) + ".";
    const bool grown = stats.final_growth && e < stats.final_growth->size();
    const std::optional<double> lo = grown ? finite((*stats.final_growth)[e].min) : std::nullopt,
                                hi = grown ? finite((*stats.final_growth)[e].max) : std::nullopt;
    page << "<tr><td>" << el.thumbnail << "</td><td>" << xml_escaped(el.name) << "</td><td>" << xml_escaped(el.library)
         << " <span class=\"note\">" << xml_escaped(el.art) << "</span></td><td>" << xml_escaped(el.kind) << "</td><td>"
         << stat(lo, g + "min", 2) << " – " << stat(hi, g + "max", 2) << "</td><td>"
         << stat(e < sizes.size() ? finite(sizes[e].ratio) : std::nullopt,
                 "motion.size_over_script." + std::to_string(e) + ".ratio", 2, 1.0, "×")
         << "</td></tr>\n";
  }
  page << "</table>\n";

  // Provenance.
  const std::optional<StatsSeconds>& seconds = stats.seconds;
  page << "<h2>Provenance</h2>\n<table id=\"provenance\">\n"
       << row("scene", "<code>" + xml_escaped(stats.scene) + "</code>")
       << row("animpak", xml_escaped(stats.animpak) + ", commit <code>" + text_of(stats.commit) + "</code>" +
                             (stats.rendered_by ? ", rendered by <code>" + text_of(stats.rendered_by) + "</code>" : ""))
       << row("device", text_of(stats.device)) << row("driver", text_of(stats.driver))
       << row("seed", stat(double(stats.seed), "seed", 0))
       << row("iterations", stat(double(stats.iterations), "iterations", 0), xml_escaped(stats.stop_reason))
       << row("time", stat(seconds ? finite(seconds->simulation) : std::nullopt, "seconds.simulation", 1, 1.0, " s"),
              "simulation; set-up " +
                  stat(seconds ? finite(seconds->setup) : std::nullopt, "seconds.setup", 1, 1.0, " s"))
       << row("size", stat(double(stats.vertices), "vertices", 0) + " vertices, " +
                          stat(count_of(stats.springs), "springs", 0) + " springs")
       << "</table>\n";

  // The frame figures the slider shows (the plots' own numbers).
  double frame_seconds = 0.0;
  const std::size_t dur = input.animation_svg.find("dur=\"");
  if (dur != std::string::npos) frame_seconds = std::atof(input.animation_svg.c_str() + dur + 5) / double(n);
  const auto list = [](const std::vector<std::optional<double>>& v) {
    json a = json::array();
    for (const auto& x : v) a.push_back(x ? json(*x) : json(nullptr));
    return a;
  };
  const json data = {{"t", t},
                     {"coverage", list(coverage)},
                     {"channel", list(channel)},
                     {"wall", list(wall)},
                     {"kink", list(kink)},
                     {"frame_seconds", frame_seconds}};
  page << "<script id=\"frame-data\" type=\"application/json\">" << script_json(data) << "</script>\n<script>"
       << kScript << "</script>\n</body></html>\n";
  return page.str();
}

}  // namespace animpak
