// `animpak params` and `animpak schema`: the tables of the code printed as documentation. The table of
// docs/parameters.md and docs/scene.schema.json are these commands' output (scripts/update-docs.sh), and
// tests fail when the docs and the code disagree.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "animpak/param_table.hpp"
#include "animpak/scene_spec.hpp"
#include "commands.hpp"

namespace animpak::cli {
namespace {

/// Shortest text that reads back to the same value, exponents written as people write them (1e-6, 1e8).
std::string shown(double value, bool integer) {
  if (integer) return std::to_string(static_cast<long long>(value));
  char buffer[64];
  const std::string text(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
  const std::size_t e = text.find('e');
  if (e == std::string::npos) return text;
  std::string exponent = text.substr(e + 1);
  const bool negative = exponent.front() == '-';
  exponent.erase(0, exponent.find_first_not_of("+-0"));
  return text.substr(0, e + 1) + (negative ? "-" : "") + exponent;
}

std::string range_of(const ParamInfo& info) {
  const bool integer = param_is_integer(info);
  if (std::isinf(info.max)) return "≥ " + shown(info.min, integer);
  return "[" + shown(info.min, integer) + ", " + shown(info.max, integer) + "]";
}

void print_markdown() {
  const Params defaults;
  std::cout << "| name | default | range | paper | meaning |\n|---|---|---|---|---|\n";
  for (const ParamInfo& info : param_table())
    std::cout << "| `" << info.name << "` | " << shown(param_value(defaults, info), param_is_integer(info)) << " | "
              << range_of(info) << " | " << info.paper << " | " << info.meaning << " |\n";
}

/// Display width of UTF-8 text: its code points (the table's ≥, Δ and § are one column each).
std::size_t width(const std::string& text) {
  return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

void print_text() {
  const Params defaults;
  std::vector<std::vector<std::string>> rows{{"name", "default", "range", "meaning"}};
  for (const ParamInfo& info : param_table())
    rows.push_back({std::string(info.name), shown(param_value(defaults, info), param_is_integer(info)), range_of(info),
                    std::string(info.meaning)});
  std::vector<std::size_t> widths(3, 0);
  for (const auto& row : rows)
    for (std::size_t c = 0; c < widths.size(); ++c) widths[c] = std::max(widths[c], width(row[c]));
  for (const auto& row : rows) {
    for (std::size_t c = 0; c < widths.size(); ++c)
      std::cout << row[c] << std::string(widths[c] - width(row[c]) + 2, ' ');
    std::cout << row.back() << "\n";
  }
}

}  // namespace

int params(const ParamsOptions& options) {
  if (options.markdown)
    print_markdown();
  else
    print_text();
  return 0;
}

int schema() {
  std::cout << scene_json_schema();
  return 0;
}

}  // namespace animpak::cli
