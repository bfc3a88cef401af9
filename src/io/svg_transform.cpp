// The `transform` of an element as the attribute (SVG 1.1, 7.6) or as the CSS property (CSS Transforms 1,
// which SVG 2 makes the attribute a presentation attribute of), and `transform-origin`; lengths as SVG writes
// them. Parsed here rather than by svgpp, whose grammar knows the attribute only (docs/scene-format.md,
// "SVG structure").
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>

#include "svg_internal.hpp"

namespace animpak::svg {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// One number and the unit letters after it ("12.5px", "-3e2", "45deg", "50%").
struct Quantity {
  double value = 0.0;
  std::string unit;
};

bool read_quantity(const std::string& s, size_t& i, Quantity& q) {
  // from_chars, not strtod: the decimal point is '.' whatever the locale.
  const char* start = s.data() + i;
  const char* digits = start + (i < s.size() && s[i] == '+' ? 1 : 0);
  double v = 0.0;
  const auto [end, ec] = std::from_chars(digits, s.data() + s.size(), v);
  if (ec != std::errc() || end == digits || !std::isfinite(v)) return false;
  // from_chars also reads "inf" and "nan"; SVG numbers are decimal only.
  for (const char* c = digits; c < end; ++c)
    if (std::isalpha(static_cast<unsigned char>(*c)) && *c != 'e' && *c != 'E') return false;
  i += static_cast<size_t>(end - start);
  size_t u = i;
  while (u < s.size() && (std::isalpha(static_cast<unsigned char>(s[u])) || s[u] == '%')) ++u;
  q.value = v;
  q.unit = lower(s.substr(i, u - i));
  i = u;
  return true;
}

}  // namespace

std::optional<double> length_in_px(const std::string& unit, double value) {
  // CSS absolute units at 96 px to the inch, as svgpp's length factory (and every browser) uses.
  if (unit.empty() || unit == "px") return value;
  if (unit == "in") return value * 96.0;
  if (unit == "cm") return value * 96.0 / 2.54;
  if (unit == "mm") return value * 96.0 / 25.4;
  if (unit == "q") return value * 96.0 / 101.6;
  if (unit == "pt") return value * 96.0 / 72.0;
  if (unit == "pc") return value * 16.0;
  return std::nullopt;
}

std::optional<double> parse_length(const std::string& text, double percent_of) {
  size_t i = 0;
  while (i < text.size() && is_space(text[i])) ++i;
  Quantity q;
  if (!read_quantity(text, i, q)) return std::nullopt;
  while (i < text.size() && is_space(text[i])) ++i;
  if (i != text.size()) return std::nullopt;
  if (q.unit == "%") return q.value / 100.0 * percent_of;
  return length_in_px(q.unit, q.value);
}

