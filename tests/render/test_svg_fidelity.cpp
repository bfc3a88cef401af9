// Fidelity of the import against a real renderer: rsvg-convert (librsvg) draws an SVG, draw_art_preview
// (what `animpak check --png` writes) draws the same file as imported, at the same size, and the alpha masks
// (alpha ≥ 0.5) must agree: intersection over union ≥ 0.97, edge pixels within rasterising noise forgiven. Files whose import warns (a feature animpak
// reduces or skips) are skipped with that feature named: the warnings, not a hand list, decide.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "animpak/error.hpp"
#include "animpak/io.hpp"
#include "animpak/render.hpp"
#include "golden.hpp"
#include "openclipart.hpp"
#include "skip.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;

namespace {

// Small enough that the test stays cheap under the sanitizers, large enough that a wrong stroke width,
// viewport or fill rule moves many pixels.
constexpr int kSize = 128;
constexpr double kMinIou = 0.97;
// Every 43rd file of the sorted collection: all categories, without reading all 8000 files.
constexpr std::size_t kStride = 43;
// Files of that sample and the hand-written ones that must be compared: those whose import warns of
// nothing, less a few, so that a change that takes more than a few out (a new warning, a refusal, a
// picture left mostly empty) fails, naming what was left out and why.
constexpr int kMinCompared = 42;

bool have_rsvg() { return std::system("rsvg-convert --version >/dev/null 2>&1") == 0; }

// The feature behind an import warning, as the importer words it (src/io/svg.cpp, svg_context.hpp).
std::string reduced_feature(const std::string& warning) {
  static const std::vector<std::pair<std::string, std::string>> features = {
      {"<text>", "text"},
      {"<image>", "image"},
      {"<foreignObject>", "foreign object"},
      {"<marker>", "marker"},
      {"<pattern>", "pattern"},
      {"gradients reduced", "gradient"},
      {"is not a gradient with stops", "pattern or other paint server"},
      {"filter is not supported", "filter"},
      {"<filter>", "filter"},
      {"mask is not supported", "mask"},
      {"<mask>", "mask"},
      {"clip-path is not supported", "clip path"},
      {"<clipPath>", "clip path"},
      {"non-uniform scale", "stretched stroke"},
      {"stroke-linejoin", "square stroke joins"},
      {"stroke-linecap", "square stroke caps"},
      {"stroke-dasharray", "dashed stroke"},
      {"<use> of", "reference to another file"},
  };
  for (const auto& [needle, feature] : features)
    if (warning.find(needle) != std::string::npos) return feature;
  return warning;
}

struct Outcome {
  bool compared = false;
  std::string skipped;  // why not, when not compared
  double iou = 0.0;
  fs::path kept;  // where both pictures were copied when they disagree
};

Outcome compare_with_rsvg(const fs::path& svg, const fs::path& dir) {
  Outcome outcome;
  animpak::ArtShape art;
  try {
    art = animpak::load_svg(svg);
  } catch (const animpak::InputError& e) {
    outcome.skipped = std::string("refused: ") + e.what();
    return outcome;
  }
  if (!art.warnings.empty()) {
    std::set<std::string> features;
    for (const std::string& w : art.warnings) features.insert(reduced_feature(w));
    for (const std::string& f : features) outcome.skipped += (outcome.skipped.empty() ? "" : ", ") + f;
    return outcome;
  }
  if (!art.viewport) {
    outcome.skipped = "no width, height or viewBox (a browser sizes it to the window)";
    return outcome;
  }
  const animpak::Picture ours = animpak::draw_art_preview(art, kSize);
  const fs::path ours_file = dir / "ours.png", theirs_file = dir / "theirs.png";
  ours.write(ours_file);
  // Only the document's longer side, as the preview is sized: rsvg-convert keeps the aspect with one scale
  // and rounds the other side up. Given both it stretches the document to fill them, so a nearly square
  // one whose shorter side rounds up to a square picture would be stretched by up to a pixel. A square
  // document gets both, as its other side may round up by one.
  const double view_width = art.viewport->width(), view_height = art.viewport->height();
  const std::string width = " -w " + std::to_string(ours.width()), height = " -h " + std::to_string(ours.height());
  const std::string side = std::abs(view_width - view_height) <= 1e-9 * std::max(view_width, view_height)
                               ? width + height
                           : view_width > view_height ? width
                                                      : height;
  const std::string command =
      "rsvg-convert" + side + " -o '" + theirs_file.string() + "' '" + svg.string() + "' 2>/dev/null";
  fs::remove(theirs_file);
  if (std::system(command.c_str()) != 0) {
    outcome.skipped = "rsvg-convert refused it";
    return outcome;
  }
  const Image a = read_rgba(ours_file), b = read_rgba(theirs_file);
  std::size_t opaque = 0;
  for (std::size_t i = 3; i < b.rgba.size(); i += 4) opaque += b.rgba[i] >= 128;
  if (opaque * 100 < b.rgba.size() / 4) {
    // Hairline art: almost nothing is opaque at this size, and the ratio of a few pixels says nothing.
    outcome.skipped = "hairlines only: under 1 % of rsvg-convert's picture is opaque at this size";
    return outcome;
  }
  outcome.compared = true;
  CHECK(a.width == b.width);
  CHECK(a.height == b.height);
  if (a.rgba.size() != b.rgba.size()) return outcome;
  outcome.iou = alpha_iou(a, b);
  if (outcome.iou < kMinIou) {
    // Both pictures beside the test binary, to hold side by side.
    outcome.kept = fs::current_path() / "svg-fidelity";
    fs::create_directories(outcome.kept);
    fs::copy_file(ours_file, outcome.kept / (svg.stem().string() + "-animpak.png"),
                  fs::copy_options::overwrite_existing);
    fs::copy_file(theirs_file, outcome.kept / (svg.stem().string() + "-rsvg.png"),
                  fs::copy_options::overwrite_existing);
  }
  return outcome;
}

// Twelve circles a little over one pixel wide at kSize: many edge pixels near half coverage.
std::string thin_rings() {
  std::ostringstream svg;
  svg << R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 1280 1280">)"
      << R"(<g fill="none" stroke="black" stroke-width="13" stroke-linejoin="round">)";
  for (int i = 0; i < 12; ++i)
    svg << "<circle cx=\"" << 640 + (i % 3) * 7.3 << "\" cy=\"" << 640 + (i % 5) * 3.1 << "\" r=\"" << 60 + i * 47.7
        << "\"/>";
  svg << "</g></svg>";
  return svg.str();
}

// Hand-written files for what the sample may not hold: viewBox alignment against another aspect, absolute
// units, nested transforms, the even-odd rule, thick strokes on open and closed subpaths, arcs, use, a nearly
// square document (its picture square once rounded), thin curved lines.
const std::vector<std::pair<std::string, std::string>>& hand_written() {
  static const std::vector<std::pair<std::string, std::string>> files = {
      {"aligned-viewbox.svg",
       R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="100" viewBox="0 0 50 50"
             preserveAspectRatio="xMinYMid meet">
           <rect x="5" y="5" width="30" height="20" fill="#c33"/><circle cx="35" cy="35" r="12" fill="#33c"/></svg>)svg"},
      {"millimetres.svg",
       R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="60mm" height="30mm" viewBox="0 0 120 60">
           <ellipse cx="40" cy="30" rx="35" ry="20" fill="green"/>
           <path d="M70 10 A 25 15 30 1 1 110 50 Z" fill="navy"/></svg>)svg"},
      {"transforms-evenodd.svg",
       R"svg(<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" width="100" height="100">
           <g transform="translate(50 50) rotate(20)"><g transform="scale(1.5) skewX(10)">
             <path fill-rule="evenodd" d="M0 -30 L18 24 L-28 -10 L28 -10 L-18 24 Z"/></g></g>
           <defs><path id="dot" d="M0 0 h10 v10 h-10 z"/></defs>
           <use xlink:href="#dot" x="80" y="5"/></svg>)svg"},
      {"thick-strokes.svg",
       R"svg(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 80">
           <polyline points="10,70 30,20 50,60 70,15" fill="none" stroke="black" stroke-width="8"
                     stroke-linejoin="round" stroke-linecap="round"/>
           <rect x="60" y="40" width="30" height="30" fill="orange" stroke="purple" stroke-width="6"
                 stroke-linejoin="round"/></svg>)svg"},
      {"nearly-square.svg",
       R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="254.6" height="256">
           <path fill-rule="evenodd" d="M0 0 h254.6 v256 h-254.6 z M6 6 v244 h242.6 v-244 z"/>
           <path fill="#080" d="M16 16 h6 v224 h-6 z m30 0 h6 v224 h-6 z m30 0 h6 v224 h-6 z m30 0 h6 v224 h-6 z
                                m30 0 h6 v224 h-6 z m30 0 h6 v224 h-6 z m30 0 h6 v224 h-6 z m30 0 h6 v224 h-6 z"/></svg>)svg"},
      {"thin-rings.svg", thin_rings()},
  };
  return files;
}

}  // namespace

