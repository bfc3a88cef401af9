// `animpak check`: exit codes, the JSON report (docs/check.md) and the preview picture.
#include <catch2/catch.hpp>

#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

#include "run_animpak.hpp"
#include "temp_dir.hpp"

namespace {

std::filesystem::path scratch_svg(const animpak::test::TempDir& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name) << text;
  return dir / name;
}

}  // namespace

TEST_CASE("animpak check: --help describes the command and its exit codes") {
  const CommandResult r = run_animpak("check --help");
  CHECK(r.code == 0);
  CHECK(r.out.find("--png") != std::string::npos);
  CHECK(r.out.find("--json") != std::string::npos);
  CHECK(r.out.find("2 the file cannot be imported") != std::string::npos);
}

TEST_CASE("animpak check --json: a .path element is ready, with its paths, outline and normalized size") {
  const CommandResult r = run_animpak("check " + shapes_dir() + "/bird.path --json");
  REQUIRE(r.code == 0);
  const nlohmann::json report = nlohmann::json::parse(r.out);
  CHECK(report["ready"] == true);
  CHECK(report["document"]["viewport"].is_null());
  REQUIRE(report["paths"].size() == 2);
  int on_outline = 0;
  for (const auto& p : report["paths"]) {
    CHECK(p["fill"]["color"].get<std::string>().size() == 7);
    on_outline += p["on_outline"].get<bool>() ? 1 : 0;
  }
  CHECK(on_outline == 1);  // the body; the eye lies inside it
  const auto& e = report["element"];
  CHECK(std::max(e["size"][0].get<double>(), e["size"][1].get<double>()) == Approx(1.0));
  CHECK(e["outline_size"][0].get<double>() > e["size"][0].get<double>());
  CHECK(e["slice_vertices"].get<int>() > e["boundary_vertices"].get<int>());
}

TEST_CASE("animpak check: skipped and reduced features are warnings, and the art is still ready") {
  const animpak::test::TempDir scratch("animpak-check-");
  const auto svg =
      scratch_svg(scratch, "reduced.svg", R"svg(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 50">
    <text x="5" y="20">hello</text>
    <path id="open" d="M10 10 L90 10 L50 45" fill="red"/>
    <path id="bow" d="M10 40 L40 10 L40 40 L10 10 Z" fill="blue" stroke="black" stroke-width="2"/></svg>)svg");
  const CommandResult r = run_animpak("check " + svg.string() + " --json");
  REQUIRE(r.code == 0);
  const nlohmann::json report = nlohmann::json::parse(r.out);
  std::string warnings;
  for (const auto& w : report["warnings"]) warnings += w.get<std::string>() + "\n";
  INFO(warnings);
  CHECK(warnings.find("<text>") != std::string::npos);
  CHECK(warnings.find("open: 1 open subpath(s) filled as if closed") != std::string::npos);
  CHECK(warnings.find("bow: 1 subpath(s) cross themselves") != std::string::npos);
  CHECK(warnings.find("bow: stroke-linejoin miter is drawn round") != std::string::npos);
  CHECK(report["paths"][0]["open_subpaths"] == 1);
  CHECK(report["paths"][1]["self_intersecting_subpaths"] == 1);
  CHECK(r.err.find("animpak: warning: ") != std::string::npos);
  const std::vector<double> viewport = report["document"]["viewport"];
  CHECK(viewport == std::vector<double>{0, 0, 100, 50});
}

