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
      {"CSS selector", "style rule not applied"},
      {"rules are not applied", "style rule not applied"},
      {"transform-box", "transform-box"},
      {"invalid CSS transform", "invalid transform"},
      {"invalid transform", "invalid transform"},
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

// `reference`, when not empty, is what rsvg-convert draws instead of `svg`: the same picture written in the
// SVG 1.1 that rsvg-convert 2.54 draws as browsers do, for features it lacks (docs/scene-format.md, "SVG
// structure").
Outcome compare_with_rsvg(const fs::path& svg, const fs::path& dir, const fs::path& reference = {}) {
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
  const std::string command = "rsvg-convert" + side + " -o '" + theirs_file.string() + "' '" +
                              (reference.empty() ? svg : reference).string() + "' 2>/dev/null";
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

// Nested viewports under each preserveAspectRatio: a 3 × 3 grid of the nine alignments (x across, y down),
// meet or slice, in viewports wider or taller than their square viewBox, so that the alignment moves the
// art along the axis with room. Each draws its viewBox, a circle on its corner and a square across its
// top-left corner, which the viewport clips.
std::string alignment_grid(bool slice, bool wide) {
  std::ostringstream svg;
  svg << R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 300 300">)";
  const char* const xs[] = {"xMin", "xMid", "xMax"};
  const char* const ys[] = {"YMin", "YMid", "YMax"};
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) {
      const int w = wide ? 90 : 50, h = wide ? 50 : 90;
      svg << "<svg x=\"" << col * 100 + (wide ? 5 : 25) << "\" y=\"" << row * 100 + (wide ? 25 : 5) << "\" width=\""
          << w << "\" height=\"" << h << "\" viewBox=\"0 0 10 10\" preserveAspectRatio=\"" << xs[col] << ys[row]
          << (slice ? " slice" : " meet") << "\">"
          << R"(<rect width="10" height="10" fill="#c33"/><circle cx="10" cy="10" r="4" fill="#33c"/>)"
          << R"(<path d="M-3 -3 h4 v4 h-4 z" fill="#3c3"/></svg>)";
    }
  svg << "</svg>";
  return svg.str();
}

struct HandWritten {
  std::string name, text;
  std::string reference;  // what rsvg-convert draws instead, when it lacks a feature; empty: the file itself
};

