// Where `d` and `points` data go wrong, for the warnings of SVG 2's error handling (docs/scene-format.md
// "Errors in path data and points"): svgpp's grammar delivers everything before the first error and says
// where it stopped; this scan finds the character to blame after that and words the warning.
#include <cctype>
#include <cstring>

#include "svg_internal.hpp"

namespace animpak::svg {
namespace {

bool is_wsp(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }
bool is_command(char c) { return c != 0 && std::strchr("MmZzLlHhVvCcSsQqTtAa", c) != nullptr; }
bool is_digit(const std::string& s, size_t i) { return i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); }

size_t skip_separators(const std::string& s, size_t i) {
  while (i < s.size() && (is_wsp(s[i]) || s[i] == ',')) ++i;
  return i;
}

// The end of the SVG number starting at i (sign, digits, fraction, exponent), or i when there is none.
size_t number_end(const std::string& s, size_t i) {
  size_t j = i;
  if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
  const size_t int_start = j;
  while (is_digit(s, j)) ++j;
  bool digits = j > int_start;
  if (j < s.size() && s[j] == '.' && is_digit(s, j + 1)) {
    j += 2;
    while (is_digit(s, j)) ++j;
    digits = true;
  } else if (j < s.size() && s[j] == '.' && digits) {
    ++j;
  }
  if (!digits) return i;
  if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {
    size_t k = j + 1;
    if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
    if (is_digit(s, k)) {
      while (is_digit(s, k)) ++k;
      j = k;
    }
  }
  return j;
}

// The text a warning quotes: from `at` to the next separator, at most 20 characters.
std::string token_at(const std::string& s, size_t at) {
  size_t end = at;
  while (end < s.size() && end - at < 20 && !is_wsp(s[end]) && s[end] != ',') ++end;
  return s.substr(at, std::max<size_t>(end - at, at < s.size() ? 1 : 0));
}

std::string quoted_at(const std::string& s, size_t at) {
  return "character " + std::to_string(at + 1) + " (\"" + token_at(s, at) + "\")";
}

}  // namespace

std::string path_data_error(const std::string& d, size_t stop) {
  // svgpp stops at the start of the first command it cannot complete. Within it, the first character that
  // is neither a separator nor a number is the culprit; when there is none the command is cut short
  // (too few numbers before the next command or the end), and the command itself is quoted.
  const size_t command = skip_separators(d, stop);
  size_t i = command;
  if (i < d.size() && is_command(d[i])) ++i;
  for (;;) {
    i = skip_separators(d, i);
    if (i >= d.size() || is_command(d[i])) {
      i = command;
      break;
    }
    const size_t end = number_end(d, i);
    if (end == i) break;
    i = end;
  }
  const std::string where = i >= d.size() ? "the end" : quoted_at(d, i);
  const bool nothing = skip_separators(d, 0) == command;
  return "path data error at " + where + (nothing ? "; nothing before it to render" : "; rendered up to there");
}

std::string points_error(const std::string& points) {
  // svgpp reads coordinate pairs and stops at the first that is incomplete: either an odd number left
  // over at the end (SVG 2: dropped), or something that is not a number (SVG 2: stop there).
  size_t count = 0, last = 0;
  for (size_t i = skip_separators(points, 0); i < points.size(); i = skip_separators(points, i)) {
    const size_t end = number_end(points, i);
    if (end == i) {
      const size_t pairs = count / 2;
      return "points error at " + quoted_at(points, i) +
             (pairs == 0
                  ? "; nothing before it to render"
                  : "; rendered the " + std::to_string(pairs) + " point" + (pairs == 1 ? "" : "s") + " before it");
    }
    last = i;
    ++count;
    i = end;
  }
  return "odd number of coordinates in points; the last one (\"" + token_at(points, last) + "\", character " +
         std::to_string(last + 1) + ") dropped";
}

}  // namespace animpak::svg
