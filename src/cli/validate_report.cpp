#include "validate_report.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <ostream>

namespace animpak::cli {
namespace {

// Three significant digits are enough to judge an error; an exact zero stays "0".
std::string number(double value) {
  if (value == 0.0) return "0";
  if (std::isinf(value)) return "inf";
  char s[32];
  std::snprintf(s, sizeof s, "%.3g", value);
  return s;
}

std::string integer(double value) {
  char s[32];
  std::snprintf(s, sizeof s, "%.0f", value);
  return s;
}

std::string where(const WorstError& w) {
  return "state " + std::to_string(w.state) + ", vertex " + std::to_string(w.vertex) + " " + w.axis;
}

std::string cell(const std::string& value, const WorstError& w) {
  return w.value == 0.0 ? value : value + " (" + where(w) + ")";
}

std::string checked_text(const DeviceValidation& v, int rebuild) {
  if (v.checked_states.empty()) return "no states";
  const std::string range = std::to_string(v.checked_states.front()) + ".." + std::to_string(v.checked_states.back());
  if (rebuild == 1) return "states " + range;
  return std::to_string(v.checked_states.size()) + " states in " + range + " (every " + std::to_string(rebuild) +
         " steps, where both sides rebuild the grid, and the last)";
}

std::string first_step_text(const DeviceValidation& v) {
  return v.first_differing_step < 0 ? "\u2014" : std::to_string(v.first_differing_step);
}

// Columns padded to their widest entry, two spaces apart. The dash is three bytes but one column wide.
void print_rows(std::ostream& out, const std::vector<std::array<std::string, 5>>& rows, const std::string& indent) {
  const auto columns = [](const std::string& s) { return s == "\u2014" ? std::size_t{1} : s.size(); };
  std::array<std::size_t, 5> width{};
  for (const auto& row : rows)
    for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], columns(row[c]));
  for (const auto& row : rows) {
    out << indent;
    for (std::size_t c = 0; c < row.size(); ++c)
      out << row[c] << (c + 1 < row.size() ? std::string(width[c] - columns(row[c]) + 2, ' ') : "");
    out << "\n";
  }
}

// ULP distances are whole numbers (at most 2^32, compare.hpp) and print as such.
nlohmann::json worst_json(const WorstError& w, bool whole = false) {
  nlohmann::json j{{"value", whole ? nlohmann::json(static_cast<std::int64_t>(w.value)) : nlohmann::json(w.value)}};
  if (w.value != 0.0) j.update({{"state", w.state}, {"vertex", w.vertex}, {"axis", std::string(1, w.axis)}});
  return j;
}

}  // namespace

void print_table(std::ostream& out, const ValidationHeader& header, const DeviceValidation& v) {
  out << "scene " << header.scene << ": " << header.elements << " elements, " << header.vertices << " vertices, "
      << header.steps << " steps\n"
      << "device " << v.device.name << " (" << v.device.platform << "), driver " << v.device.driver << "\n"
      << "forces, reference vs device, worst over " << checked_text(v, header.grid_rebuild_interval) << ":\n";
  std::vector<std::array<std::string, 5>> rows{{"force", "differing", "max abs error", "max rel error", "max ULP"}};
  for (const ForceComparison& f : v.forces)
    rows.push_back({f.name, std::to_string(f.differing), cell(number(f.abs.value), f.abs),
                    cell(number(f.rel.value), f.rel), cell(integer(f.ulp.value), f.ulp)});
  print_rows(out, rows, "  ");
  if (v.first_differing_step < 0) {
    out << "state (x, y, t, vx, vy, vt, spring_rest, growth and the counters): identical for " << v.steps << " steps\n";
  } else {
    out << "state: first differs after step " << v.first_differing_step << ":\n";
    out.precision(9);
    for (const StateMismatch& m : v.mismatches)
      if (m.index == "scalar")
        out << "  " << m.array << ": reference " << m.reference << ", device " << m.device << "\n";
      else
        out << "  " << m.array << "[" << m.first << "] (" << m.index << "): reference " << m.reference << ", device "
            << m.device << ", " << m.ulp << " ulp; " << m.count << " of " << m.size << " differ\n";
  }
  out << "verdict: " << v.verdict() << "\n";
}

void print_summary(std::ostream& out, const ValidationHeader& header, const std::vector<DeviceValidation>& all) {
  out << "scene " << header.scene << ": " << header.elements << " elements, " << header.vertices << " vertices, "
      << header.steps << " steps\n";
  std::vector<std::array<std::string, 5>> rows{{"device", "driver", "max ULP", "first differing step", "verdict"}};
  for (const DeviceValidation& v : all)
    rows.push_back({v.device.name + " (" + v.device.platform + ")", v.device.driver,
                    v.error.empty() ? std::to_string(v.max_ulp()) : "\u2014", first_step_text(v), v.verdict()});
  print_rows(out, rows, "");
}

void print_json(std::ostream& out, const ValidationHeader& header, const std::vector<DeviceValidation>& all) {
  nlohmann::json devices = nlohmann::json::array();
  for (const DeviceValidation& v : all) {
    nlohmann::json forces = nlohmann::json::array();
    for (const ForceComparison& f : v.forces)
      forces.push_back({{"force", f.name},
                        {"differing", f.differing},
                        {"max_abs_error", worst_json(f.abs)},
                        {"max_rel_error", worst_json(f.rel)},
                        {"max_ulp", worst_json(f.ulp, true)}});
    nlohmann::json mismatches = nlohmann::json::array();
    for (const StateMismatch& m : v.mismatches)
      mismatches.push_back({{"array", m.array},
                            {"index", m.index},
                            {"first", m.first},
                            {"reference", m.reference},
                            {"device", m.device},
                            {"ulp", m.ulp},
                            {"differing", m.count},
                            {"size", m.size}});
    nlohmann::json d{{"device", v.device.name},
                     {"platform", v.device.platform},
                     {"driver", v.device.driver},
                     {"max_ulp", v.max_ulp()},
                     {"first_differing_step", nullptr},
                     {"verdict", v.error.empty() ? (v.identical() ? "bit-identical" : "differs") : "error"},
                     {"checked_states", v.checked_states},
                     {"forces", forces},
                     {"state_differences", mismatches}};
    if (v.first_differing_step >= 0) d["first_differing_step"] = v.first_differing_step;
    if (!v.error.empty()) d["error"] = v.error;
    devices.push_back(d);
  }
  const nlohmann::json j{{"scene", header.scene},
                         {"elements", header.elements},
                         {"vertices", header.vertices},
                         {"steps", header.steps},
                         {"devices", devices}};
  out << j.dump(2) << "\n";
}

}  // namespace animpak::cli
