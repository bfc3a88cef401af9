// Typed reading of a parsed JSON document that remembers where each value sits, so every error names
// the file and the field path (`elements[2].animation.keys[0].t`). Used by the scene file reader.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "animpak/geometry.hpp"

namespace animpak::io_detail {

/// The closest of `candidates` to `word` (edit distance ≤ 2, or one a prefix of the other), or "".
std::string closest_name(std::string_view word, const std::vector<std::string_view>& candidates);

/// `word` between backticks, as every message quotes a name, key or token.
std::string backticked(std::string_view word);

class JsonField {
 public:
  /// `file` names the document in messages and must outlive the field.
  JsonField(const nlohmann::json& value, const std::string& file, std::string path = {});

  const std::string& path() const { return path_; }
  const nlohmann::json& json() const { return *value_; }

  /// Throws InputError `<file>: <path>: <problem>`.
  [[noreturn]] void fail(const std::string& problem) const;

  /// Object access. `check_keys` rejects any key not in `allowed`, suggesting the closest one.
  void check_keys(const std::vector<std::string_view>& allowed) const;
  bool has(std::string_view key) const;
  JsonField required(std::string_view key) const;
  std::optional<JsonField> optional(std::string_view key) const;
  /// Every key of the object in document order, with its field.
  std::vector<std::pair<std::string, JsonField>> members() const;

  /// Array access.
  std::size_t array_size() const;
  JsonField item(std::size_t index) const;

  /// Scalars; each fails with `expected ..., got <value>`.
  double number() const;
  double number_in(double min, double max) const;
  double positive_number() const;
  int integer_in(long long min, long long max) const;
  std::uint64_t unsigned_integer() const;
  bool boolean() const;
  std::string string() const;
  std::string non_empty_string() const;
  /// One of `choices`, as its index.
  std::size_t choice(std::span<const std::string_view> choices) const;
  /// A two-number array `[x, y]`.
  Vec2 point() const;

  /// The value as short JSON text for messages.
  std::string shown() const;

 private:
  /// The field path of member `key`: "key" at the top, "parent.key" below.
  std::string child_path(std::string_view key) const;

  const nlohmann::json* value_;
  const std::string* file_;
  std::string path_;
};

/// Formats a number for messages without trailing zeros (1.5, 1e-06, 250).
std::string format_number(double value);

}  // namespace animpak::io_detail
