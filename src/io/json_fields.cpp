#include "json_fields.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <vector>

#include "animpak/error.hpp"

namespace animpak::io_detail {
namespace {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string list_of(const std::vector<std::string_view>& words) {
  std::string out;
  for (std::string_view w : words) {
    if (!out.empty()) out += ", ";
    out += backticked(w);
  }
  return out;
}

}  // namespace

// Built by append: GCC 12 warns falsely (-Wrestrict) on `"`" + std::string(word)` once inlined.
std::string backticked(std::string_view word) {
  std::string out(1, '`');
  out.append(word).push_back('`');
  return out;
}

std::string closest_name(std::string_view word, const std::vector<std::string_view>& candidates) {
  std::string best;
  std::size_t best_distance = std::numeric_limits<std::size_t>::max();
  for (std::string_view c : candidates) {
    // A short stub like "a" is a prefix of too much to be a useful hint.
    const bool prefix = word.size() >= 2 && (c.starts_with(word) || word.starts_with(c));
    const std::size_t d = edit_distance(word, c);
    if ((d <= 2 || prefix) && d < best_distance) {
      best = c;
      best_distance = d;
    }
  }
  return best;
}

std::string format_number(double value) {
  // Shortest text that reads back to the same double: 0.1 stays 0.1, 90 stays 90.
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

JsonField::JsonField(const nlohmann::json& value, const std::string& file, std::string path)
    : value_(&value), file_(&file), path_(std::move(path)) {}

void JsonField::fail(const std::string& problem) const {
  throw InputError(*file_ + ": " + (path_.empty() ? std::string("top level") : path_) + ": " + problem);
}

std::string JsonField::shown() const {
  std::string text = value_->dump();
  constexpr std::size_t kLimit = 60;
  if (text.size() > kLimit) text = text.substr(0, kLimit - 3) + "...";
  return text;
}

void JsonField::check_keys(const std::vector<std::string_view>& names) const {
  if (!value_->is_object()) fail("expected an object, got " + shown());
  for (const auto& [key, value] : value_->items()) {
    if (std::find(names.begin(), names.end(), key) != names.end()) continue;
    const std::string near = closest_name(key, names);
    const JsonField field(value, *file_, child_path(key));
    field.fail(near.empty() ? "unknown field; expected one of " + list_of(names)
                            : "unknown field; did you mean " + backticked(near) + "?");
  }
}

std::string JsonField::child_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

bool JsonField::has(std::string_view key) const { return value_->is_object() && value_->contains(key); }

std::optional<JsonField> JsonField::optional(std::string_view key) const {
  if (!value_->is_object()) fail("expected an object, got " + shown());
  const auto found = value_->find(key);
  if (found == value_->end()) return std::nullopt;
  return JsonField(*found, *file_, child_path(key));
}

JsonField JsonField::required(std::string_view key) const {
  std::optional<JsonField> field = optional(key);
  if (!field) fail("missing required field " + backticked(key));
  return *field;
}

std::vector<std::pair<std::string, JsonField>> JsonField::members() const {
  if (!value_->is_object()) fail("expected an object, got " + shown());
  std::vector<std::pair<std::string, JsonField>> out;
  for (const auto& [key, value] : value_->items()) out.emplace_back(key, JsonField(value, *file_, child_path(key)));
  return out;
}

std::size_t JsonField::array_size() const {
  if (!value_->is_array()) fail("expected an array, got " + shown());
  return value_->size();
}

JsonField JsonField::item(std::size_t index) const {
  return JsonField((*value_)[index], *file_, path_ + "[" + std::to_string(index) + "]");
}

double JsonField::number() const {
  if (!value_->is_number()) fail("expected a number, got " + shown());
  const double v = value_->get<double>();
  // nlohmann reads 1e999 as infinity; nothing in a scene means infinity.
  if (!std::isfinite(v)) fail("expected a finite number, got " + shown());
  return v;
}

double JsonField::number_in(double min, double max) const {
  // Stiffnesses have no upper bound: "in [0, inf]" would read oddly.
  const std::string wanted =
      std::isinf(max) ? "expected a number >= " + format_number(min) + ", got "
                      : "expected a number in [" + format_number(min) + ", " + format_number(max) + "], got ";
  if (!value_->is_number()) fail(wanted + shown());
  const double v = value_->get<double>();
  if (!(v >= min && v <= max)) fail(wanted + shown());
  return v;
}

double JsonField::positive_number() const {
  if (!value_->is_number() || !(value_->get<double>() > 0.0) || !std::isfinite(value_->get<double>()))
    fail("expected a number > 0, got " + shown());
  return value_->get<double>();
}

int JsonField::integer_in(long long min, long long max) const {
  const std::string wanted = "expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "], got ";
  // JSON has one number type: 3.0 is accepted as the integer 3, 3.5 is not.
  if (!value_->is_number()) fail(wanted + shown());
  const double v = value_->get<double>();
  if (!(v >= static_cast<double>(min) && v <= static_cast<double>(max)) || std::floor(v) != v) fail(wanted + shown());
  return static_cast<int>(v);
}

std::uint64_t JsonField::unsigned_integer() const {
  const std::string wanted = "expected an integer in [0, 18446744073709551615], got ";
  if (value_->is_number_unsigned()) return value_->get<std::uint64_t>();
  if (value_->is_number_integer() && value_->get<std::int64_t>() >= 0) return value_->get<std::uint64_t>();
  fail(wanted + shown());
}

bool JsonField::boolean() const {
  if (!value_->is_boolean()) fail("expected true or false, got " + shown());
  return value_->get<bool>();
}

std::string JsonField::string() const {
  if (!value_->is_string()) fail("expected a string, got " + shown());
  return value_->get<std::string>();
}

std::string JsonField::non_empty_string() const {
  std::string s = string();
  if (s.empty()) fail("expected a non-empty string, got \"\"");
  return s;
}

std::size_t JsonField::choice(std::span<const std::string_view> choices) const {
  const std::vector<std::string_view> names(choices.begin(), choices.end());
  const std::string wanted = "expected one of " + list_of(names) + ", got " + shown();
  if (!value_->is_string()) fail(wanted);
  const std::string s = value_->get<std::string>();
  const auto found = std::find(names.begin(), names.end(), s);
  if (found != names.end()) return static_cast<std::size_t>(found - names.begin());
  const std::string near = closest_name(s, names);
  fail(near.empty() ? wanted : wanted + "; did you mean " + backticked(near) + "?");
}

Vec2 JsonField::point() const {
  if (!value_->is_array() || value_->size() != 2) fail("expected a point [x, y], got " + shown());
  return {item(0).number(), item(1).number()};
}

}  // namespace animpak::io_detail