std::optional<Affine> parse_transform(const std::string& text, std::string& error) {
  // One parser for both spellings: the attribute separates numbers by spaces or commas and has no units
  // (rotate may carry its centre); the property separates them by commas and gives lengths and angles
  // units. Browsers take either spelling in either place, and so does this.
  Affine m;
  size_t i = 0;
  const auto skip = [&] {
    while (i < text.size() && is_space(text[i])) ++i;
  };
  skip();
  if (lower(text.substr(i)).rfind("none", 0) == 0) {
    i += 4;
    skip();
    if (i == text.size()) return m;
    error = "\"none\" followed by more";
    return std::nullopt;
  }
  bool any = false;
  while (true) {
    while (i < text.size() && (is_space(text[i]) || text[i] == ',')) ++i;
    if (i == text.size()) break;
    const size_t name_start = i;
    while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '-')) ++i;
    const std::string name = lower(text.substr(name_start, i - name_start));
    skip();
    if (name.empty() || i == text.size() || text[i] != '(') {
      error = "expected a transform function at character " + std::to_string(name_start + 1);
      return std::nullopt;
    }
    ++i;
    std::vector<Quantity> args;
    while (true) {
      while (i < text.size() && (is_space(text[i]) || text[i] == ',')) ++i;
      if (i < text.size() && text[i] == ')') {
        ++i;
        break;
      }
      Quantity q;
      if (!read_quantity(text, i, q)) {
        error = name + "(): not a number at character " + std::to_string(i + 1);
        return std::nullopt;
      }
      args.push_back(q);
    }
    const auto count_is = [&](size_t lo, size_t hi) {
      if (args.size() >= lo && args.size() <= hi) return true;
      error = name + "() takes " + std::to_string(lo) + (hi > lo ? " to " + std::to_string(hi) : "") + " values, not " +
              std::to_string(args.size());
      return false;
    };
    const auto length = [&](const Quantity& q, double& out) {
      const std::optional<double> px = length_in_px(q.unit, q.value);
      if (px) {
        out = *px;
        return true;
      }
      error = name + "(): unit \"" + q.unit + "\" is not supported here (give px or plain numbers)";
      return false;
    };
    const auto number = [&](const Quantity& q, double& out) {
      if (q.unit.empty()) {
        out = q.value;
        return true;
      }
      error = name + "(): \"" + q.unit + "\" after a number that takes no unit";
      return false;
    };
    const auto angle = [&](const Quantity& q, double& out) {
      double deg = q.value;
      if (q.unit == "rad")
        deg = q.value * 180.0 / std::numbers::pi;
      else if (q.unit == "grad")
        deg = q.value * 0.9;
      else if (q.unit == "turn")
        deg = q.value * 360.0;
      else if (!q.unit.empty() && q.unit != "deg") {
        error = name + "(): \"" + q.unit + "\" is not an angle unit";
        return false;
      }
      out = deg * std::numbers::pi / 180.0;
      return true;
    };
    Affine f;
    if (name == "matrix") {
      if (!count_is(6, 6)) return std::nullopt;
      double v[6];
      for (int k = 0; k < 6; ++k) {
        // matrix()'s translation is in px; SVG's plain numbers are user units, which is the same.
        if (!(k < 4 ? number(args[k], v[k]) : length(args[k], v[k]))) return std::nullopt;
      }
      f = {v[0], v[1], v[2], v[3], v[4], v[5]};
    } else if (name == "translate" || name == "translatex" || name == "translatey") {
      if (!count_is(1, name == "translate" ? 2 : 1)) return std::nullopt;
      double a = 0, b = 0;
      if (!length(args[0], a) || (args.size() > 1 && !length(args[1], b))) return std::nullopt;
      if (name == "translatey") std::swap(a, b);
      f = {1, 0, 0, 1, a, b};
    } else if (name == "scale" || name == "scalex" || name == "scaley") {
      if (!count_is(1, name == "scale" ? 2 : 1)) return std::nullopt;
      double a = 0, b = 0;
      if (!number(args[0], a) || (args.size() > 1 && !number(args[1], b))) return std::nullopt;
      if (name == "scale") {
        if (args.size() == 1) b = a;
      } else if (name == "scalex") {
        b = 1;
      } else {
        b = a, a = 1;
      }
      f = {a, 0, 0, b, 0, 0};
    } else if (name == "rotate") {
      if (args.size() == 2 || !count_is(1, 3)) {
        if (args.size() == 2) error = "rotate() takes an angle, or an angle and a centre (3 values), not 2";
        return std::nullopt;
      }
      double t = 0, cx = 0, cy = 0;
      if (!angle(args[0], t) || (args.size() == 3 && (!length(args[1], cx) || !length(args[2], cy))))
        return std::nullopt;
      const double c = std::cos(t), s = std::sin(t);
      // rotate(a cx cy) is translate(cx cy) rotate(a) translate(-cx -cy).
      f = {c, s, -s, c, cx - c * cx + s * cy, cy - s * cx - c * cy};
    } else if (name == "skewx" || name == "skewy" || name == "skew") {
      if (!count_is(1, name == "skew" ? 2 : 1)) return std::nullopt;
      double ax = 0, ay = 0;
      if (!angle(args[0], ax) || (args.size() > 1 && !angle(args[1], ay))) return std::nullopt;
      if (name == "skewy") std::swap(ax, ay);
      f = {1, std::tan(ay), std::tan(ax), 1, 0, 0};
    } else {
      error = name.find("3d") != std::string::npos || name == "perspective" || name == "translatez" ||
                      name == "scalez" || name == "rotatex" || name == "rotatey" || name == "rotatez"
                  ? name + "() is a 3D transform, which SVG art cannot use"
                  : "unknown transform function " + name + "()";
      return std::nullopt;
    }
    m = compose(m, f);
    any = true;
  }
  if (!any) {
    error = "empty";
    return std::nullopt;
  }
  return m;
}

