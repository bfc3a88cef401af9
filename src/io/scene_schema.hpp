// The scene format's objects as tables: every key, its value's type and range, whether it is required.
// The parser (scene_file.cpp, scene_animation.cpp) takes its key lists, choices and ranges from here, and
// scene_schema.cpp writes the same tables as docs/scene.schema.json, so the two cannot drift apart. What
// a table cannot say (one field depending on another, names that must be unique) only the parser checks.
#pragma once

#include <limits>
#include <span>
#include <string_view>
#include <vector>

#include "json_fields.hpp"

namespace animpak::io_detail {

enum class ValueType {
  number,   ///< finite, within `range` (`above_min`: strictly above its min)
  integer,  ///< within `range`; 3.0 counts as 3
  seed,     ///< an integer in [0, 2⁶⁴−1]
  boolean,
  string,      ///< non-empty
  any_string,  ///< any string, even empty
  art,         ///< a non-empty path to a .svg or .path file
  point,       ///< [x, y]
  choice,      ///< one of `words`
  word,        ///< exactly `words[0]`
  object,      ///< an object of the keys of `object`
  array,       ///< of `items`, their count within `range`
  param,       ///< the constant of param_table() named like the field, in its range
  params,      ///< the overridable constants of param_table()
};

struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
};

struct ObjectSpec;

struct FieldSpec {
  std::string_view key;  ///< empty for the items of an array
  ValueType type;
  std::string_view meaning;
  bool required = false;
  Range range = {};
  bool above_min = false;
  const ObjectSpec* object = nullptr;
  const FieldSpec* items = nullptr;
  std::span<const std::string_view> words = {};
  const FieldSpec* alternative = nullptr;  ///< a value of this form is accepted instead
  bool distinct = false;                   ///< array: no two items equal
};

struct ObjectSpec {
  std::string_view name;  ///< its name under the schema's `$defs`
  std::string_view meaning;
  std::span<const FieldSpec> fields;

  std::vector<std::string_view> keys() const;
  /// The field of `key`; a key missing from the table is a programming error (std::logic_error).
  const FieldSpec& at(std::string_view key) const;
};

/// Pulse scales by 1 ± amplitude: at 1 the element would vanish. The table's range is swim's [0, 1].
inline constexpr double kPulseAmplitudeMax = 0.9;

extern const ObjectSpec kSceneObject;
extern const ObjectSpec kContainerObject;
extern const ObjectSpec kElementObject;
extern const ObjectSpec kAnimationObject;
extern const ObjectSpec kTransformKeyObject;
extern const ObjectSpec kHandleObject;
extern const ObjectSpec kHandleKeyObject;
extern const ObjectSpec kGuidedObject;
extern const ObjectSpec kTargetObject;
extern const ObjectSpec kOrientationObject;
extern const ObjectSpec kVectorFieldObject;
extern const ObjectSpec kMirrorObject;

/// `field` as a number or integer within `spec`'s range.
double read_number(const JsonField& field, const FieldSpec& spec);
int read_integer(const JsonField& field, const FieldSpec& spec);
/// `field` as one of `spec`'s words, as its index.
std::size_t read_choice(const JsonField& field, const FieldSpec& spec);

}  // namespace animpak::io_detail
