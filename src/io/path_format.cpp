// The authors' line-based `.path` format (RepulsionPak data; docs/scene-format.md):
//   1  <numRegions>
//   2  foreground_color_rgb <region> r,g,b ...   stroke per path, -1,-1,-1 = none
//   3  background_color_rgb <region> r,g,b ...   fill per path
//   4+ <region> <isClosed> <pathType> x0 y0 x1 y1 ...
// isClosed is unreliable in the data, so every path is read as a closed polygon.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "animpak/error.hpp"
#include "animpak/io.hpp"
#include "json_fields.hpp"
#include "text_file.hpp"

namespace animpak {
namespace {

using io_detail::backticked;

/// Strokes in the data have no width; one art unit (0.2 % of the 500-unit artboard) is a hairline
/// that stays visible at the sizes elements are packed at.
constexpr double kStrokeWidth = 1.0;
constexpr int kHolePathType = 7;

struct Line {
  int number = 0;  // 1-based, for messages
  std::vector<std::string_view> tokens;
};

class PathParser {
 public:
  PathParser(const std::string& text, std::string name) : name_(std::move(name)) { split(text); }

  ArtShape parse() {
    if (lines_.empty())
      fail(1, "the file is empty", "expected a `.path` file: a region count, two colour lines, then one line per path");
    read_region_count(lines_[0]);
    if (lines_.size() < 2) fail(lines_[0].number + 1, "missing the foreground_color_rgb line", kHeaderHelp);
    if (lines_.size() < 3) fail(lines_[1].number + 1, "missing the background_color_rgb line", kHeaderHelp);
    const std::vector<Paint> strokes = read_colours(lines_[1], "foreground_color_rgb");
    const std::vector<Paint> fills = read_colours(lines_[2], "background_color_rgb");
    const size_t path_count = lines_.size() - 3;
    if (path_count == 0)
      fail(lines_[2].number + 1, "the file has no path lines",
           "add one `0 <isClosed> <pathType> x0 y0 ...` line per path");
    for (const auto& [colours, line] : {std::pair{&strokes, &lines_[1]}, std::pair{&fills, &lines_[2]}})
      if (colours->size() != path_count)
        fail(line->number, std::to_string(colours->size()) + " colours for " + std::to_string(path_count) + " paths",
             "give exactly one r,g,b colour (or -1,-1,-1) per path line");

    ArtShape shape;
    shape.source = name_;
    // The file lists details first and the body last; the body must be painted underneath.
    for (size_t i = path_count; i-- > 0;) {
      ArtPath path = read_path(lines_[3 + i], static_cast<int>(i));
      path.stroke = strokes[i];
      path.fill = fills[i];
      path.stroke_width = path.stroke.enabled ? kStrokeWidth : 0.0;
      shape.paths.push_back(std::move(path));
    }
    return shape;
  }

 private:
  static constexpr const char* kHeaderHelp =
      "lines 2 and 3 must be `foreground_color_rgb 0 r,g,b ...` and `background_color_rgb 0 r,g,b ...`";

  void split(const std::string& text) {
    int number = 0;
    size_t begin = 0;
    while (begin <= text.size()) {
      size_t end = text.find('\n', begin);
      if (end == std::string::npos) end = text.size();
      ++number;
      Line line{number, {}};
      const std::string_view view(text.data() + begin, end - begin);
      // Tokens are single-space separated in the data; tabs, runs of spaces and CRLF endings are
      // accepted too since editors introduce them and they carry no meaning.
      size_t i = 0;
      while (i < view.size()) {
        while (i < view.size() && is_space(view[i])) ++i;
        size_t j = i;
        while (j < view.size() && !is_space(view[j])) ++j;
        if (j > i) line.tokens.push_back(view.substr(i, j - i));
        i = j;
      }
      // Blank lines hold nothing (the data ends with a newline); numbers still count them.
      if (!line.tokens.empty()) lines_.push_back(std::move(line));
      begin = end + 1;
    }
  }

  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

  [[noreturn]] void fail(int line, const std::string& problem, const std::string& what_to_do) const {
    throw InputError(name_ + ":" + std::to_string(line) + ": " + problem + "; " + what_to_do);
  }

  std::optional<long> integer(std::string_view token) const {
    long value = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || end != token.data() + token.size()) return std::nullopt;
    return value;
  }

  void read_region_count(const Line& line) {
    const std::optional<long> count = line.tokens.size() == 1 ? integer(line.tokens[0]) : std::nullopt;
    if (!count)
      fail(line.number, "expected the region count (one integer), got " + backticked(join(line.tokens)),
           "a `.path` file starts with a line holding `1`");
    if (*count != 1)
      fail(line.number, "the file has " + std::to_string(*count) + " regions, only 1 is supported",
           "split the art into one file per region");
  }

  void require_region(const Line& line, std::string_view token) const {
    const std::optional<long> region = integer(token);
    if (!region) fail(line.number, "expected a region number, got " + backticked(token), "use region 0");
    if (*region != 0)
      fail(line.number, "region " + std::to_string(*region) + " is not supported",
           "use region 0 (files hold one region)");
  }