std::optional<Vec2> parse_transform_origin(const std::string& text, double box_width, double box_height,
                                           std::string& error) {
  // CSS Transforms 1, transform-origin: one to three values; keywords may come in either order, a lone
  // value or keyword leaves the other axis at center, and a third value (z) must be 0 in 2D.
  std::vector<std::string> words;
  {
    std::string w;
    for (char c : text) {
      if (is_space(c)) {
        if (!w.empty()) words.push_back(lower(w)), w.clear();
      } else {
        w += c;
      }
    }
    if (!w.empty()) words.push_back(lower(w));
  }
  if (words.empty() || words.size() > 3) {
    error = "takes one to three values";
    return std::nullopt;
  }
  if (words.size() == 3) {
    const std::optional<double> z = parse_length(words[2], 0.0);
    if (!z || *z != 0.0) {
      error = "a z offset (\"" + words[2] + "\") has no meaning in 2D art";
      return std::nullopt;
    }
    words.pop_back();
  }
  // Each value: which axis it must be on (x, y, or either), and its offset.
  struct Value {
    char axis;  // 'x', 'y' or '?'
    double fraction = 0.0;
    std::optional<double> length;  // when a length rather than a keyword or percentage
  };
  std::vector<Value> values;
  for (const std::string& w : words) {
    if (w == "left")
      values.push_back({'x', 0.0, {}});
    else if (w == "right")
      values.push_back({'x', 1.0, {}});
    else if (w == "top")
      values.push_back({'y', 0.0, {}});
    else if (w == "bottom")
      values.push_back({'y', 1.0, {}});
    else if (w == "center")
      values.push_back({'?', 0.5, {}});
    else {
      size_t i = 0;
      Quantity q;
      if (!read_quantity(w, i, q) || i != w.size()) {
        error = "\"" + w + "\" is neither a length, a percentage nor left, center, right, top or bottom";
        return std::nullopt;
      }
      if (q.unit == "%") {
        values.push_back({'l', q.value / 100.0, {}});
      } else {
        const std::optional<double> px = length_in_px(q.unit, q.value);
        if (!px) {
          error = "unit \"" + q.unit + "\" is not supported (give px, plain numbers or percentages)";
          return std::nullopt;
        }
        values.push_back({'l', 0.0, px});
      }
    }
  }
  // 'l' (a length or percentage) is positional: first x, then y.
  Value x{'x', 0.5, {}}, y{'y', 0.5, {}};
  if (values.size() == 1) {
    if (values[0].axis == 'y')
      y = values[0];
    else
      x = values[0];
  } else {
    Value a = values[0], b = values[1];
    const bool swap = a.axis == 'y' || b.axis == 'x';
    if (swap) std::swap(a, b);
    if (a.axis == 'y' || b.axis == 'x' || (swap && (a.axis == 'l' || b.axis == 'l'))) {
      error = "\"" + text + "\" names the same axis twice, or gives a length before a vertical keyword";
      return std::nullopt;
    }
    x = a, y = b;
  }
  const auto resolve = [](const Value& v, double size) { return v.length ? *v.length : v.fraction * size; };
  return Vec2{resolve(x, box_width), resolve(y, box_height)};
}

}  // namespace animpak::svg