TEST_CASE("animpak check: a warning many paths share is one line with their count and the first names") {
  const animpak::test::TempDir scratch("animpak-check-");
  std::string body;
  for (int i = 0; i < 5; ++i)
    body += "<path id=\"p" + std::to_string(i) + "\" d=\"M" + std::to_string(10 + 15 * i) +
            " 10 l10 0 l-5 30\" stroke=\"#000\"/>";
  const auto svg = scratch_svg(
      scratch, "many.svg", R"svg(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 50">)svg" + body + "</svg>");
  const CommandResult r = run_animpak("check " + svg.string() + " --json");
  REQUIRE(r.code == 0);
  const nlohmann::json report = nlohmann::json::parse(r.out);
  std::vector<std::string> warnings;
  for (const auto& w : report["warnings"]) warnings.push_back(w.get<std::string>());
  INFO(r.err);
  const auto has = [&](const std::string& line) {
    return std::find(warnings.begin(), warnings.end(), svg.string() + ": " + line) != warnings.end();
  };
  CHECK(has("5 elements (path#p0, path#p1, path#p2 and 2 more): stroke-linejoin miter is drawn round"));
  CHECK(has("5 elements (path#p0, path#p1, path#p2 and 2 more): stroke-linecap butt is drawn round"));
  CHECK(
      has("5 paths (p0, p1, p2 and 2 more): 5 open subpath(s) filled as if closed (as SVG fills them); the "
          "element's outline takes them in closed"));
  CHECK(r.err.find("p3") == std::string::npos);
}

TEST_CASE("animpak check: a file that cannot be imported exits 2 with the error, also as JSON") {
  const CommandResult missing = run_animpak("check /nonexistent/bird.svg --json");
  CHECK(missing.code == 2);
  CHECK(missing.err.find("animpak: error: /nonexistent/bird.svg") != std::string::npos);
  const nlohmann::json report = nlohmann::json::parse(missing.out);
  CHECK(report["ready"] == false);
  CHECK(report["error"].get<std::string>().find("/nonexistent/bird.svg") != std::string::npos);
  const animpak::test::TempDir scratch("animpak-check-");
  const auto empty =
      scratch_svg(scratch, "empty.svg", R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10"/>)svg");
  const CommandResult text = run_animpak("check " + empty.string());
  CHECK(text.code == 2);
  CHECK(text.err.find("no drawable geometry") != std::string::npos);
}

TEST_CASE("animpak check --png: the art at the document's viewport, longer side --size, transparent outside") {
  const animpak::test::TempDir scratch("animpak-check-");
  const auto svg =
      scratch_svg(scratch, "viewport.svg", R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="100"
      viewBox="0 0 20 10"><rect x="10" y="0" width="10" height="10" fill="black"/></svg>)svg");
  const auto png = scratch / "viewport.png";
  const CommandResult r = run_animpak("check " + svg.string() + " --png " + png.string() + " --size 64");
  REQUIRE(r.code == 0);
  auto in = OIIO::ImageInput::open(png.string());
  REQUIRE(in);
  const OIIO::ImageSpec spec = in->spec();
  CHECK(spec.width == 64);
  CHECK(spec.height == 32);
  REQUIRE(spec.nchannels == 4);
  std::vector<unsigned char> pixels(static_cast<std::size_t>(spec.width) * spec.height * 4);
  REQUIRE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, pixels.data()));
  const auto alpha = [&](int x, int y) { return pixels[(static_cast<std::size_t>(y) * spec.width + x) * 4 + 3]; };
  CHECK(alpha(16, 16) == 0);    // left half: nothing drawn
  CHECK(alpha(48, 16) == 255);  // right half: the square
}

