// A sweep's plan (docs/sweeps.md): every run of `animpak sweep SCENE --out DIR`, each a seed and a value of
// every swept setting, with a stable id made from those values and its folder DIR/runs/ID/. The plan, the
// scene's copy (DIR/input/, as pack keeps one) and each run's scene (DIR/scenes/ID.json) are all a run needs,
// so a run is the same wherever it runs: here, a Slurm array task, a Kubernetes Indexed Job's pod or a line
// of commands.txt.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "commands.hpp"

namespace animpak::cli {

/// The most runs one plan holds: far more than a machine packs in a day, and a Slurm array's ceiling
/// (MaxArraySize) is 1001 by default.
inline constexpr std::size_t kMaxSweepRuns = 10000;

/// One setting swept by --set NAME=V1,V2,...: its name and its values, each with the text its ids use.
struct SweepSetting {
  std::string name;  ///< a parameter of param_table() (k_time), slices, count, or ELEMENT.count
  std::vector<nlohmann::json> values;
  std::vector<std::string> texts;  ///< each value as ids and the page write it (0.5, 12)
};

struct SweepRun {
  std::size_t index = 0;
  std::string id;  ///< seed3-k_time0.5: the folder's name under runs/ and scenes/
  std::uint64_t seed = 0;
  std::vector<std::pair<std::string, nlohmann::json>> set;  ///< the settings' values, in --set order
};

struct SweepPlan {
  std::string scene_file;  ///< the scene's name in DIR/input/
  std::string scene_sha256;
  std::string packed_from;          ///< the scene's path when the plan was made (shown only)
  std::vector<std::string> varied;  ///< the swept settings' names, in --set order
  SweepPackOptions pack;
  std::vector<SweepRun> runs;
};

/// "1-8", "1,3,5-7": the seeds, in the order given, each once; UsageError naming --seeds otherwise.
std::vector<std::uint64_t> parse_seeds(const std::string& text);

/// "k_time=0.05,0.5,5": UsageError naming the --set and what is wrong (an unknown name, a value outside
/// the parameter's range from param_table(), not a whole number where one is needed).
SweepSetting parse_setting(const std::string& text);

/// The runs of every seed and every combination of the settings' values (seeds outermost, then the
/// settings in order), each with its id; UsageError for more than kMaxSweepRuns runs.
std::vector<SweepRun> plan_runs(const std::vector<std::uint64_t>& seeds, const std::vector<SweepSetting>& settings);

/// `id` is a run's id as plan_runs makes them: letters, digits and . _ - + only, not starting with a dot.
bool valid_run_id(const std::string& id);

/// The scene of one run: `base` (a scene's text) with the run's seed and settings put in, and every art
/// reference replaced by `art_reference(written)`. UsageError when a setting names an element the scene
/// does not have, or one drawn by weight.
std::string run_scene_text(const std::string& base, const SweepRun& run,
                           const std::function<std::string(const std::string& written)>& art_reference);

/// plan.json's text, and the plan read back from it (InputError naming the file and the field when it is not
/// a plan this animpak wrote: a plan is read on every node, and may have been copied from anywhere).
std::string plan_json(const SweepPlan& plan);
SweepPlan read_plan(const std::filesystem::path& dir);

/// DIR/runs/ID, DIR/scenes/ID.json, DIR/status/ID.json.
std::filesystem::path run_folder(const std::filesystem::path& dir, const SweepRun& run);
std::filesystem::path run_scene_file(const std::filesystem::path& dir, const SweepRun& run);
std::filesystem::path run_status_file(const std::filesystem::path& dir, const SweepRun& run);

/// The arguments after `animpak` that pack run `run` fresh into its folder (pack SCENE --out DIR ...), continue
/// it (pack --resume), render it or write its report page.
enum class RunStep { none, pack, resume, repack, render, report };
std::vector<std::string> step_arguments(RunStep step, const std::filesystem::path& dir, const SweepPlan& plan,
                                        const SweepRun& run);
const char* step_name(RunStep step);

/// What run `run` needs next, from what its folder holds: nothing (complete: packed to its stop, rendered,
/// with its report page), or the step that continues it.
RunStep next_step(const std::filesystem::path& dir, const SweepRun& run);

/// The cluster files beside plan.json: slurm.sbatch, k8s-job.yaml, commands.txt.
struct ClusterOptions {
  std::string animpak;  ///< the animpak each task runs (a path on the nodes)
  std::string k8s_animpak;
  std::string k8s_image;
  std::string k8s_claim;
  int cpus_per_task = 2;
  int parallelism = 1;  ///< the Indexed Job's pods at a time
};
std::string slurm_script(const std::filesystem::path& dir, const SweepPlan& plan, const ClusterOptions& options);
std::string k8s_job(const std::filesystem::path& dir, const SweepPlan& plan, const ClusterOptions& options);
std::string command_lines(const std::filesystem::path& dir, const SweepPlan& plan, const ClusterOptions& options);

/// "0-3,5,7-9": indices as a Slurm --array list.
std::string index_ranges(const std::vector<std::size_t>& indices);

}  // namespace animpak::cli
