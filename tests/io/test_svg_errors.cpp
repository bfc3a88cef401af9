// SVG importer on hostile or broken input: entities, bombs, malformed data, files and their limits.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "io/svg_helpers.hpp"
#include "temp_dir.hpp"

using namespace svg_test;

TEST_CASE("svg: an external entity is never read", "[svg]") {
  const std::string xxe = R"~(<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY x SYSTEM "file:///etc/passwd">]>
<svg xmlns="http://www.w3.org/2000/svg"><path id="p" d="M0 0 L1 0 L1 1 Z"/><text id="t">&x;</text><desc>&x;</desc></svg>)~";
  try {
    const auto art = animpak::parse_svg(xxe, "xxe.svg");
    for (const auto& w : art.warnings) CHECK(w.find("root:") == std::string::npos);
    for (const auto& p : art.paths) CHECK(p.id.find("root:") == std::string::npos);
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("root:") == std::string::npos);
    CHECK(std::string(e.what()).find("xxe.svg") != std::string::npos);
  }
}

TEST_CASE("svg: a billion-laughs entity bomb is an InputError", "[svg]") {
  std::string dtd = R"~(<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY l0 "hahahahahahahahahaha">)~";
  for (int i = 1; i <= 10; ++i) {
    dtd += "<!ENTITY l" + std::to_string(i) + " \"";
    for (int j = 0; j < 10; ++j) dtd += "&l" + std::to_string(i - 1) + ";";
    dtd += "\">";
  }
  dtd += R"~(]><svg xmlns="http://www.w3.org/2000/svg"><path id="&l10;" d="M0 0 L1 0 L1 1 Z"/></svg>)~";
  CHECK_THROWS_AS(animpak::parse_svg(dtd, "bomb.svg"), InputError);
}

TEST_CASE("svg: a use bomb stops at the budget", "[svg]") {
  std::string body = R"~(<defs><path id="u0" d="M0 0 L1 0 L1 1 Z"/>)~";
  for (int i = 1; i <= 9; ++i) {
    body += "<g id=\"u" + std::to_string(i) + "\">";
    for (int j = 0; j < 10; ++j) body += "<use href=\"#u" + std::to_string(i - 1) + "\"/>";
    body += "</g>";
  }
  body += R"~(</defs><use href="#u9"/>)~";
  CHECK_THROWS_AS(parse(body), InputError);
}

TEST_CASE("svg: flattening respects the tolerance", "[svg]") {
  for (double tol : {1.0, 0.1, 0.001}) {
    const auto art = parse(R"~(<g transform="scale(10)"><circle cx="10" cy="10" r="8"/></g>)~", "", tol);
    const auto& pts = art.paths.at(0).polylines.at(0).points;
    INFO("tolerance " << tol << ", " << pts.size() << " points");
    CHECK(pts.size() >= 8);
    double worst_vertex = 0, worst_chord = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
      const Vec2 a = pts[i], b = pts[(i + 1) % pts.size()];
      worst_vertex = std::max(worst_vertex, std::abs(norm(a - Vec2{100, 100}) - 80));
      // A chord of a circle deviates most at its midpoint: sagitta = r - distance(centre, midpoint).
      worst_chord = std::max(worst_chord, 80 - norm(0.5 * (a + b) - Vec2{100, 100}));
    }
    CHECK(worst_vertex < 1e-9);
    CHECK(worst_chord <= tol);
    CHECK(worst_chord > tol / 8);  // adaptive, not wastefully fine
  }
  // A cubic: every polyline vertex lies on the curve, every chord within tolerance of sampled points.
  const auto cubic = parse(R"~(<path d="M0 0 C 0 100 100 100 100 0" fill="none" stroke="black"/>)~", "", 0.05);
  const auto& pts = cubic.paths.at(0).polylines.at(0).points;
  for (int k = 0; k <= 1000; ++k) {
    const double t = k / 1000.0, u = 1 - t;
    const Vec2 q{3 * u * t * t * 100 + t * t * t * 100, 3 * u * u * t * 100 + 3 * u * t * t * 100};
    double best = 1e300;
    for (size_t i = 0; i + 1 < pts.size(); ++i) {
      const Vec2 ab = pts[i + 1] - pts[i];
      const double s = std::clamp(dot(q - pts[i], ab) / dot(ab, ab), 0.0, 1.0);
      best = std::min(best, norm(q - (pts[i] + s * ab)));
    }
    CHECK(best <= 0.05);
  }
}

TEST_CASE("svg: malformed input is an InputError naming file and element", "[svg]") {
  // Bad path data alone is not an error (SVG 2 draws up to it, test_svg_spec_errors.cpp), but a file
  // left with nothing to draw is, and its message carries the warning that says why.
  const std::string bad_path = error_of(doc(R"~(<path id="broken" d="M 0 0 L 10 10 L 5 x 20"/>)~"));
  INFO(bad_path);
  CHECK(bad_path.find("bad.svg") != std::string::npos);
  CHECK(bad_path.find("no drawable geometry") != std::string::npos);
  CHECK(bad_path.find("path#broken: path data error at character 19 (\"x\")") != std::string::npos);
  const std::string not_xml = error_of("<svg xmlns=\"http://www.w3.org/2000/svg\">\n<path d=\"M0 0\">\n</svg>");
  CHECK(not_xml.find("bad.svg: line 3") != std::string::npos);
  CHECK(error_of("<html/>").find("not <svg>") != std::string::npos);
  CHECK(error_of(doc("<text>only words</text>")).find("no drawable geometry") != std::string::npos);
  CHECK(error_of("").find("bad.svg") != std::string::npos);
}

TEST_CASE("svg: files are read with a size limit, load_art dispatches by extension", "[svg]") {
  const animpak::test::TempDir temp("animpak-svg-");
  const auto& dir = temp.path();
  const auto file = dir / "tri.SVG";
  std::ofstream(file) << doc(R"~(<path d="M0 0 L1 0 L1 1 Z"/>)~");
  CHECK(animpak::load_art(file).paths.size() == 1);
  animpak::SvgOptions tiny;
  tiny.max_file_bytes = 10;
  CHECK_THROWS_WITH(animpak::load_svg(file, tiny), Catch::Contains("over the limit"));
  CHECK_THROWS_WITH(animpak::load_svg(dir / "missing.svg"), Catch::Contains("missing.svg"));
  CHECK_THROWS_WITH(animpak::load_art(dir / "art.png"),
                    Catch::Contains("art.png") && Catch::Contains(".svg") && Catch::Contains(".path"));
}
