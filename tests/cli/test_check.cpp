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
