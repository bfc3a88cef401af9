#include "evenness_output.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace animpak::cli {
namespace {

nlohmann::json optional_json(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); }

std::optional<double> median(std::vector<double> v) {
  if (v.empty()) return std::nullopt;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 == 1 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

std::string fixed(const std::optional<double>& v) {
  if (!v) return "none";
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << *v;
  return s.str();
}

}  // namespace

EvennessSummary summarize_evenness(const std::vector<FrameMetrics>& metrics) {
  EvennessSummary e;
  std::vector<double> walls, discs;
  for (const FrameMetrics& m : metrics) {
    if (m.wall_ratio) walls.push_back(*m.wall_ratio);
    if (const std::optional<double> disc = m.empty_disc()) {
      discs.push_back(*disc);
      if (!e.empty_disc_worst || *disc > *e.empty_disc_worst) e.empty_disc_worst = disc, e.empty_disc_worst_t = m.t;
    }
  }
  e.wall_ratio_times = int(walls.size());
  if (!walls.empty()) {
    e.wall_ratio_min = *std::min_element(walls.begin(), walls.end());
    e.wall_ratio_max = *std::max_element(walls.begin(), walls.end());
  }
  e.wall_ratio_median = median(walls);
  e.empty_disc_median = median(discs);
  e.contact_mean = mean_contact(metrics);
  return e;
}

nlohmann::json evenness_json(const FrameMetrics& m) {
  return {{"element_radius", m.element_radius},
          {"wall_ratio", optional_json(m.wall_ratio)},
          {"empty_disc", optional_json(m.empty_disc())},
          {"empty_disc_radius", m.empty_disc_radius},
          {"contact", m.contact}};
}

nlohmann::json evenness_summary_json(const EvennessSummary& e) {
  return {{"wall_ratio",
           {{"times", e.wall_ratio_times},
            {"min", optional_json(e.wall_ratio_min)},
            {"median", optional_json(e.wall_ratio_median)},
            {"max", optional_json(e.wall_ratio_max)}}},
          {"empty_disc",
           {{"median", optional_json(e.empty_disc_median)},
            {"worst", optional_json(e.empty_disc_worst)},
            {"worst_t", e.empty_disc_worst ? nlohmann::json(e.empty_disc_worst_t) : nlohmann::json()}}},
          {"contact", {{"step", contact_step}, {"mean", e.contact_mean}}}};
}

std::string evenness_line(const EvennessSummary& e) {
  std::string line = "evenness: wall ratio " + fixed(e.wall_ratio_median);
  if (e.wall_ratio_min) line += " (" + fixed(e.wall_ratio_min) + "–" + fixed(e.wall_ratio_max) + ")";
  line +=
      ", largest empty disc " + fixed(e.empty_disc_median) + " element radii (worst " + fixed(e.empty_disc_worst) + ")";
  // What leaves less room empty: a narrower channel, more elements, smaller ones in the pockets
  // (docs/parameters.md, "Secondary elements").
  if (e.empty_disc_median && *e.empty_disc_median > sparse_empty_disc)
    line += "; sparse: try a smaller params.offset, higher counts (\"count\": \"fill\") or secondary elements";
  return line;
}

}  // namespace animpak::cli
