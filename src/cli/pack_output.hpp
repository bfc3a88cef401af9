// What `pack` and `render` share: the world rebuilt from a checkpoint, stats.json and the quality lines. Drawing the frames
// lives in render_commands.cpp, so that animpak-solve links no rendering library.
#pragma once

#include "animpak/checkpoint.hpp"
#include "animpak/progress.hpp"
#include "animpak/render.hpp"
#include "animpak/run.hpp"
#include "animpak/stats.hpp"
#include "commands.hpp"
#include "packed_folder.hpp"

namespace animpak::cli {

struct LoadedWorld {
  World world;
  double setup_seconds = 0.0;
};

/// Rebuilds the world from `scene`, normally the scene text inside the checkpoint (set-up is deterministic),
/// and with `with_state` puts the checkpoint's state in it after checking that the sizes match.
LoadedWorld world_from_checkpoint(const Checkpoint& checkpoint, bool with_state, const PackedScene& scene);

/// One level's share of a pack run (docs/parameters.md, "Coarse to fine"): its slices per element, the
/// iterations and simulation seconds it ran, and its backend's phase and kernel times.
struct LevelTimes {
  int slices = 0;
  std::uint64_t iterations = 0;
  double seconds = 0.0;
  PhaseTimes times;
  std::vector<KernelTime> kernels;
};

/// The phase and kernel times of every level summed (kernels by name, in first-seen order).
LevelTimes total_times(const std::vector<LevelTimes>& levels);

struct PackReport {
  const World& world;
  const RunResult& result;
  const PhaseTimes& times;
  const Checkpoint& checkpoint;
  PackingQuality quality;  ///< empty when no frames were rendered
  double setup_seconds = 0.0;
  std::string device;                           ///< the backend's name
  std::string driver;                           ///< the device's driver and platform version
  const std::vector<ProgressSample>& progress;  ///< every statistics check of the packing, resumes included
  std::vector<KernelTime> kernels;              ///< device time per kernel (this run's; empty for the reference)
  std::vector<LevelTimes> levels = {};          ///< this run's levels, in order (one: no refinement)
};

void write_stats(const std::filesystem::path& file, const PackReport& report);

/// stats.json's "progress" rows (empty when the file or the rows are missing or not this version's columns):
/// the samples of the runs before a resume.
std::vector<ProgressSample> read_progress(const std::filesystem::path& file);

/// An output folder's stats.json (animpak/stats.hpp); nullopt when it is missing or not a packing's stats.json
/// (parse_stats refuses it). A link or special file in its place is refused (InputError), never opened.
std::optional<Stats> read_stats_json(const std::filesystem::path& file);

/// After `render`: the frame metrics and quality summaries of the frames just rendered in place of those in
/// `file` (stats.json), the rest of what `pack` wrote kept (what the checkpoint knows when there is no
/// file), written to `written_to` (the render's scratch copy, swapped in with the frames). A file that is not this packing's (not JSON, no format_version, another
/// element count, seed or iteration count) is renamed stats.foreign.json first; the note returned says so
/// (empty otherwise).
std::string update_stats_quality(const std::filesystem::path& file, const std::filesystem::path& written_to,
                                 const Checkpoint& checkpoint, const World& world, const PackingQuality& quality);

/// The still reference an animated packing's coverage is judged by (docs/quality.md, "Still reference"):
/// the mean frame coverage in FOLDER/stats.json, a folder that `pack --still` wrote.
struct StillReference {
  std::filesystem::path folder;
  double coverage = 0.0;
};

/// Reads it; InputError naming the file and what to do when it is missing, not JSON, or holds no rendered
/// frames' coverage.
StillReference read_still_reference(const std::filesystem::path& folder);

/// Adds "still_reference" to `file` (stats.json, already written): the folder, its mean coverage, and
/// this packing's lowest and mean frame coverage over it. Returns the `still:` line to print (empty when
/// the file is not a JSON object: it is left as it is).
std::string add_still_reference(const std::filesystem::path& file, const StillReference& still,
                                const PackingQuality& quality);

/// The still reference `file` (stats.json) already carries, if any: a render without --still-reference
/// keeps the comparison, its ratios taken anew for the frames it draws.
std::optional<StillReference> stored_still_reference(const std::filesystem::path& file);

/// The curve between slices a folder was packed on when it is not today's default: a folder whose
/// stats.json says 0.4.0 to 0.7.0 packed it was packed on the monotone cubic (`motion_curve` 1), one
/// before 0.4.0 on straight lines (0), unless its scene names `motion_curve`. Nothing for a folder packed
/// by 0.8.0 or later, without stats.json, or whose scene names the curve.
std::optional<int> packed_motion_curve(const std::filesystem::path& stats_file, const std::string& scene_text);

/// The lines pack and render print at the end: "quality: …" for the frames, "between slices: …" and the
/// frames' "evenness: …".
std::string quality_lines(const PackingQuality& quality);

}  // namespace animpak::cli