// Hand-written files for what the sample may not hold: viewBox alignment against another aspect, absolute
// units, nested transforms, the even-odd rule, thick strokes on open and closed subpaths, arcs, use, a nearly
// square document (its picture square once rounded), thin curved lines; and the SVG structure exporters
// write (docs/scene-format.md, "SVG structure"): nested viewports with every alignment and their clip,
// symbols and use, the transform property from CSS, transform-origin, auto radii.
const std::vector<HandWritten>& hand_written() {
  static const std::vector<HandWritten> files = {
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
      {"nested-meet-wide.svg", alignment_grid(false, true)},
      {"nested-meet-tall.svg", alignment_grid(false, false)},
      {"nested-slice-wide.svg", alignment_grid(true, true)},
      {"nested-slice-tall.svg", alignment_grid(true, false)},
      // Stretched (none), visible overflow, a viewport in a viewport, one under a rotation (its clip a
      // rotated square), and a stroke the edge cuts.
      {"nested-clip.svg",
       R"svg(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 200">
           <svg x="10" y="10" width="80" height="40" viewBox="0 0 10 10" preserveAspectRatio="none">
             <circle cx="5" cy="5" r="7" fill="#c33"/></svg>
           <svg x="110" y="10" width="40" height="40" overflow="visible">
             <rect x="-10" y="10" width="80" height="20" fill="#33c"/></svg>
           <svg x="10" y="70" width="80" height="80" viewBox="0 0 100 100">
             <svg x="20" y="20" width="100" height="100"><circle cx="40" cy="40" r="60" fill="#3c3"/></svg></svg>
           <g transform="rotate(30 150 110)"><svg x="120" y="80" width="60" height="60">
             <rect x="-40" y="20" width="140" height="20" fill="#c3c"/></svg></g>
           <svg x="100" y="160" width="90" height="30" style="overflow: hidden">
             <polyline points="-10,25 20,5 50,25 80,5 110,25" fill="none" stroke="#333" stroke-width="8"
                       stroke-linejoin="round" stroke-linecap="round"/>
             <rect x="60" y="-10" width="40" height="20" fill="#fc3" stroke="#036" stroke-width="6"
                   stroke-linejoin="round"/></svg></svg>)svg"},
      // <use> of a symbol (viewBox, alignment, the use's size), of an <svg>, of plain elements at x/y, and
      // of a use.
      {"symbol-use.svg",
       R"svg(<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 200 200">
           <defs>
             <symbol id="arrow" viewBox="0 0 20 10" preserveAspectRatio="xMaxYMax meet">
               <path d="M0 3 h12 v-3 l8 5 l-8 5 v-3 h-12 z"/></symbol>
             <svg id="tile" width="30" height="30" viewBox="0 0 10 10"><circle cx="5" cy="5" r="5"/></svg>
             <rect id="bar" width="40" height="8" rx="2"/>
             <g id="pair"><circle cx="5" cy="5" r="5"/><circle cx="20" cy="5" r="5"/></g>
           </defs>
           <use xlink:href="#arrow" x="10" y="10" width="80" height="60"/>
           <use href="#arrow" x="110" y="10" width="80" height="20"/>
           <use href="#tile" x="10" y="90"/><use href="#tile" x="60" y="110"/>
           <use href="#bar" x="130" y="100"/><use href="#bar" x="130" y="120" transform="rotate(10 150 124)"/>
           <use href="#pair" x="10" y="170"/><use id="again" href="#pair" x="60" y="170"/>
           <use href="#again" x="60" y="0"/></svg>)svg"},
      // SVG 2 symbol sizes, the clip of a symbol's viewport, and a use's size overriding an <svg>'s, which
      // rsvg-convert 2.54 lacks: drawn against each instance written out as a nested <svg>.
      {"symbol-size.svg",
       R"svg(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
           <defs><symbol id="s" width="40" height="30" viewBox="0 0 10 10">
             <rect x="-5" y="2" width="20" height="6" fill="#c33"/><circle cx="5" cy="5" r="3"/></symbol>
             <svg id="v" width="20" height="20" viewBox="0 0 10 10"><circle cx="5" cy="5" r="6"/></svg></defs>
           <use href="#s" x="5" y="5"/><use href="#s" x="50" y="5" width="45" height="45"/>
           <use href="#s" x="5" y="60" height="30"/><use href="#v" x="60" y="60" width="35"/></svg>)svg",
       R"svg(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
           <svg x="5" y="5" width="40" height="30" viewBox="0 0 10 10">
             <rect x="-5" y="2" width="20" height="6" fill="#c33"/><circle cx="5" cy="5" r="3"/></svg>
           <svg x="50" y="5" width="45" height="45" viewBox="0 0 10 10">
             <rect x="-5" y="2" width="20" height="6" fill="#c33"/><circle cx="5" cy="5" r="3"/></svg>
           <svg x="5" y="60" width="40" height="30" viewBox="0 0 10 10">
             <rect x="-5" y="2" width="20" height="6" fill="#c33"/><circle cx="5" cy="5" r="3"/></svg>
           <svg x="60" y="60" width="35" height="20" viewBox="0 0 10 10"><circle cx="5" cy="5" r="6"/></svg></svg>)svg"},
      // The transform property in style attributes and in type, class and id rules, with CSS units.
      {"css-transform.svg",
       R"svg(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
           <style>.turn { transform: rotate(45deg); } #far { transform: translate(70px, 70px) scale(1.5); }
             ellipse { transform: translateX(60px) skewX(-20deg); }</style>
           <rect width="20" height="10" style="transform: translate(10px, 10px) rotate(10deg)"/>
           <g transform="translate(40 0)"><rect class="turn" x="10" width="30" height="10"/></g>
           <rect id="far" width="10" height="10" fill="#c33"/>
           <ellipse cx="10" cy="50" rx="12" ry="8" fill="#33c"/>
           <circle cx="20" cy="85" r="8" style="transform: matrix(1, 0, 0, 1, 10, 0) scaleY(0.8)"/></svg>)svg"},
      // Where a rule or the style sets transform and so does the attribute, the property wins (CSS
      // Transforms 1; rsvg-convert 2.54 lets the attribute win): drawn against the property alone.
      {"css-transform-wins.svg",
       R"svg(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
           <style>.moved { transform: translate(60px, 10px); }</style>
           <rect class="moved" width="30" height="30" transform="translate(0 60)"/>
           <circle cx="20" cy="20" r="15" style="transform: translate(5px, 60px)" transform="scale(3)"/>
           <rect x="60" y="60" width="30" height="30" fill="#c33" style="transform: none"
                 transform="translate(-50 -50)"/></svg>)svg",
       R"svg(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
           <rect width="30" height="30" transform="translate(60 10)"/>
           <circle cx="20" cy="20" r="15" transform="translate(5 60)"/>
           <rect x="60" y="60" width="30" height="30" fill="#c33"/></svg>)svg"},
      // transform-origin as attribute and property, lengths, percentages of the viewBox and keywords;
      // rsvg-convert 2.54 ignores it, so it draws the same transforms written about the origin.
      {"transform-origin.svg",
       R"svg(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 100">
           <rect x="20" y="20" width="40" height="20" transform="rotate(30)" transform-origin="40 30"/>
           <rect x="80" y="10" width="30" height="30" fill="#c33" transform="scale(0.5)" transform-origin="center"/>
           <rect x="150" y="10" width="40" height="40" fill="#33c"
                 style="transform: scale(1.5, 0.5); transform-origin: right top"/>
           <rect x="20" y="60" width="40" height="30" fill="#3c3" transform="rotate(-20)"
                 transform-origin="25% 75%"/>
           <rect x="120" y="60" width="30" height="30" style="transform: rotate(45deg); transform-origin: 135px"/>
           <circle cx="180" cy="80" r="10" transform="scale(1.5)" transform-origin="180 bottom"/></svg>)svg",
       R"svg(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 100">
           <rect x="20" y="20" width="40" height="20" transform="rotate(30 40 30)"/>
           <rect x="80" y="10" width="30" height="30" fill="#c33" transform="translate(100 50) scale(0.5) translate(-100 -50)"/>
           <rect x="150" y="10" width="40" height="40" fill="#33c" transform="translate(200 0) scale(1.5 0.5) translate(-200 0)"/>
           <rect x="20" y="60" width="40" height="30" fill="#3c3" transform="rotate(-20 50 75)"/>
           <rect x="120" y="60" width="30" height="30" transform="rotate(45 135 50)"/>
           <circle cx="180" cy="80" r="10" transform="translate(180 100) scale(1.5) translate(-180 -100)"/></svg>)svg"},
      // SVG 2 auto radii: a rect's rx takes ry (both auto: square corners), an ellipse's rx or ry the other.
      {"auto-radii.svg",
       R"svg(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
           <rect x="5" y="5" width="40" height="40" rx="auto" ry="15" fill="#c33"/>
           <rect x="55" y="5" width="40" height="40" rx="auto" ry="auto"/>
           <rect x="5" y="55" width="40" height="20" ry="auto" rx="8" fill="#33c"/>
           <ellipse cx="75" cy="70" rx="auto" ry="15" fill="#3c3"/>
           <ellipse cx="25" cy="88" rx="18" ry="auto"/></svg>)svg"},
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
  std::map<fs::path, fs::path> references;
  for (const HandWritten& h : hand_written()) {
    std::ofstream(dir / h.name) << h.text;
    files.push_back(dir / h.name);
    if (!h.reference.empty()) {
      references[dir / h.name] = dir / ("reference-" + h.name);
      std::ofstream(references[dir / h.name]) << h.reference;
    }
  }
  const std::size_t hand_written_count = files.size();
  std::vector<fs::path> all;
  for (const auto& entry : fs::recursive_directory_iterator(root))
    if (entry.is_regular_file() && entry.path().extension() == ".svg") all.push_back(entry.path());
  std::sort(all.begin(), all.end());
  for (std::size_t i = 0; i < all.size(); i += kStride) files.push_back(all[i]);

  int compared = 0;
  std::ostringstream report, left_out;
  std::map<std::string, int> skips;
  for (std::size_t i = 0; i < files.size(); ++i) {
    const fs::path& file = files[i];
    const auto reference = references.find(file);
    const Outcome o = compare_with_rsvg(file, dir, reference == references.end() ? fs::path() : reference->second);
    INFO(file.string());
    // The hand-written files are written to import without a warning: each must be compared.
    if (i < hand_written_count) CHECK(o.skipped == "");
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
