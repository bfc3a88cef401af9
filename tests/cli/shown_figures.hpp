// The pages animpak writes (the report page, the sweep's page) tie every figure they show to stats.json: a
// `<span data-stat="PATH" data-scale="S">TEXT</span>` shows the value at PATH times S (1 without it). This
// checks each such figure of a page against the stats.json it was built from, read through the model
// (animpak/stats.hpp) and written back as the file has it.
#pragma once

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include "animpak/stats.hpp"

namespace animpak::test {

/// Every figure of `html` against `stats`, to the decimals shown: the problems found ("PATH: shows TEXT,
/// stats.json has VALUE"); `figures` counts the figures checked.
inline std::vector<std::string> shown_figure_problems(const std::string& html, const animpak::Stats& stats,
                                                      int& figures) {
  std::vector<std::string> problems;
  // The model as its file: a figure's path there is a JSON pointer with dots for slashes.
  const nlohmann::json file = nlohmann::json::parse(animpak::stats_json_text(stats));
  const std::regex shown(R"re(<span data-stat="([^"]+)"(?: data-scale="([^"]+)")?>([^<]*)</span>)re");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), shown); it != std::sregex_iterator(); ++it) {
    ++figures;
    const std::string path = (*it)[1], text = (*it)[3];
    const double scale = (*it)[2].matched ? std::stod((*it)[2]) : 1.0;
    std::string digits;
    for (const char c : text)
      if (std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-')
        digits += c;
      else if (c != ',' && !digits.empty())
        break;
    std::string pointer = "/" + path;
    std::replace(pointer.begin(), pointer.end(), '.', '/');
    const nlohmann::json::json_pointer at(pointer);
    const nlohmann::json value = file.contains(at) ? file.at(at) : nlohmann::json();
    const std::size_t point = digits.find('.');
    const int decimals = point == std::string::npos ? 0 : int(digits.size() - point - 1);
    if (!value.is_number() || digits.empty() ||
        std::abs(std::stod(digits) - value.get<double>() * scale) > 0.5 * std::pow(10.0, -decimals) * 1.0001)
      problems.push_back(path + ": shows \"" + text + "\", stats.json has " + value.dump());
  }
  return problems;
}

}  // namespace animpak::test
