// The scene format's tables (scene_schema.hpp) and their JSON Schema, docs/scene.schema.json. The
// meanings are the short ones of docs/scene-format.md, which explains each field in full.
#include "scene_schema.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "animpak/param_table.hpp"
#include "animpak/scene_spec.hpp"

namespace animpak::io_detail {
namespace {

using Type = ValueType;

constexpr Range kCount{0, 100000};
constexpr Range kUnit{0.0, 1.0};
constexpr Range kPositive{0.0};

constexpr std::array<std::string_view, 1> kFill{"fill"};
constexpr std::array<std::string_view, 1> kRandom{"random"};
// Choices in the order of their enums (AnimationPreset, OrientationMode, FieldKind): the parser casts
// the index.
constexpr std::array<std::string_view, 4> kPresets{"none", "rotate", "pulse", "swim"};
constexpr std::array<std::string_view, 3> kModes{"random", "fixed", "field"};
constexpr std::array<std::string_view, 3> kKinds{"constant", "radial", "tangential"};
constexpr std::array<std::string_view, 4> kKeepSides{"left", "right", "top", "bottom"};
constexpr std::array<std::string_view, 2> kOrients{"none", "path"};

const FieldSpec kPathIndex{.key = "", .type = Type::integer, .meaning = "", .range = kCount};
const FieldSpec kSelector{.key = "", .type = Type::string, .meaning = ""};
const FieldSpec kFillWord{.key = "", .type = Type::word, .meaning = "as many as fit", .words = kFill};
const FieldSpec kRandomWord{.key = "", .type = Type::word, .meaning = "each copy at its own slice", .words = kRandom};

const std::array kContainerFields{
    FieldSpec{.key = "art", .type = Type::art, .meaning = "the container's art file", .required = true},
    FieldSpec{.key = "outline", .type = Type::integer, .meaning = "source index of the outline path", .range = kCount},
    FieldSpec{.key = "holes",
              .type = Type::array,
              .meaning = "source indices of the hole paths, not the outline",
              .items = &kPathIndex,
              .distinct = true},
    FieldSpec{.key = "animation",
              .type = Type::object,
              .meaning = "its motion as a whole: the rotate or pulse preset, or keys; loops when the scene does",
              .object = &kAnimationObject},
    FieldSpec{.key = "inherit_scale",
              .type = Type::boolean,
              .meaning = "the elements scale with an animated container (default true)"},
};

const FieldSpec kTransformKeyItem{.key = "", .type = Type::object, .meaning = "", .object = &kTransformKeyObject};
const std::array kTransformKeyFields{
    FieldSpec{
        .key = "t", .type = Type::number, .meaning = "key time, strictly increasing", .required = true, .range = kUnit},
    FieldSpec{.key = "translate", .type = Type::point, .meaning = "offset in element art units"},
    FieldSpec{.key = "rotate", .type = Type::number, .meaning = "degrees about the pivot, clockwise on screen"},
    FieldSpec{.key = "scale",
              .type = Type::number,
              .meaning = "uniform scale about the pivot",
              .range = kPositive,
              .above_min = true},
};

const FieldSpec kHandleKeyItem{.key = "", .type = Type::object, .meaning = "", .object = &kHandleKeyObject};
const std::array kHandleKeyFields{
    FieldSpec{
        .key = "t", .type = Type::number, .meaning = "key time, strictly increasing", .required = true, .range = kUnit},
    FieldSpec{
        .key = "position", .type = Type::point, .meaning = "where the handle's point is at time t", .required = true},
};

const FieldSpec kHandleItem{.key = "", .type = Type::object, .meaning = "", .object = &kHandleObject};
const std::array kHandleFields{
    FieldSpec{.key = "point",
              .type = Type::point,
              .meaning = "a point of the undeformed art, distinct among handles",
              .required = true},
    FieldSpec{.key = "keys",
              .type = Type::array,
              .meaning = "where that point is over time",
              .required = true,
              .range = {1},
              .items = &kHandleKeyItem},
};

const std::array kAnimationFields{
    FieldSpec{.key = "preset",
              .type = Type::choice,
              .meaning = "a built-in animation; not with keys or handles",
              .words = kPresets},
    FieldSpec{.key = "turns", .type = Type::number, .meaning = "rotate only: turns per loop"},
    FieldSpec{.key = "amplitude",
              .type = Type::number,
              .meaning = "pulse ([0, 0.9]): relative scale change; swim: bend as a fraction of the body length",
              .range = kUnit},
    FieldSpec{.key = "count",
              .type = Type::integer,
              .meaning = "pulse: pulses per loop; swim: waves per loop",
              .range = {1, 100}},
    FieldSpec{.key = "wavelength",
              .type = Type::number,
              .meaning = "swim only: wave length as a fraction of the body length",
              .range = {0.05, 10.0}},
    FieldSpec{.key = "loop", .type = Type::boolean, .meaning = "the animation is periodic: t = 1 equals t = 0"},
    FieldSpec{.key = "pivot", .type = Type::point, .meaning = "centre of rotation and scaling, element art units"},
    FieldSpec{.key = "keys",
              .type = Type::array,
              .meaning = "keyed transforms of the whole element",
              .items = &kTransformKeyItem},
    FieldSpec{.key = "handles", .type = Type::array, .meaning = "keyed vertex handles", .items = &kHandleItem},
};

const FieldSpec kElementItem{.key = "", .type = Type::object, .meaning = "", .object = &kElementObject};
const std::array kElementFields{
    FieldSpec{.key = "name", .type = Type::string, .meaning = "unique; default: the art file's stem"},
    FieldSpec{.key = "art", .type = Type::art, .meaning = "the element's art file", .required = true},
    FieldSpec{.key = "exclude",
              .type = Type::array,
              .meaning = "SVG elements left out of the art, from its outline and its drawing: \"#id\", \".class\"",
              .items = &kSelector,
              .distinct = true},
    FieldSpec{.key = "animation",
              .type = Type::object,
              .meaning = "its scripted animation (§3.2)",
              .object = &kAnimationObject},
    FieldSpec{.key = "count", .type = Type::integer, .meaning = "exact number of unguided copies", .range = kCount},
    FieldSpec{.key = "weight",
              .type = Type::number,
              .meaning = "relative frequency of copies; not with count",
              .range = kPositive,
              .above_min = true},
    FieldSpec{.key = "phase",
              .type = Type::number,
              .meaning = "where in its loop each copy's animation starts; needs a looping scene",
              .range = kUnit,
              .alternative = &kRandomWord},
    FieldSpec{.key = "secondary", .type = Type::boolean, .meaning = "its copies are secondary elements"},
};

const FieldSpec kTargetItem{.key = "", .type = Type::object, .meaning = "", .object = &kTargetObject};
const std::array kTargetFields{
    FieldSpec{.key = "x", .type = Type::number, .meaning = "container art coordinates", .required = true},
    FieldSpec{.key = "y", .type = Type::number, .meaning = "container art coordinates", .required = true},
    FieldSpec{.key = "t",
              .type = Type::number,
              .meaning = "first 0, last 1, strictly increasing",
              .required = true,
              .range = kUnit},
    FieldSpec{.key = "scale",
              .type = Type::number,
              .meaning = "size relative to the element's packed size",
              .range = kPositive,
              .above_min = true},
    FieldSpec{.key = "angle", .type = Type::number, .meaning = "orientation in degrees, held at the target"},
};

const FieldSpec kGuidedItem{.key = "", .type = Type::object, .meaning = "", .object = &kGuidedObject};
const std::array kGuidedFields{
    FieldSpec{.key = "name", .type = Type::string, .meaning = "unique among guided elements", .required = true},
    FieldSpec{.key = "element", .type = Type::string, .meaning = "a name in elements", .required = true},
    FieldSpec{.key = "targets",
              .type = Type::array,
              .meaning = "spacetime points its anchor passes through",
              .required = true,
              .range = {2},
              .items = &kTargetItem},
    FieldSpec{.key = "loop_to",
              .type = Type::string,
              .meaning = "the guided element its t = 1 slice meets at t = 0; default: itself"},
    FieldSpec{.key = "orient",
              .type = Type::choice,
              .meaning = "\"path\": turned to face along its path (targets' angles still win); default \"none\"",
              .words = kOrients},
    FieldSpec{
        .key = "facing",
        .type = Type::number,
        .meaning = "with orient \"path\": the way the art faces as drawn, in degrees (0 right, 90 down, 180 left)"},
};

const std::array kVectorFieldFields{
    FieldSpec{.key = "kind", .type = Type::choice, .meaning = "the field's shape", .required = true, .words = kKinds},
    FieldSpec{.key = "angle", .type = Type::number, .meaning = "constant only: the field's direction in degrees"},
    FieldSpec{.key = "center", .type = Type::point, .meaning = "radial and tangential only: container art coordinates"},
};

const std::array kOrientationFields{
    FieldSpec{.key = "mode",
              .type = Type::choice,
              .meaning = "how unguided elements are turned at the start",
              .words = kModes},
    FieldSpec{.key = "angle", .type = Type::number, .meaning = "fixed only: every element's angle in degrees"},
    FieldSpec{.key = "field",
              .type = Type::object,
              .meaning = "field only: the direction field",
              .object = &kVectorFieldObject},
};

const std::array kMirrorFields{
    FieldSpec{
        .key = "x", .type = Type::number, .meaning = "a vertical mirror line at this x (container art coordinates)"},
    FieldSpec{
        .key = "y", .type = Type::number, .meaning = "a horizontal mirror line at this y (container art coordinates)"},
    FieldSpec{.key = "keep",
              .type = Type::choice,
              .meaning = "the side simulated: left or right of a vertical line (default left), top or bottom of a "
                         "horizontal one (default top)",
              .words = kKeepSides},
};

const FieldSpec kContainerArt{.key = "", .type = Type::art, .meaning = "the container's art file"};
const std::array kSceneFields{
    FieldSpec{.key = "container",
              .type = Type::object,
              .meaning = "the container; a string is its art file",
              .required = true,
              .object = &kContainerObject,
              .alternative = &kContainerArt},
    FieldSpec{.key = "elements",
              .type = Type::array,
              .meaning = "the library of elements to pack",
              .required = true,
              .range = {1},
              .items = &kElementItem},
    FieldSpec{.key = "guided",
              .type = Type::array,
              .meaning = "elements that pass through target points (§4)",
              .items = &kGuidedItem},
    FieldSpec{.key = "orientation",
              .type = Type::object,
              .meaning = "initial orientation of unguided elements",
              .object = &kOrientationObject},
    FieldSpec{.key = "mirror",
              .type = Type::object,
              .meaning = "mirror symmetry: simulate one side of the line, draw its reflection on the other",
              .object = &kMirrorObject},
    FieldSpec{.key = "count",
              .type = Type::integer,
              .meaning = "unguided elements to seed; default \"fill\"",
              .range = kCount,
              .alternative = &kFillWord},
    FieldSpec{.key = "seed", .type = Type::seed, .meaning = "the one random seed of the run"},
    FieldSpec{.key = "loop", .type = Type::boolean, .meaning = "the t = 1 plane meets the t = 0 plane (§5.2)"},
    FieldSpec{.key = "slices", .type = Type::param, .meaning = "n_s, the same as params.slices (give one)"},
    FieldSpec{.key = "params", .type = Type::params, .meaning = "overrides of the constants (docs/parameters.md)"},
    FieldSpec{.key = "$schema", .type = Type::any_string, .meaning = "ignored: lets an editor find this schema"},
    FieldSpec{.key = "version",
              .type = Type::integer,
              .meaning = "the scene format version; default 1",
              .range = {1, kSceneFormatVersion}},
};

using nlohmann::ordered_json;

/// Whole numbers as JSON integers, so that the schema reads `"minimum": 0`, not `0.0`.
ordered_json number_json(double value) {
  if (std::floor(value) == value && std::abs(value) < 1e15) return static_cast<long long>(value);
  return value;
}

const ParamInfo& param_named(std::string_view name) {
  for (const ParamInfo& info : param_table())
    if (info.name == name) return info;
  throw std::logic_error("no parameter named " + std::string(name));
}

void add_range(ordered_json& schema, const ParamInfo& info) {
  schema["minimum"] = number_json(info.min);
  if (std::isfinite(info.max)) schema["maximum"] = number_json(info.max);
}

ordered_json params_schema() {
  ordered_json properties = ordered_json::object();
  for (const ParamInfo& info : param_table()) {
    ordered_json p;
    p["description"] = info.meaning;
    p["type"] = param_is_integer(info) ? "integer" : "number";
    add_range(p, info);
    p["default"] = number_json(param_value(Params{}, info));
    properties[std::string(info.name)] = std::move(p);
  }
  ordered_json schema;
  schema["description"] = "overrides of the constants by name; docs/parameters.md explains each";
  schema["type"] = "object";
  schema["properties"] = std::move(properties);
  schema["additionalProperties"] = false;
  return schema;
}

ordered_json strings(std::span<const std::string_view> words) {
  ordered_json out = ordered_json::array();
  for (std::string_view w : words) out.push_back(std::string(w));
  return out;
}

ordered_json value_schema(const FieldSpec& field) {
  ordered_json s;
  if (!field.meaning.empty() && !field.alternative) s["description"] = field.meaning;
  switch (field.type) {
    case Type::number:
      s["type"] = "number";
      if (std::isfinite(field.range.min))
        s[field.above_min ? "exclusiveMinimum" : "minimum"] = number_json(field.range.min);
      if (std::isfinite(field.range.max)) s["maximum"] = number_json(field.range.max);
      break;
    case Type::integer:
      s["type"] = "integer";
      s["minimum"] = number_json(field.range.min);
      s["maximum"] = number_json(field.range.max);
      break;
    case Type::param: {
      const ParamInfo& info = param_named(field.key);
      s["type"] = param_is_integer(info) ? "integer" : "number";
      add_range(s, info);
      break;
    }
    case Type::seed:
      s["type"] = "integer";
      s["minimum"] = 0;
      s["maximum"] = std::numeric_limits<std::uint64_t>::max();
      break;
    case Type::boolean:
      s["type"] = "boolean";
      break;
    case Type::string:
      s["type"] = "string";
      s["minLength"] = 1;
      break;
    case Type::any_string:
      s["type"] = "string";
      break;
    case Type::art:
      s["type"] = "string";
      s["pattern"] = "\\.([sS][vV][gG]|[pP][aA][tT][hH])$";
      break;
    case Type::point:
      s["type"] = "array";
      s["items"] = {{"type", "number"}};
      s["minItems"] = 2;
      s["maxItems"] = 2;
      break;
    case Type::choice:
      s["enum"] = strings(field.words);
      break;
    case Type::word:
      s["const"] = field.words.front();
      break;
    case Type::object:
      s["$ref"] = "#/$defs/" + std::string(field.object->name);
      break;
    case Type::params:
      s["$ref"] = "#/$defs/params";
      break;
    case Type::array:
      s["type"] = "array";
      s["items"] = value_schema(*field.items);
      if (field.range.min > 0) s["minItems"] = number_json(field.range.min);
      if (field.distinct) s["uniqueItems"] = true;
      break;
  }
  if (!field.alternative) return s;
  ordered_json either;
  if (!field.meaning.empty()) either["description"] = field.meaning;
  either["anyOf"] = ordered_json::array({s, value_schema(*field.alternative)});
  return either;
}

ordered_json object_schema(const ObjectSpec& object) {
  ordered_json s;
  s["description"] = object.meaning;
  s["type"] = "object";
  ordered_json properties = ordered_json::object();
  std::vector<std::string> required;
  for (const FieldSpec& field : object.fields) {
    properties[std::string(field.key)] = value_schema(field);
    if (field.required) required.emplace_back(field.key);
  }
  s["properties"] = std::move(properties);
  if (!required.empty()) s["required"] = required;
  s["additionalProperties"] = false;
  return s;
}

/// Every object reachable from `object`'s fields, in the order first met, for `$defs`.
void collect_objects(const ObjectSpec& object, std::vector<const ObjectSpec*>& out) {
  for (const FieldSpec& field : object.fields) {
    const ObjectSpec* inner = field.type == Type::array ? field.items->object : field.object;
    if (!inner || std::find(out.begin(), out.end(), inner) != out.end()) continue;
    out.push_back(inner);
    collect_objects(*inner, out);
  }
}

}  // namespace

const ObjectSpec kSceneObject{"scene", "an animpak scene (docs/scene-format.md)", kSceneFields};
const ObjectSpec kContainerObject{"container", "the container's art and which of its paths are outline and holes",
                                  kContainerFields};
const ObjectSpec kElementObject{"element", "one element of the library", kElementFields};
const ObjectSpec kAnimationObject{"animation", "a preset, or keys and handles", kAnimationFields};
const ObjectSpec kTransformKeyObject{"transform_key", "a keyed transform of the whole element", kTransformKeyFields};
const ObjectSpec kHandleObject{"handle", "a keyed vertex handle", kHandleFields};
const ObjectSpec kHandleKeyObject{"handle_key", "a keyed position of a handle", kHandleKeyFields};
const ObjectSpec kGuidedObject{"guided", "an element that passes through target points", kGuidedFields};
const ObjectSpec kTargetObject{"target", "a spacetime point of a guided element", kTargetFields};
const ObjectSpec kOrientationObject{"orientation", "how unguided elements are turned at the start", kOrientationFields};
const ObjectSpec kVectorFieldObject{"vector_field", "a direction field the elements align with", kVectorFieldFields};
const ObjectSpec kMirrorObject{"mirror", "a vertical (x) or horizontal (y) line the packing is mirrored across",
                               kMirrorFields};

std::vector<std::string_view> ObjectSpec::keys() const {
  std::vector<std::string_view> out;
  for (const FieldSpec& field : fields) out.push_back(field.key);
  return out;
}

const FieldSpec& ObjectSpec::at(std::string_view key) const {
  for (const FieldSpec& field : fields)
    if (field.key == key) return field;
  throw std::logic_error("the scene table " + std::string(name) + " has no key " + std::string(key));
}

double read_number(const JsonField& field, const FieldSpec& spec) {
  // Every field above its minimum is above 0 with no maximum: a scale, a weight.
  if (spec.above_min) return field.positive_number();
  if (!std::isfinite(spec.range.min) && !std::isfinite(spec.range.max)) return field.number();
  return field.number_in(spec.range.min, spec.range.max);
}

int read_integer(const JsonField& field, const FieldSpec& spec) {
  return field.integer_in(static_cast<long long>(spec.range.min), static_cast<long long>(spec.range.max));
}

std::size_t read_choice(const JsonField& field, const FieldSpec& spec) { return field.choice(spec.words); }

}  // namespace animpak::io_detail

namespace animpak {

std::string scene_json_schema() {
  using io_detail::kSceneObject;
  nlohmann::ordered_json schema;
  schema["$schema"] = "https://json-schema.org/draft/2020-12/schema";
  schema["title"] = "animpak scene, format version " + std::to_string(kSceneFormatVersion);
  const nlohmann::ordered_json root = io_detail::object_schema(kSceneObject);
  for (const auto& [key, value] : root.items()) schema[key] = value;
  std::vector<const io_detail::ObjectSpec*> objects;
  io_detail::collect_objects(kSceneObject, objects);
  nlohmann::ordered_json defs;
  for (const io_detail::ObjectSpec* object : objects)
    defs[std::string(object->name)] = io_detail::object_schema(*object);
  defs["params"] = io_detail::params_schema();
  schema["$defs"] = std::move(defs);
  return schema.dump(2) + "\n";
}

}  // namespace animpak