TEST_CASE("animpak check --container: the heart's outline, no holes, its area and bounds instead of an element") {
  const std::string heart = shapes_dir() + "/heart-container.path";
  const CommandResult r = run_animpak("check " + heart + " --container --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const nlohmann::json report = nlohmann::json::parse(r.out);
  CHECK(report["ready"] == true);
  CHECK_FALSE(report.contains("element"));
  REQUIRE(report["paths"].size() == 1);
  CHECK(report["paths"][0]["role"] == "outline");
  CHECK_FALSE(report["paths"][0].contains("on_outline"));
  const auto& c = report["container"];
  CHECK(c["outline"]["path"] == 0);
  CHECK(c["outline"]["points"] == 56);
  CHECK(c["holes"].empty());
  // The heart's tip is at y = 474 of its 500-unit artboard (shared/data/README.md); it is wider than tall.
  const std::vector<double> bounds = c["bounds"];
  CHECK(bounds[1] + bounds[3] == Approx(474.0).margin(1.0));
  CHECK(bounds[2] > bounds[3]);
  // A heart covers well over half its box but not all of it; without holes the area is the outline's.
  const double area = c["area"];
  CHECK(area > 0.5 * bounds[2] * bounds[3]);
  CHECK(area < 0.9 * bounds[2] * bounds[3]);
  CHECK(area == Approx(c["outline"]["area"].get<double>()));
  const double scale = c["scale"];
  CHECK(scale == Approx(1.0 / bounds[2]));
  CHECK(c["unit_area"].get<double>() == Approx(area * scale * scale));

  const CommandResult text = run_animpak("check " + heart + " --container");
  CHECK(text.code == 0);
  CHECK(text.out.find("outline    path 0 (path0): 56 points") != std::string::npos);
  CHECK(text.out.find("holes      0") != std::string::npos);
  CHECK(text.out.find("slice vertices") == std::string::npos);
  CHECK(text.out.find("ready to pack into (as a container)") != std::string::npos);
}

TEST_CASE("animpak check SCENE.json: the scene's container with its outline and holes, as pack reads them") {
  const CommandResult r =
      run_animpak("check " + std::string(ANIMPAK_SOURCE_DIR) + "/examples/annulus/scene.json --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const nlohmann::json report = nlohmann::json::parse(r.out);
  CHECK(report["scene"].get<std::string>().find("annulus/scene.json") != std::string::npos);
  CHECK(report["file"].get<std::string>().find("ring.svg") != std::string::npos);
  CHECK(report["paths"][0]["role"] == "outline");
  CHECK(report["paths"][1]["role"] == "hole");
  // ring.svg: circles of radius 240 and 95 about (250, 250), flattened into polygons just inside them.
  const auto& c = report["container"];
  const double pi = 3.14159265358979;
  REQUIRE(c["holes"].size() == 1);
  CHECK(c["holes"][0]["id"] == "inner");
  CHECK(c["outline"]["area"].get<double>() == Approx(pi * 240 * 240).epsilon(0.002));
  CHECK(c["holes"][0]["area"].get<double>() == Approx(pi * 95 * 95).epsilon(0.002));
  CHECK(c["area"].get<double>() == Approx(c["outline"]["area"].get<double>() - c["holes"][0]["area"].get<double>()));
  const std::vector<double> bounds = c["bounds"];
  CHECK(bounds == std::vector<double>{10, 10, 480, 480});

  // The same SVG on its own has no hole (SVG paths are holes only when named): the inner circle is
  // packed over, and the check says how to make it a hole.
  const std::string ring = std::string(ANIMPAK_SOURCE_DIR) + "/examples/annulus/ring.svg";
  const CommandResult plain = run_animpak("check " + ring + " --container --json");
  REQUIRE(plain.code == 0);
  const nlohmann::json unholed = nlohmann::json::parse(plain.out);
  CHECK(unholed["container"]["holes"].empty());
  CHECK(unholed["paths"][1]["role"] == "");
  CHECK_THAT(plain.err, Catch::Matchers::Contains("path 1 (inner) lies inside the container's outline but is not a "
                                                  "hole") &&
                            Catch::Matchers::Contains("--holes 1"));
  const CommandResult holed = run_animpak("check " + ring + " --container --holes 1 --outline 0 --json");
  REQUIRE(holed.code == 0);
  CHECK(nlohmann::json::parse(holed.out)["container"]["area"] == Approx(c["area"].get<double>()));
  CHECK(holed.err.find("is not a hole") == std::string::npos);
}

TEST_CASE("animpak check SCENE.json: a guided path that ends where it starts in a scene that does not loop warns") {
  const animpak::test::TempDir scratch("animpak-check-scene-");
  const std::string examples = std::string(ANIMPAK_SOURCE_DIR) + "/examples/";
  const auto scene = [&](const std::string& loop) {
    std::ofstream(scratch / "scene.json")
        << R"({"container": ")" << examples << R"(shapes/heart-container.path", "elements": [{"name": "star", "art": ")"
        << examples << R"(default/star.svg", "count": 0}], "guided": [{"name": "dove", "element": "star", "targets": [
             {"x": 200, "y": 250, "t": 0}, {"x": 300, "y": 250, "t": 0.5}, {"x": 200, "y": 250, "t": 1}]}])"
        << loop << "}";
    return run_animpak("check " + (scratch / "scene.json").string() + " --json");
  };
  const CommandResult open = scene(R"(, "loop": false)");
  INFO(open.err);
  REQUIRE(open.code == 0);
  CHECK_THAT(open.err, Catch::Matchers::Contains("animpak: warning: " + (scratch / "scene.json").string() +
                                                 ": guided element \"dove\" ends where it starts (x 200, y 250) but "
                                                 "the scene does not loop; add \"loop\": true"));
  const nlohmann::json report = nlohmann::json::parse(open.out);
  CHECK(report["ready"] == true);
  CHECK_THAT(report["warnings"][0].get<std::string>(), Catch::Matchers::Contains("guided element \"dove\""));
  const CommandResult looping = scene("");
  REQUIRE(looping.code == 0);
  CHECK(looping.err.find("ends where it starts") == std::string::npos);
}