TEST_CASE("svg fidelity: the preview's alpha matches rsvg-convert's on openclipart and hand-written files",
          "[svg][fidelity]") {
  if (!have_rsvg())
    return animpak::test::skip("rsvg-convert is not on PATH (Debian package librsvg2-bin); nothing was compared");
  const fs::path root = animpak::test::openclipart_root();
  if (!fs::is_directory(root))
    return animpak::test::skip(root.string() + " is absent (Debian package openclipart-svg); nothing was compared");
  const animpak::test::TempDir temp("animpak-fidelity-");
  const fs::path& dir = temp.path();
  std::vector<fs::path> files;
  for (const auto& [name, text] : hand_written()) {
    std::ofstream(dir / name) << text;
    files.push_back(dir / name);
  }
  std::vector<fs::path> all;
  for (const auto& entry : fs::recursive_directory_iterator(root))
    if (entry.is_regular_file() && entry.path().extension() == ".svg") all.push_back(entry.path());
  std::sort(all.begin(), all.end());
  for (std::size_t i = 0; i < all.size(); i += kStride) files.push_back(all[i]);

  int compared = 0;
  std::ostringstream report, left_out;
  std::map<std::string, int> skips;
  for (const fs::path& file : files) {
    const Outcome o = compare_with_rsvg(file, dir);
    INFO(file.string());
    if (!o.compared) {
      report << "  skipped " << file.filename().string() << ": " << o.skipped << "\n";
      left_out << "  " << file.string() << ": " << o.skipped << "\n";
      ++skips[o.skipped.substr(0, o.skipped.find(':'))];
      continue;
    }
    ++compared;
    report << "  IoU " << o.iou << " " << file.filename().string() << "\n";
    if (!o.kept.empty()) UNSCOPED_INFO("both pictures kept in " << o.kept.string());
    CHECK(o.iou >= kMinIou);
  }
  report << compared << " of " << files.size() << " files compared";
  for (const auto& [why, count] : skips) report << "; " << count << " skipped for " << why;
  WARN(report.str());
  INFO("fewer than " << kMinCompared << " files compared; left out:\n" << left_out.str());
  CHECK(compared >= kMinCompared);
}
