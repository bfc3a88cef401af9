// Helpers shared by the SVG importer tests: a document wrapper, parsing with a tolerance, exact
// point comparison and error capture.
#pragma once

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "animpak/error.hpp"
#include "animpak/io.hpp"

namespace svg_test {

using animpak::ArtShape;
using animpak::InputError;
using animpak::Vec2;

inline std::string doc(const std::string& body, const std::string& root_attrs = "") {
  return R"~(<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" )~" + root_attrs + ">" +
         body + "</svg>";
}

inline ArtShape parse(const std::string& body, const std::string& root_attrs = "", double tolerance = 0.1) {
  animpak::SvgOptions options;
  options.flatten_tolerance = tolerance;
  return animpak::parse_svg(doc(body, root_attrs), "test.svg", options);
}

inline bool near(Vec2 a, Vec2 b, double eps = 1e-9) { return std::abs(a.x - b.x) <= eps && std::abs(a.y - b.y) <= eps; }

inline void require_points(const std::vector<Vec2>& got, const std::vector<Vec2>& want, double eps = 1e-9) {
  INFO("got " << got.size() << " points, want " << want.size());
  REQUIRE(got.size() == want.size());
  for (size_t i = 0; i < want.size(); ++i) {
    INFO("point " << i << ": (" << got[i].x << ", " << got[i].y << ") want (" << want[i].x << ", " << want[i].y << ")");
    CHECK(near(got[i], want[i], eps));
  }
}

inline std::string error_of(const std::string& text) {
  try {
    animpak::parse_svg(text, "bad.svg");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

inline bool has_warning(const ArtShape& art, const std::string& part) {
  for (const auto& w : art.warnings)
    if (w.find(part) != std::string::npos) return true;
  return false;
}

}  // namespace svg_test