TEST_CASE("animpak check --container: a .path hole (type 7) is counted and measured, and bad hole indices exit 2") {
  const animpak::test::TempDir scratch("animpak-check-");
  // A 400 x 200 frame with a 100 x 100 hole.
  const auto frame = scratch_svg(scratch, "frame.path",
                                 "1\nforeground_color_rgb 0 -1,-1,-1 -1,-1,-1\n"
                                 "background_color_rgb 0 200,200,200 255,255,255\n"
                                 "0 1 0 0 0 400 0 400 200 0 200\n"
                                 "0 1 7 100 50 200 50 200 150 100 150\n");
  const CommandResult r = run_animpak("check " + frame.string() + " --container --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const nlohmann::json report = nlohmann::json::parse(r.out);
  const auto& c = report["container"];
  CHECK(c["outline"]["area"] == Approx(80000));
  REQUIRE(c["holes"].size() == 1);
  CHECK(c["holes"][0]["path"] == 1);
  CHECK(c["holes"][0]["area"] == Approx(10000));
  CHECK(c["area"] == Approx(70000));
  CHECK(c["unit_area"] == Approx(70000.0 / (400 * 400)));
  const std::vector<double> bounds = c["bounds"];
  CHECK(bounds == std::vector<double>{0, 0, 400, 200});
  const CommandResult text = run_animpak("check " + frame.string() + " --container");
  CHECK(text.out.find("holes      1:\n  path 1 (path1): 4 points, area 10000") != std::string::npos);
  CHECK(text.out.find("area       70000 art units") != std::string::npos);

  // Checked as an element, the hole path points at --container.
  const CommandResult element = run_animpak("check " + frame.string());
  CHECK(element.code == 0);
  CHECK(element.err.find("has hole paths (.path type 7)") != std::string::npos);
  CHECK(element.err.find("animpak check --container " + frame.string()) != std::string::npos);

  const CommandResult missing = run_animpak("check " + frame.string() + " --container --holes 5 --json");
  CHECK(missing.code == 2);
  CHECK(nlohmann::json::parse(missing.out)["error"].get<std::string>().find(
            "path 5: container.holes names a path the file does not have") != std::string::npos);
  CHECK(run_animpak("check " + frame.string() + " --holes 1").code == 1);  // --holes needs --container
}

namespace {

// A square body and, apart from it, a drop-shadow ellipse with an id and a class: two outline pieces.
constexpr const char* kShadowedSvg = R"svg(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 300 100">
  <g id="bee"><rect id="body" x="0" y="0" width="100" height="100" fill="#fc0"/></g>
  <ellipse id="shadow" class="shade" cx="250" cy="90" rx="40" ry="10" fill="#000" fill-opacity="0.5"/></svg>)svg";

// The alpha of the --png picture at pixel (x, y).
int png_alpha(const std::filesystem::path& png, int x, int y) {
  auto in = OIIO::ImageInput::open(png.string());
  REQUIRE(in);
  const OIIO::ImageSpec spec = in->spec();
  REQUIRE(spec.nchannels == 4);
  std::vector<unsigned char> pixels(static_cast<std::size_t>(spec.width) * spec.height * 4);
  REQUIRE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, pixels.data()));
  return pixels[(static_cast<std::size_t>(y) * spec.width + x) * 4 + 3];
}

}  // namespace

