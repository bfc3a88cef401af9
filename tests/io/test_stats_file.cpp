// stats.json's typed model (animpak/stats.hpp): what the writer writes the reader reads back equal, field by
// field; files of earlier versions, which lack later fields, read and write back as they were; a section of
// another shape and a field the model does not know are kept as they are.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

#include "animpak/error.hpp"
#include "animpak/stats.hpp"

using Catch::Matchers::Contains;

namespace stats_file_test {

animpak::StatsFrame sample_frame(double base, bool evenness) {
  animpak::StatsFrame f;
  f.t = base + 0.01;
  f.coverage = base + 0.02;
  f.min_gap = base + 0.03;
  f.mean_gap = base + 0.04;
  f.channel_cv = base + 0.05;
  f.overlapping_pairs = 2;
  f.elements_outside = {{"star#1", base + 0.06}, {"bee", base + 0.07}};
  f.overlaps = {{"star#1", "bee", base + 0.08}};
  f.worst_outside = {"bee", base + 0.09};
  f.worst_overlap = {"star#2", "star#3", base + 0.11};
  if (evenness)
    f.evenness = animpak::StatsFrameEvenness{base + 0.12, base + 0.13, base + 0.14, base + 0.15, {0.9, 0.5}};
  return f;
}

animpak::StatsSummary sample_summary(double base, bool evenness) {
  animpak::StatsSummary q;
  q.times = 4;
  q.element_frames = 12;
  q.element_frames_outside = 3;
  q.worst_outside = {"bee", base + 0.01};
  q.worst_outside_t = base + 0.02;
  q.overlapping_pair_frames = 5;
  q.overlapping_pairs = 2;
  q.worst_overlap = {"star#1", "bee", base + 0.03};
  q.worst_overlap_t = base + 0.04;
  q.coverage_min = base + 0.05;
  q.coverage_max = base + 0.06;
  q.coverage_mean = base + 0.07;
  q.min_gap = base + 0.08;
  q.channel_cv_mean = base + 0.09;
  q.channel_cv_max = base + 0.11;
  if (evenness)
    q.evenness = animpak::StatsEvennessSummary{3, 0.41, 0.52, 0.63, 0.74, 0.85, 0.96, 0.05, {0.8, 0.3, 0.1}};
  return q;
}

// Every field set, each to a value of its own (none left at its default), so that a field the writer or the
// reader drops reads back different.
animpak::Stats sample_stats() {
  animpak::Stats s;
  s.format_version = 1;
  s.animpak = "9.8.7";
  s.commit = "abc1234";
  s.scene = "examples/default/scene.json";
  s.seed = 18446744073709551615ull;
  s.device = "PoCL cpu";
  s.driver = "3.1";
  s.elements = 3;
  s.vertices = 1234;
  s.springs = 5678;
  s.envelope_triangles = 910;
  s.iterations = 300;
  s.stop_reason = "max_iterations";
  s.secondary_since = 120;
  s.seconds = animpak::StatsSeconds{0.25, 31.5, {{"forces", 29.75}, {"grid", 0.5}}};
  s.final_growth = {{"star#1", 0.5, 0.625, 0.75}, {"bee", 0.125, 0.25, 0.375}};
  animpak::StatsProgress progress;
  progress.rows = {{10, 0.5, 0.3, 1.0, std::numeric_limits<double>::quiet_NaN(), 0, 2},
                   {20, 1.25, 0.4, 0.5, 0.0625, 3, 1}};
  progress.unit_mesh_density = 612.5;
  progress.stall = animpak::StatsProgress::Stall{400, 0.004, 4};
  progress.secondary = true;
  s.progress = progress;
  s.kernels = {{"repulsion", "forces", 12.5, 300}, {"host: sort", "grid", 0.25, 300}};
  s.frames = {sample_frame(0.1, true), sample_frame(0.2, true)};
  s.between_slices = {sample_frame(0.3, false)};
  s.quality = animpak::StatsQuality{0.002, sample_summary(0.4, true), sample_summary(0.5, false)};
  animpak::StatsMotion m;
  m.acceleration_median = 0.0125;
  m.acceleration_p99 = 0.5;
  m.frame_peak = {0.25, std::numeric_limits<double>::quiet_NaN()};
  m.kink = 40.0;
  m.slice_ratio = 1.5;
  m.size_over_script = {{"star#1", 1.125}, {"bee", 1.25}};
  m.movement = {{"star#1", false, 0.0625, 1.0, 0.5}, {"bee", true, 0.125, 0.75, 2.5}};
  s.motion = m;
  s.still_reference = animpak::StatsStillReference{"/tmp/still", 0.5, 0.75, 0.875};
  s.rendered_by = "def5678";
  return s;
}

// The model with its NaNs (none) set to a number, so that == can compare it (NaN equals nothing).
animpak::Stats comparable(animpak::Stats s) {
  for (auto& row : s.progress->rows)
    if (std::isnan(row.max_gap)) row.max_gap = -1.0;
  for (double& peak : *s.motion->frame_peak)
    if (std::isnan(peak)) peak = -1.0;
  return s;
}

}  // namespace stats_file_test

using namespace stats_file_test;

