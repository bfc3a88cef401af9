// The `evenness:` line (docs/quality.md, "Evenness"), beside the quality lines pack_output.cpp prints; the
// summary it prints is summarize_evenness's (animpak/quality_summary.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "animpak/quality_summary.hpp"

namespace animpak::cli {

/// The median frame's largest empty disc, in element radii, above which a packing is sparse: a pocket
/// an element of the median size would fit in (docs/quality.md, "Evenness").
inline constexpr double sparse_empty_disc = 1.0;

/// "evenness: wall ratio …, largest empty disc …", and for a sparse packing what fills it: "; sparse: try a
/// smaller params.offset, …".
std::string evenness_line(const EvennessSummary& e);

}  // namespace animpak::cli