TEST_CASE("animpak check: every piece of the outline it bridges is named, with its share and the exclude entry") {
  const animpak::test::TempDir scratch("animpak-check-");
  const auto svg = scratch_svg(scratch, "bee.svg", kShadowedSvg);
  const CommandResult text = run_animpak("check " + svg.string());
  INFO(text.out << text.err);
  REQUIRE(text.code == 0);
  CHECK(text.out.find("pieces     the art's outline comes in 2 pieces, bridged with a closing of radius") !=
        std::string::npos);
  CHECK(text.out.find("  2   11.1 % of the art's area, bridged: 1 path") != std::string::npos);
  CHECK(text.out.find("path 1: ellipse#shadow.shade") != std::string::npos);
  CHECK(text.out.find("to leave it out, add to the scene's element: \"exclude\": [\"#shadow\"]") != std::string::npos);
  CHECK(text.out.find("(animpak check " + svg.string() + " --exclude '#shadow' --png OUT shows the art without it)") !=
        std::string::npos);
  CHECK(text.err.find("apart from it: path 1 ('shadow') 11.11 %") != std::string::npos);

  const CommandResult json = run_animpak("check " + svg.string() + " --json");
  REQUIRE(json.code == 0);
  const nlohmann::json pieces = nlohmann::json::parse(json.out)["element"]["pieces"];
  REQUIRE(pieces.size() == 2);
  CHECK(pieces[0]["state"] == "largest");
  CHECK(pieces[1]["state"] == "bridged");
  CHECK(pieces[1]["share"].get<double>() == Approx(0.1116).epsilon(0.01));  // π·40·10 of 100² + π·40·10
  CHECK(pieces[1]["paths"][0]["id"] == "shadow");
  CHECK(pieces[1]["paths"][0]["element"] == "ellipse#shadow.shade");
  CHECK(pieces[1]["exclude"] == nlohmann::json::array({"#shadow"}));
}

TEST_CASE(
    "animpak check --exclude: the piece is gone from the outline and the picture, and one that matches nothing is "
    "an error") {
  const animpak::test::TempDir scratch("animpak-check-");
  const auto svg = scratch_svg(scratch, "bee.svg", kShadowedSvg);
  const auto png = scratch / "bee.png";
  // 150 x 50 pixels, half a pixel per art unit: the shadow's middle is at (125, 45), the body's at (25, 25).
  REQUIRE(run_animpak("check " + svg.string() + " --png " + png.string() + " --size 150").code == 0);
  CHECK(png_alpha(png, 125, 45) > 64);
  for (const std::string selector : {"#shadow", ".shade"}) {
    INFO(selector);
    const CommandResult r = run_animpak("check " + svg.string() + " --exclude '" + selector + "' --png " +
                                        png.string() + " --size 150 --json");
    INFO(r.err);
    REQUIRE(r.code == 0);
    const nlohmann::json report = nlohmann::json::parse(r.out);
    REQUIRE(report["paths"].size() == 1);
    CHECK(report["paths"][0]["id"] == "body");
    CHECK(report["element"]["pieces"].empty());
    CHECK(report["element"]["bridge_radius"] == 0.0);
    CHECK(report["exclude"] == nlohmann::json::array({selector}));
    CHECK(r.err.find("bridged") == std::string::npos);
    CHECK(png_alpha(png, 125, 45) == 0);
    CHECK(png_alpha(png, 25, 25) == 255);
  }
  const CommandResult text = run_animpak("check " + svg.string() + " --exclude '#shadow' --exclude '#bee'");
  CHECK(text.code == 2);
  CHECK(text.err.find("no drawable geometry") != std::string::npos);

  const CommandResult unknown = run_animpak("check " + svg.string() + " --exclude '#shadw'");
  CHECK(unknown.code == 2);
  CHECK(unknown.err.find("bee.svg: exclude \"#shadw\": matches no element of the file; did you mean \"#shadow\"?") !=
        std::string::npos);
  const CommandResult container = run_animpak("check " + svg.string() + " --container --exclude '#shadow'");
  CHECK(container.code == 1);
}
