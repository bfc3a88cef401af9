// The evenness measures in stats.json and on the `evenness:` line (docs/quality.md, "Evenness"), beside
// the quality fields pack_output.cpp writes.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "animpak/render.hpp"

namespace animpak::cli {

struct EvennessSummary {
  int wall_ratio_times = 0;  ///< times that have a wall ratio
  std::optional<double> wall_ratio_min, wall_ratio_median, wall_ratio_max;
  std::optional<double> empty_disc_median;  ///< the median time's largest empty disc, in element radii
  std::optional<double> empty_disc_worst;   ///< the largest at any time
  double empty_disc_worst_t = 0.0;
  std::vector<double> contact_mean;  ///< mean_contact
};
EvennessSummary summarize_evenness(const std::vector<FrameMetrics>& metrics);

/// One time's evenness fields, to merge into its object in `frames` or `between_slices`.
nlohmann::json evenness_json(const FrameMetrics& m);
/// The summary's fields, to merge into `quality.frames` or `quality.between_slices`.
nlohmann::json evenness_summary_json(const EvennessSummary& e);
/// The median frame's largest empty disc, in element radii, above which a packing is sparse: a pocket
/// an element of the median size would fit in (docs/quality.md, "Evenness").
inline constexpr double sparse_empty_disc = 1.0;

/// "evenness: wall ratio …, largest empty disc …", and for a sparse packing what fills it: "; sparse: try a
/// smaller params.offset, …".
std::string evenness_line(const EvennessSummary& e);

}  // namespace animpak::cli
