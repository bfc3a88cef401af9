// A schema check of the Lottie documents animpak writes: the keys and types the Bodymovin 5.x readers
// (lottie-web, rlottie) need of the root, each layer, shape item, animated property and keyframe
// (docs/animation-formats.md lists them). Each error names its JSON path, e.g.
// "layers[2].shapes[0].it[1].ks.k[3].s: missing".
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace lottie_schema {

using nlohmann::json;

class Checker {
 public:
  std::vector<std::string> errors;

  void document(const json& doc) {
    if (!doc.is_object()) return fail("", "expected an object");
    string_key(doc, "", "v");
    positive(doc, "", "fr");
    const bool times = number_key(doc, "", "ip") && number_key(doc, "", "op");
    if (times && doc["op"].get<double>() <= doc["ip"].get<double>()) fail("op", "not after ip");
    positive_integer(doc, "", "w");
    positive_integer(doc, "", "h");
    if (!array_key(doc, "", "layers")) return;
    for (std::size_t i = 0; i < doc["layers"].size(); ++i) layer(doc["layers"][i], "layers[" + std::to_string(i) + "]");
  }

 private:
  void fail(const std::string& path, const std::string& what) {
    errors.push_back((path.empty() ? "(root)" : path) + ": " + what);
  }
  static std::string at(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }

  bool has(const json& o, const std::string& path, const std::string& key) {
    if (o.contains(key)) return true;
    fail(at(path, key), "missing");
    return false;
  }
  bool number_key(const json& o, const std::string& path, const std::string& key) {
    if (!has(o, path, key)) return false;
    if (o[key].is_number()) return true;
    fail(at(path, key), "expected a number");
    return false;
  }
  void positive(const json& o, const std::string& path, const std::string& key) {
    if (number_key(o, path, key) && o[key].get<double>() <= 0) fail(at(path, key), "expected a positive number");
  }
  bool integer_key(const json& o, const std::string& path, const std::string& key) {
    if (!has(o, path, key)) return false;
    if (o[key].is_number_integer()) return true;
    fail(at(path, key), "expected an integer");
    return false;
  }
  void positive_integer(const json& o, const std::string& path, const std::string& key) {
    if (integer_key(o, path, key) && o[key].get<long long>() <= 0) fail(at(path, key), "expected a positive integer");
  }
  void one_of(const json& o, const std::string& path, const std::string& key, std::vector<int> allowed) {
    if (!integer_key(o, path, key)) return;
    for (int a : allowed)
      if (o[key].get<int>() == a) return;
    fail(at(path, key), "unexpected value " + o[key].dump());
  }
  void string_key(const json& o, const std::string& path, const std::string& key) {
    if (has(o, path, key) && !o[key].is_string()) fail(at(path, key), "expected a string");
  }
  bool array_key(const json& o, const std::string& path, const std::string& key) {
    if (!has(o, path, key)) return false;
    if (o[key].is_array()) return true;
    fail(at(path, key), "expected an array");
    return false;
  }
  bool object_key(const json& o, const std::string& path, const std::string& key) {
    if (!has(o, path, key)) return false;
    if (o[key].is_object()) return true;
    fail(at(path, key), "expected an object");
    return false;
  }

  // A number array of `size` entries (0: any size but one at least).
  void numbers(const json& v, const std::string& path, std::size_t size) {
    if (!v.is_array() || v.empty() || (size && v.size() != size)) {
      return fail(path, size ? "expected " + std::to_string(size) + " numbers" : "expected an array of numbers");
    }
    for (const json& x : v)
      if (!x.is_number()) return fail(path, "expected numbers only");
  }

  // A shape value: vertices v with in and out tangents i, o, as many as v, and the closed flag c.
  void shape_value(const json& v, const std::string& path) {
    if (!v.is_object()) return fail(path, "expected a shape object");
    for (const char* key : {"i", "o", "v"}) {
      if (!array_key(v, path, key)) continue;
      if (v[key].size() != v["v"].size()) fail(at(path, key), "not as many points as v");
      for (std::size_t k = 0; k < v[key].size(); ++k)
        numbers(v[key][k], at(path, key) + "[" + std::to_string(k) + "]", 2);
    }
    if (has(v, path, "c") && !v["c"].is_boolean()) fail(at(path, "c"), "expected true or false");
  }

  enum class Kind { scalar, vector, colour, shape };

  void value(const json& v, const std::string& path, Kind kind) {
    switch (kind) {
      case Kind::scalar:
        if (!v.is_number() && !(v.is_array() && v.size() == 1 && v[0].is_number())) fail(path, "expected a number");
        break;
      case Kind::vector:
        numbers(v, path, 0);
        break;
      case Kind::colour:
        if (!v.is_array() || v.size() < 3 || v.size() > 4) return fail(path, "expected 3 or 4 numbers");
        numbers(v, path, v.size());
        for (const json& c : v)
          if (c.is_number() && (c.get<double>() < 0 || c.get<double>() > 1)) return fail(path, "channel outside 0–1");
        break;
      case Kind::shape:
        shape_value(v, path);
        break;
    }
  }

  // A keyframe's start or end value: shapes and scalars come wrapped in a one-entry array.
  void key_value(const json& v, const std::string& path, Kind kind) {
    if (kind == Kind::shape || kind == Kind::scalar) {
      if (!v.is_array() || v.size() != 1) return fail(path, "expected a one-entry array");
      return value(v[0], path + "[0]", kind);
    }
    value(v, path, kind);
  }

  void easing(const json& key, const std::string& path, const char* name) {
    if (!object_key(key, path, name)) return;
    const json& e = key[name];
    for (const char* axis : {"x", "y"}) {
      if (!has(e, at(path, name), axis)) continue;
      const json& c = e[axis];
      if (!c.is_number() && !(c.is_array() && !c.empty() && c[0].is_number()))
        fail(at(at(path, name), axis), "expected a number or an array of numbers");
    }
  }

  // An animatable property: {"a": 0, "k": value} or {"a": 1, "k": [keyframes]}, times increasing; every
  // keyframe but the last has a start value and, unless it holds, easing.
  void property(const json& o, const std::string& parent, const std::string& key, Kind kind) {
    if (!object_key(o, parent, key)) return;
    const std::string path = at(parent, key);
    const json& p = o[key];
    one_of(p, path, "a", {0, 1});
    if (!has(p, path, "k")) return;
    if (!p["a"].is_number_integer() || p["a"] == 0) return value(p["k"], at(path, "k"), kind);
    if (!array_key(p, path, "k")) return;
    const json& keys = p["k"];
    if (keys.size() < 2) fail(at(path, "k"), "an animated property needs two keyframes at least");
    double previous = -1e300;
    for (std::size_t i = 0; i < keys.size(); ++i) {
      const std::string kp = at(path, "k") + "[" + std::to_string(i) + "]";
      const json& k = keys[i];
      if (!k.is_object()) {
        fail(kp, "expected a keyframe object");
        continue;
      }
      if (number_key(k, kp, "t")) {
        if (k["t"].get<double>() <= previous) fail(at(kp, "t"), "not after the previous keyframe");
        previous = k["t"].get<double>();
      }
      const bool last = i + 1 == keys.size();
      if (k.contains("s"))
        key_value(k["s"], at(kp, "s"), kind);
      else if (!last)
        fail(at(kp, "s"), "missing");
      if (k.contains("e")) key_value(k["e"], at(kp, "e"), kind);
      const bool hold = k.contains("h") && k["h"] == 1;
      if (k.contains("h")) one_of(k, kp, "h", {0, 1});
      if (!last && !hold) easing(k, kp, "i"), easing(k, kp, "o");
    }
  }

  void layer(const json& l, const std::string& path) {
    if (!l.is_object()) return fail(path, "expected a layer object");
    one_of(l, path, "ty", {1, 4});
    string_key(l, path, "nm");
    integer_key(l, path, "ind");
    number_key(l, path, "ip");
    number_key(l, path, "op");
    number_key(l, path, "st");
    if (object_key(l, path, "ks")) {
      const std::string ks = at(path, "ks");
      property(l["ks"], ks, "o", Kind::scalar);
      property(l["ks"], ks, "r", Kind::scalar);
      property(l["ks"], ks, "p", Kind::vector);
      property(l["ks"], ks, "a", Kind::vector);
      property(l["ks"], ks, "s", Kind::vector);
    }
    if (!l.contains("ty") || !l["ty"].is_number_integer()) return;
    if (l["ty"] == 1) {
      string_key(l, path, "sc");
      positive_integer(l, path, "sw");
      positive_integer(l, path, "sh");
    } else if (array_key(l, path, "shapes")) {
      items(l["shapes"], at(path, "shapes"));
    }
  }

  void items(const json& list, const std::string& path) {
    for (std::size_t i = 0; i < list.size(); ++i) item(list[i], path + "[" + std::to_string(i) + "]");
  }

  void item(const json& s, const std::string& path) {
    if (!s.is_object()) return fail(path, "expected a shape item object");
    if (!has(s, path, "ty")) return;
    if (!s["ty"].is_string()) return fail(at(path, "ty"), "expected a string");
    const std::string ty = s["ty"];
    if (ty == "gr") {
      if (!array_key(s, path, "it")) return;
      const json& it = s["it"];
      if (it.empty() || !it.back().is_object() || it.back().value("ty", "") != "tr")
        fail(at(path, "it"), "a group's last item must be its transform (tr)");
      items(it, at(path, "it"));
    } else if (ty == "sh") {
      property(s, path, "ks", Kind::shape);
    } else if (ty == "fl") {
      property(s, path, "c", Kind::colour);
      property(s, path, "o", Kind::scalar);
      one_of(s, path, "r", {1, 2});
    } else if (ty == "st") {
      property(s, path, "c", Kind::colour);
      property(s, path, "o", Kind::scalar);
      property(s, path, "w", Kind::scalar);
      one_of(s, path, "lc", {1, 2, 3});
      one_of(s, path, "lj", {1, 2, 3});
    } else if (ty == "tr") {
      for (const char* key : {"p", "a", "s"}) property(s, path, key, Kind::vector);
      for (const char* key : {"r", "o"}) property(s, path, key, Kind::scalar);
    } else {
      fail(at(path, "ty"), "unexpected shape item type \"" + ty + "\"");
    }
  }
};

/// Every problem found in `doc`, each naming its JSON path; empty when the document passes.
inline std::vector<std::string> errors(const nlohmann::json& doc) {
  Checker c;
  c.document(doc);
  return c.errors;
}

}  // namespace lottie_schema
