// The page `animpak report DIR` writes (docs/cli.md, "`report`"): one self-contained HTML file with the
// packing's animation, its quality and motion per frame as plots, its elements and its provenance. Built
// from stats.json's figures as they are (docs/quality.md, "stats.json"), so every number the page shows is
// one of that file's, named by its path in a data-stat attribute.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "svg_plot.hpp"  // report_number

namespace animpak::cli {

/// The value of stats.json (or any JSON) at a dotted path ("quality.frames.coverage.mean",
/// "final_growth.3.min": a number indexes an array), null when absent. The report page, the sweep's page and
/// table, and their tests all read stats.json through it.
const nlohmann::json& stats_at(const nlohmann::json& root, const std::string& path);

/// One row of the page's table of elements.
struct ReportElement {
  std::string name;       ///< the element's name in stats.json ("star#3", a guided element's own name)
  std::string library;    ///< its library element's name
  std::string art;        ///< the art file as the scene names it
  std::string kind;       ///< "unguided", "guided" or "secondary"
  std::string thumbnail;  ///< an inline <svg> of its art (our own drawing of the imported art, never the file)
};

struct ReportInput {
  std::string title;          ///< the packed folder's name
  nlohmann::json stats;       ///< DIR/stats.json
  std::string animation_svg;  ///< DIR/animation.svg (animpak's own svg-anim output), inline
  /// Instead of the SVG, when it is too large to open quickly: DIR/animation.gif's bytes, embedded as a
  /// data URI (the slider then moves the plots' cursor and the readout, not the animation).
  std::string animation_gif;
  std::string animation_note;           ///< a line under the animation saying which one the page shows, and why
  std::vector<ReportElement> elements;  ///< in stats.json's element order
};

/// The ids of the page's plots, each an inline <svg> holding one <polyline> per series: coverage,
/// channel CV, wall ratio and kink against the frame time, and the contact function H(r).
inline const std::vector<std::string> kReportPlots = {"plot-coverage", "plot-channel", "plot-wall", "plot-kink",
                                                      "plot-contact"};

/// animation.svg files larger than this are not inlined when animation.gif can stand in (report.cpp): a
/// 61 MB one (32 elements of detailed clip art over 100 slices) took headless Chromium a minute to open.
inline constexpr std::uintmax_t kInlineSvgLimit = 16u << 20;

/// The whole page. InputError when stats.json lacks the per-frame figures (a folder packed with
/// --no-render or by animpak-solve).
std::string report_page(const ReportInput& input);

/// RFC 4648 base64 of `bytes` (the GIF's data URI).
std::string base64(const std::string& bytes);

}  // namespace animpak::cli
