// The render stage's quality measures summed up over a set of times (docs/quality.md): the counts and worst
// cases of a packing's frames and of the points between slices, and the frames' evenness. Header-only over
// render.hpp's plain structs, so that animpak-solve writes stats.json's summaries (of no frames) without
// linking the rendering library.
#pragma once

#include <algorithm>
#include <limits>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "animpak/render.hpp"

namespace animpak {

/// The quality of a set of measured times summed up; counts use quality_share_threshold.
struct QualitySummary {
  int times = 0;
  int element_times = 0;       ///< elements × times
  int outside = 0;             ///< element-times whose art is more than the threshold outside
  ElementShare worst_outside;  ///< largest outside share at any time, counted or not
  double worst_outside_t = 0.0;
  int overlapping = 0;        ///< pair-times whose overlap exceeds the threshold
  int overlapping_pairs = 0;  ///< distinct pairs among them
  PairShare worst_overlap;    ///< largest overlap share at any time, counted or not
  double worst_overlap_t = 0.0;
  double coverage_min = 0.0, coverage_max = 0.0, coverage_mean = 0.0;
  double min_gap = 0.0;
  double channel_cv_mean = 0.0, channel_cv_max = 0.0;
};

inline QualitySummary summarize(const std::vector<FrameMetrics>& metrics) {
  QualitySummary q;
  q.times = int(metrics.size());
  if (metrics.empty()) return q;
  std::set<std::pair<int, int>> pairs;
  q.coverage_min = std::numeric_limits<double>::infinity();
  q.coverage_max = -q.coverage_min;
  q.min_gap = q.coverage_min;
  for (const FrameMetrics& m : metrics) {
    q.element_times += int(m.outside_share.size());
    q.outside += int(m.elements_outside().size());
    const ElementShare out = m.worst_outside();
    if (out.share > q.worst_outside.share) q.worst_outside = out, q.worst_outside_t = m.t;
    for (const PairShare& p : m.overlapping()) pairs.insert({p.a, p.b}), ++q.overlapping;
    const PairShare overlap = m.worst_overlap();
    if (overlap.share > q.worst_overlap.share) q.worst_overlap = overlap, q.worst_overlap_t = m.t;
    q.coverage_min = std::min(q.coverage_min, m.coverage);
    q.coverage_max = std::max(q.coverage_max, m.coverage);
    q.coverage_mean += m.coverage / double(metrics.size());
    q.min_gap = std::min(q.min_gap, m.min_gap);
    q.channel_cv_mean += m.channel_cv / double(metrics.size());
    q.channel_cv_max = std::max(q.channel_cv_max, m.channel_cv);
  }
  q.overlapping_pairs = int(pairs.size());
  return q;
}

/// The evenness of a set of times summed up (docs/quality.md, "Evenness").
struct EvennessSummary {
  int wall_ratio_times = 0;  ///< times that have a wall ratio
  std::optional<double> wall_ratio_min, wall_ratio_median, wall_ratio_max;
  std::optional<double> empty_disc_median;  ///< the median time's largest empty disc, in element radii
  std::optional<double> empty_disc_worst;   ///< the largest at any time
  double empty_disc_worst_t = 0.0;
  std::vector<double> contact_mean;  ///< mean_contact
};

/// The middle value of `v` (the mean of the two middle ones for an even count); none when empty.
inline std::optional<double> median_of(std::vector<double> v) {
  if (v.empty()) return std::nullopt;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 == 1 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

inline EvennessSummary summarize_evenness(const std::vector<FrameMetrics>& metrics) {
  EvennessSummary e;
  std::vector<double> walls, discs;
  for (const FrameMetrics& m : metrics) {
    if (m.wall_ratio) walls.push_back(*m.wall_ratio);
    if (const std::optional<double> disc = m.empty_disc()) {
      discs.push_back(*disc);
      if (!e.empty_disc_worst || *disc > *e.empty_disc_worst) e.empty_disc_worst = disc, e.empty_disc_worst_t = m.t;
    }
  }
  e.wall_ratio_times = int(walls.size());
  if (!walls.empty()) {
    e.wall_ratio_min = *std::min_element(walls.begin(), walls.end());
    e.wall_ratio_max = *std::max_element(walls.begin(), walls.end());
  }
  e.wall_ratio_median = median_of(walls);
  e.empty_disc_median = median_of(discs);
  e.contact_mean = mean_contact(metrics);
  return e;
}

}  // namespace animpak
