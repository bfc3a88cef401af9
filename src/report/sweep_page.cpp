// The sweep's page and table (animpak/report.hpp): text, inline SVG and data URIs only, so the page needs no
// network and no file beside it; its links lead to each run's own report page.
#include "animpak/report.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "animpak/xml_text.hpp"
#include "svg_plot.hpp"

namespace animpak {
namespace {

using nlohmann::json;

std::optional<double> measure_value(const CollectedRun& r, const SweepMeasure& m) {
  if (r.state != "done" || !r.stats) return std::nullopt;
  const std::optional<double> v = m.value(*r.stats);
  return v && std::isfinite(*v) ? v : std::nullopt;
}

// A setting's value as the run's id writes it: 0.5, 5, 12.
std::string value_text(const json& value) {
  if (!value.is_number_float()) return value.dump();
  char text[64];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value.get<double>());
  return error == std::errc() ? std::string(text, end) : value.dump();
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string figure(const CollectedRun& r, const SweepMeasure& m) {
  const std::optional<double> v = measure_value(r, m);
  if (!v) return "<span class=\"none\">–</span>";
  std::ostringstream out;
  out << "<span data-stat=\"" << xml_escaped(m.path) << "\"";
  if (m.scale != 1.0) out << " data-scale=\"" << m.scale << "\"";
  out << ">" << report_number(*v * m.scale, m.decimals) << xml_escaped(m.unit) << "</span>";
  return out.str();
}

const char* kSweepStyle = R"(
body{font:15px/1.45 system-ui,-apple-system,"Segoe UI",sans-serif;margin:0 auto;max-width:1400px;padding:16px 24px 40px;color:#222;background:#fafafa}
h1{font-size:24px;margin:8px 0 2px}h2{font-size:18px;margin:28px 0 8px;border-bottom:1px solid #ddd;padding-bottom:4px}
.sub{color:#666;margin:0 0 12px}.controls{display:flex;gap:14px;align-items:center;margin:10px 0 16px}
#cards{display:flex;flex-wrap:wrap;gap:14px}
.card{background:#fff;border:1px solid #ddd;border-radius:6px;padding:10px;width:300px}
.card[data-state="failed"]{border-color:#d88;background:#fff6f6}.card[data-state="unfinished"],.card[data-state="running"],.card[data-state="not started"]{background:#f4f4f4;color:#555}
.card h3{font-size:14px;margin:6px 0;word-break:break-all}.state{font-size:12px;font-weight:normal;color:#777;margin-left:6px}
.pics{display:flex;gap:6px}.pics img{width:145px;height:auto;border:1px solid #eee;background:#fff;image-rendering:auto}
.pics .missing{width:145px;height:100px;display:flex;align-items:center;justify-content:center;color:#999;font-size:12px;border:1px dashed #ccc;text-align:center}
table{border-collapse:collapse}th,td{text-align:left;padding:1px 10px 1px 0;font-size:13px}th{font-weight:600;color:#444}
td{font-variant-numeric:tabular-nums}.message{font-size:13px;color:#922;word-break:break-word}.note{color:#777;font-size:13px}
#plots{display:flex;flex-wrap:wrap;gap:12px}
)";

// Sorting: the measure in the select (or #sort=KEY in the address, &reverse=1 for the other way), finished runs
// first, ties in plan order; failed and unfinished runs after them in plan order.
const char* kSweepScript = R"(
(function () {
  var measures = JSON.parse(document.getElementById('measures').textContent);
  var cards = document.getElementById('cards');
  var select = document.getElementById('sort'), reverse = document.getElementById('reverse');
  function index(card) { return Number(card.getAttribute('data-index')); }
  function score(card, m) {
    var v = card.getAttribute('data-' + m.key);
    if (card.getAttribute('data-state') !== 'done' || v === null || v === '') return null;
    v = Number(v);
    return m.better === 'high' ? -v : m.better === 'half' ? Math.abs(v - 0.5) : v;
  }
  function sortBy(key, reversed) {
    var m = measures.filter(function (x) { return x.key === key; })[0] || measures[0];
    var list = Array.prototype.slice.call(cards.querySelectorAll('.card'));
    list.sort(function (a, b) {
      var sa = score(a, m), sb = score(b, m);
      if (sa === null || sb === null) return sa === sb ? index(a) - index(b) : (sa === null ? 1 : -1);
      var d = reversed ? sb - sa : sa - sb;
      return d !== 0 ? d : index(a) - index(b);
    });
    list.forEach(function (card) { cards.appendChild(card); });
    select.value = m.key;
    reverse.checked = reversed;
    document.body.setAttribute('data-sort', m.key + (reversed ? ' reversed' : ''));
  }
  var hash = {};
  location.hash.replace(/^#/, '').split('&').forEach(function (kv) {
    var p = kv.split('='); if (p[0]) hash[decodeURIComponent(p[0])] = decodeURIComponent(p[1] || '');
  });
  function apply() {
    sortBy(select.value, reverse.checked);
    history.replaceState(null, '', '#sort=' + select.value + (reverse.checked ? '&reverse=1' : ''));
  }
  select.addEventListener('change', apply);
  reverse.addEventListener('change', apply);
  sortBy(hash.sort || measures[0].key, hash.reverse === '1');
  document.body.setAttribute('data-ready', 'yes');
})();
)";

const char* kSweepColors[] = {"#1f6fb2", "#c0392b", "#2a8a4a", "#7b3fa0", "#a0522d", "#d4a017", "#16a3a3", "#555555"};

// Each measure against the one setting the sweep varies (the paper's Fig. 16 for k_time): a line per seed.
std::string plots(const SweepCollection& c) {
  if (c.varied.size() != 1) return {};
  const std::string& name = c.varied.front();
  std::set<double> xs;
  std::map<std::uint64_t, std::vector<const CollectedRun*>> by_seed;
  for (const CollectedRun& r : c.runs) {
    xs.insert(r.set.front().second.get<double>());
    by_seed[r.seed].push_back(&r);
  }
  if (xs.size() < 2) return {};
  const double lo = *xs.begin(), hi = *xs.rbegin();
  const bool log_x = lo > 0.0 && hi / lo >= 20.0;
  const double x_min = log_x ? lo / 1.5 : lo - 0.06 * (hi - lo), x_max = log_x ? hi * 1.5 : hi + 0.06 * (hi - lo);
  std::ostringstream out;
  out << "<h2>Against " << xml_escaped(name) << "</h2>\n<p class=\"note\">Each finished run is a dot, the runs of "
      << "one seed joined" << (log_x ? "; " + xml_escaped(name) + " on a logarithmic axis" : std::string()) << ".</p>\n"
      << "<div id=\"plots\">\n";
  for (const SweepMeasure& m : sweep_measures()) {
    std::vector<Series> series;
    std::size_t colour = 0;
    for (const auto& [seed, runs] : by_seed) {
      std::vector<std::pair<double, std::optional<double>>> points;
      for (const CollectedRun* r : runs) {
        const std::optional<double> v = measure_value(*r, m);
        points.emplace_back(r->set.front().second.get<double>(), v ? std::optional<double>(*v * m.scale) : v);
      }
      std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      Series s{"seed " + std::to_string(seed), {}, {}, kSweepColors[colour++ % std::size(kSweepColors)]};
      for (const auto& [x, y] : points) s.x.push_back(x), s.y.push_back(y);
      series.push_back(std::move(s));
    }
    if (series.size() > 6)
      for (Series& s : series) s.name.clear();  // a legend of that many seeds would not fit
    std::string y_label = m.label;
    if (!m.unit.empty()) y_label += " (" + (m.unit == " %" ? std::string("%") : m.unit.substr(1)) + ")";
    out << plot({"plot-" + m.key, m.label, name, y_label, x_min, x_max, false, std::nullopt,
                 "no finished run has this figure", log_x},
                series);
  }
  out << "</div>\n";
  return out.str();
}

}  // namespace

const std::vector<SweepMeasure>& sweep_measures() {
  // docs/quality.md says what each is; docs/sweeps.md why these.
  using Summary = StatsSummary;
  const auto frames = [](double Summary::*member) {
    return [member](const Stats& s) {
      return s.quality ? std::optional<double>(s.quality->frames.*member) : std::nullopt;
    };
  };
  const auto evenness = [](double StatsEvennessSummary::*member) {
    return [member](const Stats& s) {
      return s.quality && s.quality->frames.evenness ? std::optional<double>((*s.quality->frames.evenness).*member)
                                                     : std::nullopt;
    };
  };
  static const std::vector<SweepMeasure> measures = {
      {"coverage_min", "coverage, lowest frame", "quality.frames.coverage.min", frames(&Summary::coverage_min), false,
       100.0, 1, " %", "high"},
      {"coverage_mean", "coverage, mean", "quality.frames.coverage.mean", frames(&Summary::coverage_mean), false, 100.0,
       1, " %", "high"},
      {"wall_ratio", "wall ratio", "quality.frames.wall_ratio.median",
       evenness(&StatsEvennessSummary::wall_ratio_median), false, 1.0, 2, "", "half"},
      {"empty_disc", "largest empty disc", "quality.frames.empty_disc.median",
       evenness(&StatsEvennessSummary::empty_disc_median), false, 1.0, 2, " ρ", "low"},
      {"kink", "kink", "motion.kink",
       [](const Stats& s) { return s.motion ? std::optional<double>(s.motion->kink) : std::nullopt; }, false, 1.0, 1,
       "", "low"},
      {"iterations", "iterations", "iterations",
       [](const Stats& s) { return std::optional<double>(double(s.iterations)); }, true, 1.0, 0, "", "low"},
      {"seconds", "time", "seconds.simulation",
       [](const Stats& s) { return s.seconds ? std::optional<double>(s.seconds->simulation) : std::nullopt; }, false,
       1.0, 1, " s", "low"}};
  return measures;
}

std::string sweep_page(const SweepCollection& c) {
  std::map<std::string, int> states;
  for (const CollectedRun& r : c.runs) ++states[r.state];
  std::ostringstream page;
  page << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
       << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
       << "<title>animpak sweep: " << xml_escaped(c.title) << "</title><style>" << kSweepStyle << kPlotStyle
       << "</style></head>\n<body>\n<h1>" << xml_escaped(c.title) << "</h1>\n<p class=\"sub\">" << c.runs.size()
       << " runs of <code>" << xml_escaped(c.scene_file) << "</code>";
  for (const auto& [state, n] : states) page << ", " << n << " " << xml_escaped(state);
  page << "; varied: seed";
  for (const std::string& name : c.varied) page << ", " << xml_escaped(name);
  page << "</p>\n<div class=\"controls\"><label>Sort by <select id=\"sort\">";
  for (const SweepMeasure& m : sweep_measures())
    page << "<option value=\"" << m.key << "\">" << xml_escaped(m.label)
         << (m.better == "high"   ? " (highest first)"
             : m.better == "half" ? " (closest to 0.5 first)"
                                  : " (lowest first)")
         << "</option>";
  page << "<option value=\"index\">plan order</option></select></label>"
       << "<label><input type=\"checkbox\" id=\"reverse\"> the other way</label></div>\n<div id=\"cards\">\n";
  for (const CollectedRun& r : c.runs) {
    const CollectedRun& run = r;
    page << "<div class=\"card\" id=\"run-" << xml_escaped(run.id) << "\" data-id=\"" << xml_escaped(run.id)
         << "\" data-index=\"" << run.index << "\" data-state=\"" << xml_escaped(r.state) << "\"";
    for (const SweepMeasure& m : sweep_measures())
      if (const std::optional<double> v = measure_value(r, m))
        page << " data-" << m.key << "=\"" << json(*v).dump() << "\"";
    page << ">\n<div class=\"pics\">";
    if (!r.frame_png.empty())
      page << "<img class=\"frame0\" alt=\"frame 0\" title=\"frame 0\" src=\"data:image/png;base64,"
           << base64(r.frame_png) << "\">";
    else
      page << "<div class=\"missing\">no frame 0</div>";
    if (!r.animation_gif.empty())
      page << "<img class=\"animation\" alt=\"the animation\" title=\"the animation\" src=\"data:image/gif;base64,"
           << base64(r.animation_gif) << "\">";
    else
      page << "<div class=\"missing\">no animation.gif</div>";
    page << "</div>\n<h3>" << xml_escaped(run.id) << "<span class=\"state\">" << xml_escaped(r.state)
         << "</span></h3>\n<table class=\"values\"><tr><th>seed</th><td>" << run.seed << "</td></tr>";
    for (const auto& [name, value] : run.set)
      page << "<tr><th>" << xml_escaped(name) << "</th><td>" << xml_escaped(value_text(value)) << "</td></tr>";
    page << "</table>\n";
    if (r.state == "done") {
      page << "<table class=\"figures\">";
      for (const SweepMeasure& m : sweep_measures())
        page << "<tr><th>" << xml_escaped(m.label) << "</th><td>" << figure(r, m) << "</td></tr>";
      page << "</table>\n";
    }
    if (!r.message.empty()) page << "<p class=\"message\">" << xml_escaped(r.message) << "</p>\n";
    if (!r.picture_note.empty()) page << "<p class=\"note\">" << xml_escaped(r.picture_note) << "</p>\n";
    if (r.report)
      page << "<p><a href=\"runs/" << xml_escaped(run.id) << "/report.html\">report page</a> <span class=\"note\">runs/"
           << xml_escaped(run.id) << "/</span></p>\n";
    page << "</div>\n";
  }
  page << "</div>\n" << plots(c);
  json measures = json::array();
  for (const SweepMeasure& m : sweep_measures()) measures.push_back({{"key", m.key}, {"better", m.better}});
  measures.push_back({{"key", "index"}, {"better", "low"}});
  page << "<script id=\"measures\" type=\"application/json\">" << measures.dump() << "</script>\n<script>"
       << kSweepScript << "</script>\n</body></html>\n";
  return page.str();
}

std::string sweep_csv(const SweepCollection& c) {
  std::ostringstream out;
  out << "index,id,state,seed";
  for (const std::string& name : c.varied) out << "," << csv_field(name);
  for (const SweepMeasure& m : sweep_measures()) out << "," << m.key;
  out << ",stop_reason,message,folder\n";
  for (const CollectedRun& r : c.runs) {
    const CollectedRun& run = r;
    out << run.index << "," << csv_field(run.id) << "," << csv_field(r.state) << "," << run.seed;
    for (const auto& [name, value] : run.set) out << "," << value_text(value);
    // Each figure as stats.json writes it, to the last digit (a count without a decimal point).
    for (const SweepMeasure& m : sweep_measures()) {
      const std::optional<double> v = measure_value(r, m);
      out << "," << (!v ? std::string() : m.whole ? json(std::int64_t(*v)).dump() : json(*v).dump());
    }
    out << "," << (r.stats ? csv_field(r.stats->stop_reason) : std::string()) << "," << csv_field(r.message) << ",runs/"
        << csv_field(run.id) << "\n";
  }
  return out.str();
}

}  // namespace animpak