TEST_CASE("stats.json's model: every field written is read back equal, and the text is stable") {
  const animpak::Stats s = sample_stats();
  const std::string text = animpak::stats_json_text(s);
  const animpak::Stats back = animpak::parse_stats(text, "stats.json");
  CHECK(back.kept.empty());
  CHECK(comparable(back) == comparable(s));
  CHECK(std::isnan(back.progress->rows[0].max_gap));
  CHECK(std::isnan((*back.motion->frame_peak)[1]));
  CHECK(animpak::stats_json_text(back) == text);
  // The comparison itself sees a field that differs, at every level of the tree.
  animpak::Stats changed = comparable(back);
  (*changed.frames)[1].evenness->contact[1] = 0.25;
  CHECK_FALSE(changed == comparable(s));
  changed = comparable(back);
  changed.quality->between_slices.worst_overlap.b = "star#9";
  CHECK_FALSE(changed == comparable(s));
  // The file's own shape: none is null, an empty name is null, the evenness only where it was measured.
  const nlohmann::json j = nlohmann::json::parse(text);
  CHECK(j["progress"]["rows"][0][4].is_null());
  CHECK(j["progress"]["columns"] == nlohmann::json(animpak::kStatsProgressColumns));
  CHECK(j["frames"][0].contains("wall_ratio"));
  CHECK_FALSE(j["between_slices"][0].contains("wall_ratio"));
  CHECK(j["quality"]["frames"]["contact"]["step"] == 0.05);
  CHECK_FALSE(j["quality"]["between_slices"].contains("contact"));
  CHECK(j["quality"]["frames"]["worst_outside"]["t"].get<double>() == s.quality->frames.worst_outside_t);
  CHECK(j["seconds"]["forces"] == 29.75);
  CHECK(j["seed"].get<std::uint64_t>() == 18446744073709551615ull);
  animpak::Stats nameless = s;
  nameless.quality->frames.worst_outside.element.clear();
  CHECK(nlohmann::json::parse(animpak::stats_json_text(nameless))["quality"]["frames"]["worst_outside"]["element"]
            .is_null());
}

TEST_CASE("stats.json's model: an earlier version's file, without later fields, reads and writes back as it was") {
  // What render writes without a stats.json of the packing's own, and a frame measured before evenness: the
  // later fields are absent, and stay absent.
  const std::string old = R"({
  "animpak": "0.3.0",
  "elements": 2,
  "format_version": 1,
  "frames": [
    {
      "channel_cv": 0.5,
      "coverage": 0.25,
      "elements_outside": [],
      "mean_gap": 0.125,
      "min_gap": null,
      "overlapping_pairs": 0,
      "overlaps": [],
      "t": 0.0,
      "worst_outside": {
        "element": null,
        "share": 0.0
      },
      "worst_overlap": {
        "a": null,
        "b": null,
        "share": 0.0
      }
    }
  ],
  "iterations": 40,
  "motion": {
    "acceleration": {
      "median": 0.5,
      "p99": 2.0
    },
    "kink": null
  },
  "scene": "scene.json",
  "seed": 1,
  "stop_reason": "max_iterations",
  "vertices": 300
}
)";
  const animpak::Stats s = animpak::parse_stats(old, "stats.json");
  CHECK(s.kept.empty());
  CHECK_FALSE(s.commit);
  CHECK_FALSE(s.progress);
  CHECK_FALSE(s.quality);
  REQUIRE(s.frames);
  CHECK_FALSE(s.frames->front().evenness);
  CHECK(std::isnan(s.frames->front().min_gap));
  CHECK(s.frames->front().worst_outside.element.empty());
  REQUIRE(s.motion);
  CHECK_FALSE(s.motion->frame_peak);
  CHECK_FALSE(s.motion->movement);
  CHECK(std::isnan(s.motion->kink));
  CHECK(animpak::stats_json_text(s) == old);
}

TEST_CASE(
    "stats.json's model: a section of another shape and an unknown field are kept, a file without its fields is "
    "refused") {
  const std::string text = R"({
  "animpak": "0.17.0",
  "elements": 2,
  "format_version": 1,
  "future_field": {
    "x": [
      1,
      2
    ]
  },
  "iterations": 40,
  "progress": {
    "columns": [
      "iteration",
      "seconds"
    ],
    "rows": [
      [
        1,
        0.5
      ]
    ]
  },
  "scene": "scene.json",
  "seed": 1,
  "stop_reason": "converged",
  "vertices": 300
}
)";
  const animpak::Stats s = animpak::parse_stats(text, "stats.json");
  CHECK_FALSE(s.progress);
  CHECK(s.kept.size() == 2);
  CHECK(s.kept.count("future_field") == 1);
  CHECK(s.kept.count("progress") == 1);
  CHECK(animpak::stats_json_text(s) == text);
  CHECK_THROWS_AS(animpak::parse_stats("[1, 2]", "runs/x/stats.json"), animpak::InputError);
  CHECK_THROWS_WITH(animpak::parse_stats(R"({"format_version": 1, "animpak": "0.17.0"})", "runs/x/stats.json"),
                    Contains("runs/x/stats.json") && Contains("\"scene\""));
  CHECK_THROWS_WITH(animpak::parse_stats("not json", "runs/x/stats.json"), Contains("not a JSON object"));
}
