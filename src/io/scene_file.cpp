// The scene file: JSON, every field checked here with its path in the message (docs/scene-format.md).
// Only scene-level facts are checked; art files are tested for existence but not opened (the element
// stage reads them), so parsing a scene never reads another file.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <system_error>
#include <type_traits>
#include <variant>
#include <vector>

#include "animpak/error.hpp"
#include "animpak/param_table.hpp"
#include "animpak/scene_spec.hpp"
#include "json_fields.hpp"
#include "scene_animation.hpp"
#include "scene_schema.hpp"
#include "text_file.hpp"

namespace animpak {
namespace {

namespace fs = std::filesystem;
using io_detail::backticked;
using io_detail::format_number;
using io_detail::JsonField;
using io_detail::read_integer;
using io_detail::read_number;
using nlohmann::json;

/// How close the end of one guided path must be to the start of the path it loops into, in art units:
/// far below anything visible, above the rounding of coordinates typed with a few decimals.
constexpr double kLoopTolerance = 1e-6;

fs::path resolve_art(const JsonField& field, const fs::path& base_dir, const ArtLocator& locate) {
  const std::string text = field.non_empty_string();
  const fs::path given(text);
  const fs::path beside = (given.is_absolute() ? given : base_dir / given).lexically_normal();
  const fs::path resolved = locate ? locate(text, beside) : beside;
  std::string extension = resolved.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".svg" && extension != ".path")
    field.fail("\"" + text + "\" is not an art file; expected a .svg or .path file");
  std::error_code ec;
  const fs::path absolute = fs::absolute(resolved, ec);
  if (!fs::is_regular_file(resolved, ec))
    field.fail("cannot read \"" + text + "\" (resolved to " + (ec ? resolved : absolute).string() +
               "); relative paths start at the scene file's folder");
  return resolved;
}

/// The container's `animation` (docs/scene-format.md, "A container that moves"): its whole-body motion,
/// looping when the scene loops; handles and swim bend art, so a container refuses them here.
AnimationSpec read_container_animation(const JsonField& field, bool loop) {
  if (auto f = field.optional("loop"))
    f->fail("a container's animation loops when the scene does (`loop` at the top of the scene); remove it");
  if (auto f = field.optional("handles"))
    f->fail(
        "a container moves as a whole (turn, scale, move); handles would bend it, which animpak does not pack; "
        "use keys or the rotate or pulse preset");
  AnimationSpec spec = io_detail::read_animation(field, loop);
  if (spec.preset == AnimationPreset::swim)
    field.required("preset").fail("swim bends its art, and a container moves as a whole; use rotate, pulse or keys");
  return spec;
}

ContainerSpec read_container(const JsonField& field, const fs::path& base_dir, const ArtLocator& locate, bool loop) {
  ContainerSpec spec;
  // A bare string is the common case: the container is its art's default outline and holes.
  if (field.json().is_string()) {
    spec.art = resolve_art(field, base_dir, locate);
    return spec;
  }
  const io_detail::ObjectSpec& format = io_detail::kContainerObject;
  field.check_keys(format.keys());
  spec.art = resolve_art(field.required("art"), base_dir, locate);
  if (auto f = field.optional("outline")) spec.outline = read_integer(*f, format.at("outline"));
  if (auto f = field.optional("holes")) {
    std::vector<int> holes;
    for (std::size_t i = 0, n = f->array_size(); i < n; ++i) {
      const int hole = read_integer(f->item(i), *format.at("holes").items);
      if (std::find(holes.begin(), holes.end(), hole) != holes.end())
        f->item(i).fail("path " + std::to_string(hole) + " is listed twice");
      if (spec.outline == hole)
        f->item(i).fail("path " + std::to_string(hole) + " is the outline and cannot be a hole");
      holes.push_back(hole);
    }
    spec.holes = std::move(holes);
  }
  if (auto f = field.optional("animation")) spec.animation = read_container_animation(*f, loop);
  if (auto f = field.optional("inherit_scale")) spec.inherit_scale = f->boolean();
  return spec;
}

std::vector<LibraryElementSpec> read_elements(const JsonField& field, const fs::path& base_dir,
                                              const ArtLocator& locate) {
  const io_detail::ObjectSpec& format = io_detail::kElementObject;
  std::vector<LibraryElementSpec> elements;
  const std::size_t n = field.array_size();
  if (n == 0) field.fail("expected at least one element");
  if (n > static_cast<std::size_t>(kMaxLibraryElements))
    field.fail(std::to_string(n) + " entries, more than the " + std::to_string(kMaxLibraryElements) +
               " a scene may list (docs/cli.md, \"Limits\"); copies of one element need one entry with a `count`");
  for (std::size_t i = 0; i < n; ++i) {
    const JsonField item = field.item(i);
    item.check_keys(format.keys());
    LibraryElementSpec e;
    e.art = resolve_art(item.required("art"), base_dir, locate);
    const std::optional<JsonField> name = item.optional("name");
    // The stem of the art as the scene writes it: a packed folder's copy may be stored under another name.
    e.name = name ? name->non_empty_string() : fs::path(item.required("art").non_empty_string()).stem().string();
    for (std::size_t j = 0; j < elements.size(); ++j)
      if (elements[j].name == e.name)
        (name ? *name : item)
            .fail("name " + backticked(e.name) + (name ? "" : " (the art file's stem)") + " is already used by " +
                  field.item(j).path() + "; give each element a unique `name`");
    if (auto f = item.optional("exclude")) {
      std::string extension = e.art.extension().string();
      std::transform(extension.begin(), extension.end(), extension.begin(),
                     [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      if (extension == ".path")
        f->fail(
            "a .path file has no ids or classes to select a piece by; remove `exclude`, or use the art as SVG "
            "with an id on the piece");
      for (std::size_t k = 0, count = f->array_size(); k < count; ++k) {
        const std::string selector = f->item(k).non_empty_string();
        if (std::find(e.exclude.begin(), e.exclude.end(), selector) != e.exclude.end())
          f->item(k).fail("\"" + selector + "\" is listed twice");
        e.exclude.push_back(selector);
      }
    }
    if (auto f = item.optional("animation")) e.animation = io_detail::read_animation(*f);
    if (auto f = item.optional("count")) e.count = read_integer(*f, format.at("count"));
    if (auto f = item.optional("weight")) {
      if (e.count) f->fail("give either `count` or `weight`, not both");
      e.weight = read_number(*f, format.at("weight"));
    }
    if (auto f = item.optional("phase")) {
      const io_detail::FieldSpec& phase = format.at("phase");
      const std::string_view random = phase.alternative->words.front();
      if (f->json().is_string()) {
        if (f->string() != random)
          f->fail("expected a number in [" + format_number(phase.range.min) + ", " + format_number(phase.range.max) +
                  "] or \"" + std::string(random) + "\", got " + f->shown());
        e.random_phase = true;
      } else {
        e.phase = read_number(*f, phase);
      }
    }
    if (auto f = item.optional("secondary")) e.secondary = f->boolean();
    elements.push_back(std::move(e));
  }
  return elements;
}

std::vector<std::string_view> names_of(const auto& items) {
  std::vector<std::string_view> names;
  for (const auto& item : items) names.push_back(item.name);
  return names;
}

std::string unknown_name_problem(const std::string& name, const std::vector<std::string_view>& known,
                                 const std::string& what) {
  std::string problem = "no " + what + " is named " + backticked(name);
  const std::string near = io_detail::closest_name(name, known);
  if (!near.empty()) return problem + "; did you mean " + backticked(near) + "?";
  problem += "; expected one of";
  // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on `" " + std::string` once inlined.
  for (std::string_view k : known) problem.append(" ").append(backticked(k));
  return problem;
}

std::vector<TargetSpec> read_targets(const JsonField& field) {
  const io_detail::ObjectSpec& format = io_detail::kTargetObject;
  std::vector<TargetSpec> targets;
  const std::size_t n = field.array_size();
  if (n < 2) field.fail("expected at least two targets, the first at t = 0 and the last at t = 1");
  for (std::size_t i = 0; i < n; ++i) {
    const JsonField item = field.item(i);
    item.check_keys(format.keys());
    TargetSpec target;
    target.x = read_number(item.required("x"), format.at("x"));
    target.y = read_number(item.required("y"), format.at("y"));
    const JsonField t = item.required("t");
    target.t = read_number(t, format.at("t"));
    if (i == 0 && target.t != 0.0) t.fail("the first target must have t = 0, got " + t.shown());
    if (i == n - 1 && target.t != 1.0) t.fail("the last target must have t = 1, got " + t.shown());
    if (i > 0 && target.t <= targets.back().t)
      t.fail(target.t == targets.back().t ? "duplicate t " + t.shown() + "; each target needs its own time"
                                          : "targets out of order: t " + t.shown() + " comes after t " +
                                                format_number(targets.back().t) + "; list targets by increasing t");
    if (auto f = item.optional("scale")) target.scale = read_number(*f, format.at("scale"));
    if (auto f = item.optional("angle")) target.angle = read_number(*f, format.at("angle"));
    targets.push_back(target);
  }
  return targets;
}

/// Every guided element's t = 1 slice must land on exactly one t = 0 slice: `loop_to` (default: itself)
/// must be a permutation, and the paths must meet where they hand over.
void check_guided_loops(const JsonField& field, const std::vector<GuidedSpec>& guided, bool loop) {
  std::vector<std::size_t> into(guided.size());
  for (std::size_t i = 0; i < guided.size(); ++i) {
    const std::optional<JsonField> loop_to = field.item(i).optional("loop_to");
    into[i] = i;
    if (!loop_to) continue;
    if (!loop) loop_to->fail("needs `loop: true` at the top level; remove it or turn looping on");
    const auto names = names_of(guided);
    const auto found = std::find(names.begin(), names.end(), guided[i].loop_to);
    if (found == names.end()) loop_to->fail(unknown_name_problem(guided[i].loop_to, names, "guided element"));
    into[i] = static_cast<std::size_t>(found - names.begin());
  }
  if (!loop) return;
  for (std::size_t i = 0; i < guided.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (into[i] == into[j]) {
        // Blame the one that names its target; one without loop_to loops into itself implicitly.
        const std::size_t blamed = field.item(i).has("loop_to") ? i : j;
        const std::size_t other = blamed == i ? j : i;
        field.item(blamed).required("loop_to").fail(
            backticked(guided[into[i]].name) + " is already looped into by " + field.item(other).path() + " (" +
            backticked(guided[other].name) +
            (field.item(other).has("loop_to") ? "" : ", which has no `loop_to` and loops into itself") +
            "); loops must be a permutation: each guided element is looped into by exactly one");
      }
  for (std::size_t i = 0; i < guided.size(); ++i) {
    const TargetSpec& last = guided[i].targets.back();
    const TargetSpec& first = guided[into[i]].targets.front();
    const double gap = std::hypot(last.x - first.x, last.y - first.y);
    if (gap <= kLoopTolerance) continue;
    const std::string whose = into[i] == i ? "its own first target (it has no `loop_to`, so it loops into itself)"
                                           : "the first target of " + backticked(guided[into[i]].name) + " (" +
                                                 field.item(into[i]).path() + ".targets[0]), its `loop_to`";
    field.item(i)
        .required("targets")
        .item(guided[i].targets.size() - 1)
        .fail("the last target (" + format_number(last.x) + ", " + format_number(last.y) + ") must meet " + whose +
              " at (" + format_number(first.x) + ", " + format_number(first.y) + ") within " +
              format_number(kLoopTolerance) + " art units, but is " + format_number(gap) +
              " away; move one of them or set `loop` to false");
  }
}

std::vector<GuidedSpec> read_guided(const JsonField& field, const std::vector<LibraryElementSpec>& library, bool loop) {
  std::vector<GuidedSpec> guided;
  if (field.array_size() > static_cast<std::size_t>(kMaxSceneElements))
    field.fail(std::to_string(field.array_size()) + " guided elements, more than the " +
               std::to_string(kMaxSceneElements) + " elements a scene may build (docs/cli.md, \"Limits\")");
  for (std::size_t i = 0, n = field.array_size(); i < n; ++i) {
    const JsonField item = field.item(i);
    item.check_keys(io_detail::kGuidedObject.keys());
    GuidedSpec g;
    const JsonField name = item.required("name");
    g.name = name.non_empty_string();
    for (std::size_t j = 0; j < guided.size(); ++j)
      if (guided[j].name == g.name)
        name.fail("name " + backticked(g.name) + " is already used by " + field.item(j).path() +
                  "; give each guided element a unique `name`");
    const JsonField element = item.required("element");
    g.element = element.non_empty_string();
    const auto library_names = names_of(library);
    if (std::find(library_names.begin(), library_names.end(), g.element) == library_names.end())
      element.fail(unknown_name_problem(g.element, library_names, "element in `elements`"));
    g.targets = read_targets(item.required("targets"));
    if (auto f = item.optional("loop_to")) g.loop_to = f->non_empty_string();
    if (auto f = item.optional("orient"))
      g.orient_path = io_detail::read_choice(*f, io_detail::kGuidedObject.at("orient")) == 1;
    if (auto f = item.optional("facing")) {
      if (!g.orient_path)
        f->fail("`facing` turns the art along its path, which needs \"orient\": \"path\"; add it or remove `facing`");
      g.facing = read_number(*f, io_detail::kGuidedObject.at("facing"));
    }
    guided.push_back(std::move(g));
  }
  check_guided_loops(field, guided, loop);
  return guided;
}

MirrorSpec read_mirror(const JsonField& field) {
  const io_detail::ObjectSpec& format = io_detail::kMirrorObject;
  field.check_keys(format.keys());
  const std::optional<JsonField> x = field.optional("x"), y = field.optional("y");
  if (x && y) y->fail("a mirror line is vertical (x) or horizontal (y), not both; keep one");
  if (!x && !y)
    field.fail("needs the line: {\"x\": X} (vertical) or {\"y\": Y} (horizontal), in container art coordinates");
  MirrorSpec spec;
  spec.vertical = x.has_value();
  spec.at = read_number(x ? *x : *y, format.at(x ? "x" : "y"));
  if (auto f = field.optional("keep")) {
    const std::size_t side = io_detail::read_choice(*f, format.at("keep"));
    if (spec.vertical != (side < 2))
      f->fail(std::string("a ") + (spec.vertical ? "vertical line keeps \"left\" or \"right\""
                                                 : "horizontal line keeps \"top\" or \"bottom\""));
    spec.keep_low = side % 2 == 0;
  }
  return spec;
}

OrientationSpec read_orientation(const JsonField& field) {
  const io_detail::ObjectSpec& format = io_detail::kOrientationObject;
  const io_detail::ObjectSpec& field_format = io_detail::kVectorFieldObject;
  field.check_keys(format.keys());
  OrientationSpec spec;
  if (auto f = field.optional("mode"))
    spec.mode = static_cast<OrientationMode>(io_detail::read_choice(*f, format.at("mode")));
  if (auto f = field.optional("angle")) {
    if (spec.mode != OrientationMode::fixed)
      f->fail("applies only to mode `fixed`; remove it or set `mode` to \"fixed\"");
    spec.angle = read_number(*f, format.at("angle"));
  }
  const std::optional<JsonField> vector_field = field.optional("field");
  if (spec.mode != OrientationMode::field) {
    if (vector_field) vector_field->fail("applies only to mode `field`; remove it or set `mode` to \"field\"");
    return spec;
  }
  if (!vector_field)
    field.fail("mode `field` needs a `field` object ({\"kind\": \"constant\"|\"radial\"|\"tangential\", ...})");
  vector_field->check_keys(field_format.keys());
  spec.field = static_cast<FieldKind>(io_detail::read_choice(vector_field->required("kind"), field_format.at("kind")));
  if (auto f = vector_field->optional("angle")) {
    if (spec.field != FieldKind::constant)
      f->fail("applies only to kind `constant`; radial and tangential fields use `center`");
    spec.angle = read_number(*f, field_format.at("angle"));
  }
  if (auto f = vector_field->optional("center")) {
    if (spec.field == FieldKind::constant)
      f->fail("applies only to kinds `radial` and `tangential`; a constant field uses `angle`");
    spec.center = f->point();
  }
  return spec;
}

void read_param(const JsonField& field, const ParamInfo& info, Params& params) {
  std::visit(
      [&](auto member) {
        using T = std::remove_reference_t<decltype(member(params))>;
        if constexpr (std::is_same_v<T, int>)
          member(params) = field.integer_in(static_cast<long long>(info.min), static_cast<long long>(info.max));
        else
          member(params) = field.number_in(info.min, info.max);
      },
      info.field);
}

const ParamInfo& param_info(std::string_view name) {
  for (const ParamInfo& info : param_table())
    if (info.name == name) return info;
  throw InputError("internal: no parameter named " + std::string(name));
}

void read_params(const JsonField& field, Params& params) {
  std::vector<std::string_view> names;
  for (const ParamInfo& info : param_table()) names.push_back(info.name);
  for (const auto& [key, value] : field.members()) {
    const auto found = std::find(names.begin(), names.end(), key);
    if (found == names.end()) {
      const std::string near = io_detail::closest_name(key, names);
      value.fail(near.empty() ? "unknown parameter; docs/parameters.md lists them all"
                              : "unknown parameter; did you mean " + backticked(near) + "?");
    }
    read_param(value, param_info(key), params);
  }
}

// The elements a scene with fixed counts builds, refused above kMaxSceneElements before any art is read
// (docs/cli.md, "Limits"); a scene that fills is estimated when its container is known (make_world).
void check_element_count(const JsonField& root, const SceneSpec& scene) {
  long long fixed = 0;
  for (const LibraryElementSpec& e : scene.elements) fixed += e.count.value_or(0);
  const long long unguided = scene.count ? std::max<long long>(*scene.count, fixed) : fixed;
  const long long total = unguided + static_cast<long long>(scene.guided.size());
  if (total <= kMaxSceneElements) return;
  const std::string what = std::to_string(total) + " elements (" + std::to_string(unguided) + " unguided, " +
                           std::to_string(scene.guided.size()) + " guided), more than the " +
                           std::to_string(kMaxSceneElements) + " a scene may build (docs/cli.md, \"Limits\"); ";
  if (scene.count) root.required("count").fail("the scene would build " + what + "lower `count`");
  root.required("elements").fail("the elements' counts would build " + what + "lower them");
}

void read_count(const JsonField& field, SceneSpec& scene) {
  const io_detail::FieldSpec& count = io_detail::kSceneObject.at("count");
  const std::string_view fill = count.alternative->words.front();
  if (field.json().is_string()) {
    if (field.string() != fill)
      field.fail("expected an integer or \"" + std::string(fill) + "\", got " + field.shown());
  } else {
    scene.count = read_integer(field, count);
  }
  if (!scene.count) return;
  int fixed = 0;
  bool weighted = false;
  for (const LibraryElementSpec& e : scene.elements) {
    fixed += e.count.value_or(0);
    weighted = weighted || !e.count;
  }
  if (fixed > *scene.count || (!weighted && fixed != *scene.count))
    field.fail(std::to_string(*scene.count) + " unguided elements, but the elements' `count`s add up to " +
               std::to_string(fixed) + (weighted ? "" : " and no element is drawn by weight") +
               "; make them agree or use \"fill\"");
}

// A JSON token of the text for the slip hints: a string ('"'), a number or literal ('v'), or one of
// the punctuation characters {}[]:, as itself; [begin, end) in bytes.
struct JsonToken {
  std::size_t begin = 0, end = 0;
  char kind = 0;
};

// The tokens that begin before byte `stop`: enough to see what the parser stopped at and what came before.
std::vector<JsonToken> json_tokens(const std::string& text, std::size_t stop) {
  std::vector<JsonToken> tokens;
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  const auto punctuation = [](char c) { return std::string_view("{}[]:,").find(c) != std::string_view::npos; };
  std::size_t i = 0;
  while (i < text.size() && i < stop) {
    if (space(text[i])) {
      ++i;
      continue;
    }
    JsonToken t{i, i + 1, punctuation(text[i]) ? text[i] : 'v'};
    if (text[i] == '"') {
      t.kind = '"';
      while (t.end < text.size() && text[t.end] != '"') t.end += text[t.end] == '\\' ? 2 : 1;
      t.end = std::min(t.end + 1, text.size());
    } else if (t.kind == 'v') {
      while (t.end < text.size() && !space(text[t.end]) && !punctuation(text[t.end]) && text[t.end] != '"') ++t.end;
    }
    tokens.push_back(t);
    i = t.end;
  }
  return tokens;
}

// The slip a parse error most likely comes from, as a hint to append: two values with nothing between them
// (a missing comma), or a comma right before a closing bracket (a trailing comma, which JSON forbids).
// `byte` is how far the parser read: the end of the token it stopped at; `what` is its message.
std::string json_slip_hint(const std::string& text, std::size_t byte, const std::string& what) {
  const std::vector<JsonToken> tokens = json_tokens(text, byte);
  if (tokens.size() < 2) return "";
  const JsonToken &before = tokens[tokens.size() - 2], &at = tokens.back();
  const auto line_of = [&](std::size_t offset) {
    return 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n');
  };
  const auto ends_value = [](char k) { return k == '"' || k == 'v' || k == '}' || k == ']'; };
  const auto starts_value = [](char k) { return k == '"' || k == 'v' || k == '{' || k == '['; };
  // Only where the parser wanted the end of the object or array: after a key it wants ':' instead.
  const bool wanted_close =
      what.find("expected '}'") != std::string::npos || what.find("expected ']'") != std::string::npos;
  if (wanted_close && ends_value(before.kind) && starts_value(at.kind)) {
    const auto line = line_of(before.end - 1);
    if (line < line_of(at.begin)) return " (missing comma after line " + std::to_string(line) + "?)";
    const std::size_t line_start = text.rfind('\n', at.begin) == std::string::npos ? 0 : text.rfind('\n', at.begin) + 1;
    return " (missing comma before column " + std::to_string(at.begin - line_start + 1) + " of line " +
           std::to_string(line) + "?)";
  }
  if (before.kind == ',' && (at.kind == '}' || at.kind == ']'))
    return std::string(" (trailing comma at line ") + std::to_string(line_of(before.begin)) + " before the '" +
           at.kind + "': JSON does not allow it; remove the comma)";
  return "";
}

/// How deep a scene's objects and arrays may nest (a real scene nests five or six levels): deeper input is
/// refused while it is parsed, before anything walks or prints it recursively.
constexpr int kMaxNesting = 64;

/// nlohmann's document reader, refusing as it reads a key given twice in one object (nlohmann keeps the
/// last silently; in a hand-written scene that hides a mistake) and nesting deeper than kMaxNesting. A
/// SAX handler, not a parser callback: nlohmann's callback parser searches the enclosing array after
/// every object it closes, so reading grows with the square of an array's length (a scene of 100,000
/// element entries took minutes in a test build; docs/cli.md, "Limits").
class SceneJsonReader : public nlohmann::detail::json_sax_dom_parser<json> {
 public:
  SceneJsonReader(json& document, const std::string& name)
      : nlohmann::detail::json_sax_dom_parser<json>(document, true), name_(name) {}

  bool start_object(std::size_t length) {
    enter();
    open_objects_.emplace_back();
    return json_sax_dom_parser::start_object(length);
  }
  bool key(string_t& text) {
    if (!open_objects_.back().insert(text).second)
      throw InputError(name_ + ": key " + backticked(text) + " appears twice in one object; keep only one");
    return json_sax_dom_parser::key(text);
  }
  bool end_object() {
    open_objects_.pop_back();
    --depth_;
    return json_sax_dom_parser::end_object();
  }
  bool start_array(std::size_t length) {
    enter();
    return json_sax_dom_parser::start_array(length);
  }
  bool end_array() {
    --depth_;
    return json_sax_dom_parser::end_array();
  }

 private:
  void enter() {
    if (depth_ >= kMaxNesting)
      throw InputError(name_ + ": objects and arrays nested more than " + std::to_string(kMaxNesting) +
                       " levels deep; a scene needs a handful, check that this is the scene file");
    ++depth_;
  }

  const std::string& name_;
  int depth_ = 0;  // objects and arrays open around the next value
  std::vector<std::set<std::string>> open_objects_;
};

json parse_json(const std::string& text, const std::string& name) {
  try {
    json document;
    SceneJsonReader reader(document, name);
    json::sax_parse(text, &reader);
    return document;
  } catch (const json::parse_error& e) {
    // what() reads "[json.exception.parse_error.101] parse error at line L, column C: <detail>".
    const std::string what = e.what();
    const std::size_t at = what.find("at line ");
    throw InputError(name + ": malformed JSON " + (at == std::string::npos ? what : what.substr(at)) +
                     json_slip_hint(text, e.byte, what));
  } catch (const json::out_of_range& e) {
    // 406: a number past a double's range, "number overflow parsing '1e999'".
    const std::string what = e.what();
    const std::size_t at = what.find("number overflow");
    throw InputError(name + ": " + (at == std::string::npos ? what : what.substr(at)) +
                     ", a number no double can hold; write a finite number");
  }
}

}  // namespace

SceneSpec parse_scene(const std::string& text, const fs::path& file_for_messages, const fs::path& base_dir,
                      const ArtLocator& locate) {
  const std::string name = file_for_messages.string();
  const json document = parse_json(text, name);
  const JsonField root(document, name);
  // Before the keys: a newer format may have keys this program does not know, and the version explains them.
  if (auto f = root.optional("version")) {
    const int version = f->integer_in(1, std::numeric_limits<int>::max());
    if (version > kSceneFormatVersion)
      f->fail("scene format version " + std::to_string(version) + " is newer than this animpak reads (" +
              std::to_string(kSceneFormatVersion) + "); upgrade animpak to read this scene");
  }
  root.check_keys(io_detail::kSceneObject.keys());
  // `$schema` only points an editor at docs/scene.schema.json; it must be a string, as JSON Schema says.
  if (auto f = root.optional("$schema")) f->string();

  SceneSpec scene;
  scene.file = file_for_messages;
  if (auto f = root.optional("loop")) scene.loop = f->boolean();
  scene.container = read_container(root.required("container"), base_dir, locate, scene.loop);
  scene.elements = read_elements(root.required("elements"), base_dir, locate);
  // A phase shifts the copy's slices round the loop, so the t = 1 slice must meet the t = 0 one.
  for (std::size_t i = 0; i < scene.elements.size() && !scene.loop; ++i)
    if (scene.elements[i].random_phase || scene.elements[i].phase != 0.0)
      root.required("elements")
          .item(i)
          .required("phase")
          .fail(
              "a phase needs a looping scene (`loop`: true): shifting the animation would cut it where t = 1 "
              "meets t = 0; remove the phase or let the scene loop");
  if (auto f = root.optional("guided")) scene.guided = read_guided(*f, scene.elements, scene.loop);
  if (auto f = root.optional("orientation")) scene.orientation = read_orientation(*f);
  if (auto f = root.optional("mirror")) scene.mirror = read_mirror(*f);
  if (auto f = root.optional("count")) read_count(*f, scene);
  if (auto f = root.optional("seed")) scene.seed = f->unsigned_integer();
  if (auto f = root.optional("params")) {
    read_params(*f, scene.params);
    scene.initial_scale_given = f->has("initial_scale");
  }
  if (auto f = root.optional("slices")) {
    if (root.has("params") && root.required("params").has("slices"))
      f->fail("given twice, here and as params.slices; keep one");
    read_param(*f, param_info("slices"), scene.params);
  }
  check_element_count(root, scene);
  return scene;
}

SceneSpec load_scene(const fs::path& file) {
  const std::string text = io_detail::read_text_file(file, "check the scene file's path");
  return parse_scene(text, file, file.parent_path());
}

bool ends_where_it_starts(const GuidedSpec& g) {
  if (g.targets.size() < 2) return false;
  const TargetSpec& first = g.targets.front();
  const auto away = [&](const TargetSpec& t) { return std::hypot(t.x - first.x, t.y - first.y) > kLoopTolerance; };
  return !away(g.targets.back()) && std::any_of(g.targets.begin(), g.targets.end(), away);
}

std::vector<std::string> scene_warnings(const SceneSpec& scene) {
  std::vector<std::string> warnings;
  if (scene.loop) return warnings;
  for (const GuidedSpec& g : scene.guided) {
    if (!ends_where_it_starts(g)) continue;
    const TargetSpec& first = g.targets.front();
    warnings.push_back("guided element \"" + g.name + "\" ends where it starts (x " + format_number(first.x) + ", y " +
                       format_number(first.y) +
                       ") but the scene does not loop; add \"loop\": true to the scene to make the animation "
                       "loop seamlessly");
  }
  return warnings;
}

}  // namespace animpak
