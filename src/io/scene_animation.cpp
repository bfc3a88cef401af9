#include "scene_animation.hpp"

#include "scene_schema.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace animpak::io_detail {
namespace {

// Keys meeting at the loop seam are usually typed twice by hand; allow only rounding noise.
constexpr double kSeamTolerance = 1e-9;

bool near(double a, double b) { return std::abs(a - b) <= kSeamTolerance; }
bool near(Vec2 a, Vec2 b) { return near(a.x, b.x) && near(a.y, b.y); }

// Appended piecewise: GCC 12 warns falsely (-Wrestrict) on `"[" + std::string` once inlined.
std::string show(Vec2 p) {
  std::string out(1, '[');
  out.append(format_number(p.x)).append(", ").append(format_number(p.y)).push_back(']');
  return out;
}

/// t of keys[index], checked against the previous key's t.
double key_time(const JsonField& key, const ObjectSpec& format, std::size_t index, double previous) {
  const JsonField t = key.required("t");
  const double value = read_number(t, format.at("t"));
  if (index > 0 && value == previous) t.fail("duplicate t " + format_number(value) + "; each key needs its own time");
  if (index > 0 && value < previous)
    t.fail("keys out of order: t " + format_number(value) + " comes after t " + format_number(previous) +
           "; list keys by increasing t");
  return value;
}

std::vector<TransformKey> read_transform_keys(const JsonField& field) {
  std::vector<TransformKey> keys;
  for (std::size_t i = 0, n = field.array_size(); i < n; ++i) {
    const JsonField key = field.item(i);
    const ObjectSpec& format = kTransformKeyObject;
    key.check_keys(format.keys());
    TransformKey k;
    k.t = key_time(key, format, i, keys.empty() ? 0.0 : keys.back().t);
    if (auto f = key.optional("translate")) k.translate = f->point();
    if (auto f = key.optional("rotate")) k.rotate = read_number(*f, format.at("rotate"));
    if (auto f = key.optional("scale")) k.scale = read_number(*f, format.at("scale"));
    keys.push_back(k);
  }
  return keys;
}

std::vector<HandleKey> read_handle_keys(const JsonField& field) {
  std::vector<HandleKey> keys;
  const std::size_t n = field.array_size();
  if (n == 0) field.fail("a handle needs at least one key");
  for (std::size_t i = 0; i < n; ++i) {
    const JsonField key = field.item(i);
    key.check_keys(kHandleKeyObject.keys());
    HandleKey k;
    k.t = key_time(key, kHandleKeyObject, i, keys.empty() ? 0.0 : keys.back().t);
    k.position = key.required("position").point();
    keys.push_back(k);
  }
  return keys;
}

/// With looping, the motion at t = 1 must be the motion at t = 0, or the seam jumps.
void check_transform_seam(const JsonField& keys_field, const std::vector<TransformKey>& keys) {
  if (keys.size() < 2 || keys.front().t != 0.0 || keys.back().t != 1.0) return;
  const TransformKey& a = keys.front();
  const TransformKey& b = keys.back();
  if (near(a.translate, b.translate) && near(a.rotate, b.rotate) && near(a.scale, b.scale)) return;
  keys_field.item(keys.size() - 1)
      .fail("the key at t = 1 differs from the key at t = 0 (translate " + show(b.translate) + " vs " +
            show(a.translate) + ", rotate " + format_number(b.rotate) + " vs " + format_number(a.rotate) + ", scale " +
            format_number(b.scale) + " vs " + format_number(a.scale) +
            ") in a looping animation; make them equal, drop the t = 1 key, or set `loop` to false");
}

void check_handle_seam(const JsonField& keys_field, const std::vector<HandleKey>& keys) {
  if (keys.size() < 2 || keys.front().t != 0.0 || keys.back().t != 1.0) return;
  if (near(keys.front().position, keys.back().position)) return;
  keys_field.item(keys.size() - 1)
      .fail("the key at t = 1 (position " + show(keys.back().position) + ") differs from the key at t = 0 (" +
            show(keys.front().position) +
            ") in a looping animation; make them equal, drop the t = 1 key, or set `loop` to false");
}

}  // namespace

AnimationSpec read_animation(const JsonField& field, bool loop) {
  const ObjectSpec& format = kAnimationObject;
  field.check_keys(format.keys());
  AnimationSpec spec;
  spec.loop = loop;
  if (auto f = field.optional("preset"))
    spec.preset = static_cast<AnimationPreset>(read_choice(*f, format.at("preset")));

  // A parameter of another preset is almost always a mistake (a preset changed, its knobs left behind).
  struct Knob {
    const char* name;
    bool applies;
  };
  const AnimationPreset p = spec.preset;
  const Knob knobs[] = {{"turns", p == AnimationPreset::rotate},
                        {"amplitude", p == AnimationPreset::pulse || p == AnimationPreset::swim},
                        {"count", p == AnimationPreset::pulse || p == AnimationPreset::swim},
                        {"wavelength", p == AnimationPreset::swim}};
  for (const Knob& knob : knobs) {
    const std::optional<JsonField> f = field.optional(knob.name);
    if (!f || knob.applies) continue;
    if (!field.has("preset")) f->fail("needs a `preset`; add one or remove this field");
    f->fail("does not apply to preset `" + field.required("preset").string() + "`; remove it or change the preset");
  }

  if (auto f = field.optional("turns")) spec.turns = read_number(*f, format.at("turns"));
  if (auto f = field.optional("amplitude")) {
    const Range range = format.at("amplitude").range;
    spec.amplitude = f->number_in(range.min, p == AnimationPreset::pulse ? kPulseAmplitudeMax : range.max);
  }
  if (auto f = field.optional("count")) spec.count = read_integer(*f, format.at("count"));
  if (auto f = field.optional("wavelength")) spec.wavelength = read_number(*f, format.at("wavelength"));
  if (auto f = field.optional("loop")) spec.loop = f->boolean();
  if (auto f = field.optional("pivot")) spec.pivot = f->point();

  if (auto f = field.optional("keys")) {
    spec.keys = read_transform_keys(*f);
    if (spec.loop) check_transform_seam(*f, spec.keys);
  }
  if (auto f = field.optional("handles")) {
    for (std::size_t i = 0, n = f->array_size(); i < n; ++i) {
      const JsonField handle = f->item(i);
      handle.check_keys(kHandleObject.keys());
      HandleSpec h;
      h.point = handle.required("point").point();
      for (std::size_t j = 0; j < spec.handles.size(); ++j)
        if (spec.handles[j].point == h.point)
          handle.required("point").fail("same point as " + f->item(j).path() + "; give each handle its own point");
      const JsonField keys = handle.required("keys");
      h.keys = read_handle_keys(keys);
      if (spec.loop) check_handle_seam(keys, h.keys);
      spec.handles.push_back(std::move(h));
    }
  }
  if (spec.preset != AnimationPreset::none && (!spec.keys.empty() || !spec.handles.empty()))
    field.required(spec.keys.empty() ? "handles" : "keys")
        .fail(
            "a preset is a complete animation and cannot be mixed with keys or handles; "
            "use `preset` alone, or express the motion with keys");
  return spec;
}

}  // namespace animpak::io_detail