  std::vector<Paint> read_colours(const Line& line, std::string_view keyword) {
    if (line.tokens[0] != keyword)
      fail(line.number, "expected " + backticked(keyword) + ", got " + backticked(line.tokens[0]), kHeaderHelp);
    if (line.tokens.size() < 2) fail(line.number, "missing the region after " + backticked(keyword), kHeaderHelp);
    require_region(line, line.tokens[1]);
    std::vector<Paint> paints;
    for (size_t i = 2; i < line.tokens.size(); ++i) paints.push_back(read_colour(line, line.tokens[i]));
    return paints;
  }

  Paint read_colour(const Line& line, std::string_view token) const {
    long channel[3];
    size_t start = 0;
    for (int c = 0; c < 3; ++c) {
      const size_t comma = c < 2 ? token.find(',', start) : token.size();
      const std::optional<long> value =
          comma == std::string_view::npos ? std::nullopt : integer(token.substr(start, comma - start));
      if (!value)
        fail(line.number, "expected a colour `r,g,b`, got " + backticked(token),
             "write three integers 0-255 separated by commas, or -1,-1,-1 for none");
      channel[c] = *value;
      start = comma + 1;
    }
    if (channel[0] == -1 && channel[1] == -1 && channel[2] == -1) return {};
    for (long v : channel)
      if (v < 0 || v > 255)
        fail(line.number, "colour " + backticked(token) + " has a channel outside 0-255",
             "use 0-255 per channel, or -1,-1,-1 for none");
    return Paint{true, Rgba{channel[0] / 255.0, channel[1] / 255.0, channel[2] / 255.0, 1.0}};
  }

  ArtPath read_path(const Line& line, int index) const {
    const std::string what = "path " + std::to_string(index);
    if (line.tokens.size() < 3)
      fail(line.number, what + " has no `<region> <isClosed> <pathType>` prefix",
           "start each path line with `0 1 <pathType>` then its coordinates");
    require_region(line, line.tokens[0]);
    const std::optional<long> closed = integer(line.tokens[1]);
    if (!closed || (*closed != 0 && *closed != 1))
      fail(line.number, what + ": expected isClosed 0 or 1, got " + backticked(line.tokens[1]), "write 0 or 1");
    const std::optional<long> type = integer(line.tokens[2]);
    if (!type || *type < 0 || *type > kHolePathType)
      fail(line.number, what + ": unknown pathType " + backticked(line.tokens[2]),
           "use 0 boundary, 1 detail, 2 focal, 3 field, 4 seed, 5 streamline, 6 skeleton or 7 hole");
    const size_t coordinates = line.tokens.size() - 3;
    if (coordinates % 2 != 0)
      fail(line.number, what + " has an odd number of coordinates (" + std::to_string(coordinates) + ")",
           "give x y pairs; a number is missing or extra");

    ArtPath path;
    path.id = "path" + std::to_string(index);
    path.source_index = index;
    path.path_type = static_cast<int>(*type);
    Polyline ring;
    for (size_t i = 3; i < line.tokens.size(); i += 2)
      ring.points.push_back({coordinate(line, what, i), coordinate(line, what, i + 1)});
    // Some paths repeat their first point at the end; the closing segment is implied instead.
    while (ring.points.size() > 1 && ring.points.back() == ring.points.front()) ring.points.pop_back();
    std::set<std::pair<double, double>> distinct;
    for (Vec2 p : ring.points) distinct.insert({p.x, p.y});
    if (distinct.size() < 3)
      fail(line.number, what + " has " + std::to_string(distinct.size()) + " distinct points, fewer than 3",
           "a path must enclose an area; remove it or add its missing points");
    path.polylines.push_back(std::move(ring));
    return path;
  }

  double coordinate(const Line& line, const std::string& what, size_t token_index) const {
    const std::string_view token = line.tokens[token_index];
    double value = 0.0;
    // from_chars takes no leading '+', which some exporters write.
    const std::string_view digits = token.starts_with('+') ? token.substr(1) : token;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    const std::string position = what + ", token " + std::to_string(token_index + 1);
    if (ec == std::errc::result_out_of_range || (ec == std::errc() && !std::isfinite(value)))
      fail(line.number, position + ": " + backticked(token) + " is not a finite number",
           "replace it with a finite coordinate");
    if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty())
      fail(line.number, position + ": " + backticked(token) + " is not a number",
           "coordinates must be decimal numbers");
    return value;
  }

  static std::string join(const std::vector<std::string_view>& tokens) {
    std::string out;
    for (std::string_view t : tokens) {
      if (!out.empty()) out.push_back(' ');
      out.append(t);
    }
    return out;
  }

  std::string name_;
  std::vector<Line> lines_;
};

}  // namespace

ArtShape parse_path_text(const std::string& text, const std::string& name) { return PathParser(text, name).parse(); }

ArtShape load_path_file(const std::filesystem::path& file) {
  const std::string text = io_detail::read_text_file(file, "check the path and that the file is a `.path` art file");
  return parse_path_text(text, file.string());
}

}  // namespace animpak
