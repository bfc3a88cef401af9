// What the commands print while they work and when they are done (docs/cli.md, "Progress and the time
// left"): clock times, file sizes, the render's progress line and the list of the files a run wrote. Every
// line fits 80 columns.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "animpak/progress.hpp"
#include "animpak/simulation.hpp"

namespace animpak::cli {

/// `word` (a path, an argument) as one word of a POSIX shell command line: as it is when it holds only plain
/// path characters, else in single quotes.
std::string shell_word(const std::string& word);

/// HH:MM:SS.
std::string clock_text(double seconds);

/// "812 B", "24.0 KiB", "3.4 MiB", "1.2 GiB".
std::string size_text(std::uintmax_t bytes);

/// The pack's progress text: "iter 3290  gap 0.0149  growing 43%  00:01:12  ~00:02:32 left" ("estimating"
/// without an estimate, "left+" while secondary elements are still to grow), at most 70 columns for any
/// count up to 10^8; `verbose` adds the overlapping and outside vertex counts and the range of g.
std::string pack_progress_text(const StepStatistics& st, double elapsed, const std::optional<StopEstimate>& estimate,
                               bool verbose);

/// pack --profile's table: each phase's time, share and ms per iteration, then each kernel's (device time
/// from profiling events; "host:" rows are the host's work inside a step), the largest first. Every line
/// within 80 columns; `iterations` 0 leaves out the per-iteration column.
std::string profile_text(const PhaseTimes& times, const std::vector<KernelTime>& kernels, std::uint64_t iterations,
                         double simulation_seconds);

/// "[###.....]": `done` (0..1) of a bar of 8, the pack's progress line on a terminal.
std::string progress_bar(double done);

/// The share of a pack done that its progress bar shows: the time so far over the time so far plus the
/// time left, and never less than it showed before (an estimate that grows holds the bar where it was
/// until the run catches up with it, instead of moving it back).
class ProgressShare {
 public:
  /// The share to show now; 0 while there is no estimate yet (`seconds_left` empty).
  double update(double elapsed, std::optional<double> seconds_left);

 private:
  double shown_ = 0.0;
};

/// The render's progress text for `stage` as FrameOutput::on_progress reports it: "frame 37/100" with the
/// time so far and the time left at the pace of the frames written, or the file being written.
std::string render_progress_text(const std::string& stage, int done, int total, double elapsed);

/// Redraws the render's progress on a terminal (at most every 0.2 s) and prints a line every 5 s and at each
/// stage otherwise; `finish` ends the redrawn line.
class RenderProgress {
 public:
  RenderProgress();
  void operator()(const std::string& stage, int done, int total);
  void finish();

 private:
  bool tty_;
  double start_, last_print_ = -1e9;
  std::string last_stage_;
  bool drawn_ = false;
};

/// Which files the listing names: a pack's own (state.bin, input/) and then the render's, or a render's.
enum class WrittenBy { pack, render };

/// The files of the run in `dir`, one line each with its size: state.bin and input/ (pack only),
/// stats.json, frames/ (count of PNG and SVG frames, total size), animation.*, contact.png. An output folder
/// holds one run (README, "The output folder"), so what is there is what the run wrote. Then, after
/// `removed:`, the files of the run before that the run removed (`removed`, relative to `dir`) and did not
/// write again: frames/ with their count, the others by name, wrapped within 80 columns.
std::string written_files(const std::filesystem::path& dir, WrittenBy by,
                          const std::vector<std::filesystem::path>& removed = {});

}  // namespace animpak::cli
