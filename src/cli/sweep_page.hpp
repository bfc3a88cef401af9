// What `animpak sweep collect DIR` writes (docs/sweeps.md, "Choosing a packing"): DIR/sweep.html, one
// self-contained page with a card per run, sorted by a measure chosen on the page, and plots of each measure
// against the one setting a sweep varies; and DIR/runs.csv, the same figures for a notebook. Every figure is
// a run's stats.json's, named by its path there (data-stat), as on the report page (report_page.hpp).
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "sweep_plan.hpp"

namespace animpak::cli {

/// A figure of every run, the page sorts by and the CSV lists: its path in stats.json, how the page shows it
/// and which way is better.
struct SweepMeasure {
  std::string key;    ///< the CSV's column and the page's sort key (coverage_min)
  std::string label;  ///< "coverage, lowest frame"
  std::string path;   ///< in stats.json (quality.frames.coverage.min)
  double scale = 1.0;
  int decimals = 2;
  std::string unit;
  std::string better;  ///< high, low, or half (closest to 0.5: the wall ratio of an even packing)
};

/// The measures in the order the cards and the CSV show them; the first is the page's default sort.
const std::vector<SweepMeasure>& sweep_measures();

/// One run as collect found it.
struct CollectedRun {
  const SweepRun* run = nullptr;
  std::string state;          ///< done, failed, running, unfinished, not started
  std::string message;        ///< a failed run's error; what an unfinished one needs
  nlohmann::json stats;       ///< its stats.json (done runs), else null
  std::string frame_png;      ///< frames/frame_0000.png's bytes, when there and not too large
  std::string animation_gif;  ///< animation.gif's bytes, likewise
  std::string picture_note;   ///< why a picture is missing
  bool report = false;        ///< runs/ID/report.html is there
};

struct SweepCollection {
  std::string title;  ///< the sweep folder's name
  const SweepPlan* plan = nullptr;
  std::vector<CollectedRun> runs;  ///< in plan order
};

/// The page (self-contained: pictures as data URIs; the only links are to each run's report page).
std::string sweep_page(const SweepCollection& collection);

/// runs.csv: one row per run, every measure as stats.json has it (coverage as a share, not a percentage).
std::string sweep_csv(const SweepCollection& collection);

}  // namespace animpak::cli
