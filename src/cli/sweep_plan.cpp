// A sweep's plan, its runs' scenes and steps, and the cluster files (sweep_plan.hpp; docs/sweeps.md).
#include "sweep_plan.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>
#include <sstream>

#include "animpak/checkpoint.hpp"
#include "animpak/error.hpp"
#include "animpak/file_io.hpp"
#include "animpak/param_table.hpp"
#include "animpak/sha256.hpp"
#include "animpak/version.hpp"
#include "console.hpp"
#include "pack_output.hpp"
#include "packed_folder.hpp"

namespace animpak::cli {
namespace fs = std::filesystem;
using nlohmann::json;
using ordered_json = nlohmann::ordered_json;

namespace {

constexpr int kPlanVersion = 1;
// An element's count, as docs/scene-format.md gives its range.
constexpr long long kMaxCount = 100000;
constexpr const char* kSetHelp =
    "a parameter of `animpak params` (k_time), slices, count (the scene's), or an element's count "
    "(NAME.count, NAME as the scene's elements[i].name or its art file's stem)";

// The shortest text that reads back as `value` (0.5, 5e-05, 12).
std::string number_text(double value) {
  char text[64];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value);
  return error == std::errc() ? std::string(text, end) : std::to_string(value);
}

std::optional<std::uint64_t> whole_number(const std::string& text) {
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || !std::isdigit(static_cast<unsigned char>(text.front())) || error != std::errc() || stop != end)
    return std::nullopt;
  return value;
}

std::vector<std::string> split(const std::string& text, char by) {
  std::vector<std::string> parts;
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = std::min(text.find(by, begin), text.size());
    std::string part = text.substr(begin, end - begin);
    part.erase(0, part.find_first_not_of(" \t"));
    part.erase(part.find_last_not_of(" \t") + 1);
    parts.push_back(part);
    if (end == text.size()) return parts;
    begin = end + 1;
  }
}

const ParamInfo* find_param(const std::string& name) {
  for (const ParamInfo& info : param_table())
    if (info.name == name) return &info;
  return nullptr;
}

// The part of an id a name contributes: its characters outside [A-Za-z0-9._] made '_'.
std::string id_part(const std::string& text) {
  std::string part = text;
  for (char& c : part)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') c = '_';
  return part;
}

// The element of a scene's "elements" that `name` means: the one named so, or one without a name whose
// art file's stem it is.
ordered_json* find_element(ordered_json& root, const std::string& name, std::string& names) {
  if (!root.contains("elements") || !root["elements"].is_array()) return nullptr;
  ordered_json* found = nullptr;
  for (ordered_json& e : root["elements"]) {
    if (!e.is_object()) continue;
    std::string own;
    if (e.contains("name") && e["name"].is_string())
      own = e["name"].get<std::string>();
    else if (e.contains("art") && e["art"].is_string())
      own = fs::path(e["art"].get<std::string>()).stem().string();
    names += (names.empty() ? "" : ", ") + own;
    if (own == name && !found) found = &e;
  }
  return found;
}

void apply_setting(ordered_json& root, const std::string& name, const json& value) {
  if (name == "slices") {
    // Where the scene gives it already (a scene may not give it twice), else at the top level.
    if (!root.contains("slices") && root.contains("params") && root["params"].is_object() &&
        root["params"].contains("slices"))
      root["params"]["slices"] = value;
    else
      root["slices"] = value;
    return;
  }
  if (name == "count") {
    root["count"] = value;
    return;
  }
  const std::string suffix = ".count";
  if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
    const std::string element = name.substr(0, name.size() - suffix.size());
    std::string names;
    ordered_json* e = find_element(root, element, names);
    if (!e)
      throw UsageError("--set " + name + ": the scene has no element named \"" + element +
                       "\" (its elements: " + names + ")");
    if (e->contains("weight"))
      throw UsageError("--set " + name + ": element \"" + element +
                       "\" is drawn by weight in the scene; a count and a weight cannot go together, so remove its "
                       "\"weight\" (or give it a \"count\") to sweep its count");
    (*e)["count"] = value;
    return;
  }
  if (!root.contains("params") || !root["params"].is_object()) root["params"] = ordered_json::object();
  root["params"][name] = value;
}

// Every art reference of a scene: the container's and each element's.
void rewrite_art(ordered_json& root, const std::function<std::string(const std::string&)>& art_reference) {
  if (root.contains("container")) {
    ordered_json& c = root["container"];
    if (c.is_string())
      c = art_reference(c.get<std::string>());
    else if (c.is_object() && c.contains("art") && c["art"].is_string())
      c["art"] = art_reference(c["art"].get<std::string>());
  }
  if (root.contains("elements") && root["elements"].is_array())
    for (ordered_json& e : root["elements"])
      if (e.is_object() && e.contains("art") && e["art"].is_string())
        e["art"] = art_reference(e["art"].get<std::string>());
}

const char* kFrameKeys[] = {"frames", "size", "fps", "format", "precision", "interpolation", "background", "container"};

ordered_json pack_json(const SweepPackOptions& p) {
  const FrameOptions& f = p.frames;
  ordered_json formats = ordered_json::array();
  for (const std::string& item : f.formats) formats.push_back(item);
  return {{"max_iterations", p.max_iterations ? ordered_json(*p.max_iterations) : ordered_json(nullptr)},
          {"device", p.device},
          {"grid_sort", p.grid_sort},
          {"checkpoint_every", p.checkpoint_seconds},
          {"frames", f.frames},
          {"size", f.size},
          {"fps", f.fps},
          {"format", formats},
          {"precision", f.precision},
          {"interpolation", f.interpolation},
          {"background", f.background},
          {"container", f.no_container ? std::string("none") : f.container}};
}

}  // namespace

std::vector<std::uint64_t> parse_seeds(const std::string& text) {
  std::vector<std::uint64_t> seeds;
  std::set<std::uint64_t> seen;
  for (const std::string& item : split(text, ',')) {
    const std::size_t dash = item.find('-');
    const auto bad = [&](const std::string& why) {
      return UsageError("--seeds " + text + ": \"" + item + "\" " + why +
                        "; give seeds and ranges of whole numbers from 0 to 2^64 - 1, separated by commas (1-8, "
                        "or 1,3,5-7)");
    };
    const std::optional<std::uint64_t> first = whole_number(item.substr(0, dash));
    const std::optional<std::uint64_t> last = dash == std::string::npos ? first : whole_number(item.substr(dash + 1));
    if (!first || !last) throw bad("is not a seed or a range of seeds");
    if (*last < *first) throw bad("ends before it starts");
    if (*last - *first >= kMaxSweepRuns) throw bad("holds more than " + std::to_string(kMaxSweepRuns) + " seeds");
    for (std::uint64_t s = *first;; ++s) {
      if (seen.insert(s).second) seeds.push_back(s);
      if (s == *last) break;
    }
  }
  return seeds;
}

SweepSetting parse_setting(const std::string& text) {
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos || equals == 0)
    throw UsageError("--set " + text + ": expected NAME=V1,V2,... where NAME is " + kSetHelp);
  SweepSetting s;
  s.name = text.substr(0, equals);
  const std::string list = text.substr(equals + 1);
  const ParamInfo* param = find_param(s.name);
  const bool element_count = s.name.size() > 6 && s.name.ends_with(".count");
  if (!param && s.name != "count" && !element_count)
    throw UsageError("--set " + text + ": \"" + s.name + "\" is not a setting a sweep varies; NAME is " + kSetHelp);
  const bool integer = param ? param_is_integer(*param) : true;
  const double lo = param ? param->min : 0.0, hi = param ? param->max : double(kMaxCount);
  std::set<std::string> seen;
  for (const std::string& item : split(list, ',')) {
    const auto bad = [&](const std::string& why) {
      std::string range = "[" + number_text(lo) + ", " + number_text(hi) + "]";
      return UsageError("--set " + text + ": \"" + item + "\" " + why + "; " + s.name + " takes " +
                        (integer ? "a whole number" : "a number") + " in " + range +
                        (param ? " (animpak params; docs/parameters.md)" : ""));
    };
    if (item.empty()) throw bad("is empty (a comma too many?)");
    double value = 0.0;
    const char* end = item.data() + item.size();
    const auto [stop, error] = std::from_chars(item.data(), end, value);
    if (error != std::errc() || stop != end || !std::isfinite(value)) throw bad("is not a number");
    if (integer && value != std::floor(value)) throw bad("is not a whole number");
    if (value < lo || value > hi) throw bad("is outside the range");
    const std::string shown = integer ? std::to_string(static_cast<long long>(value)) : number_text(value);
    if (!seen.insert(shown).second) continue;
    s.values.push_back(integer ? json(static_cast<long long>(value)) : json(value));
    s.texts.push_back(shown);
  }
  return s;
}

std::vector<SweepRun> plan_runs(const std::vector<std::uint64_t>& seeds, const std::vector<SweepSetting>& settings) {
  std::size_t total = seeds.size();
  for (const SweepSetting& s : settings) {
    total *= s.values.size();
    if (total > kMaxSweepRuns) break;
  }
  if (total > kMaxSweepRuns)
    throw UsageError("the sweep would make more than " + std::to_string(kMaxSweepRuns) +
                     " runs (seeds times every setting's values); sweep fewer values at a time");
  std::vector<SweepRun> runs;
  std::set<std::string> ids;
  for (const std::uint64_t seed : seeds) {
    std::vector<std::size_t> at(settings.size(), 0);
    while (true) {
      SweepRun run;
      run.index = runs.size();
      run.seed = seed;
      run.id = "seed" + std::to_string(seed);
      for (std::size_t k = 0; k < settings.size(); ++k) {
        run.set.emplace_back(settings[k].name, settings[k].values[at[k]]);
        run.id += "-" + id_part(settings[k].name) + settings[k].texts[at[k]];
      }
      // Two element names that differ only in characters an id leaves out would meet here.
      for (int n = 2; !ids.insert(run.id).second; ++n) run.id += "_" + std::to_string(n);
      runs.push_back(std::move(run));
      std::size_t k = settings.size();
      while (k > 0 && ++at[k - 1] == settings[k - 1].values.size()) at[--k] = 0;
      if (k == 0) break;
    }
  }
  return runs;
}

bool valid_run_id(const std::string& id) {
  if (id.empty() || id.size() > 200 || id.front() == '.') return false;
  return std::all_of(id.begin(), id.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-' || c == '+';
  });
}

std::string run_scene_text(const std::string& base, const SweepRun& run,
                           const std::function<std::string(const std::string&)>& art_reference) {
  ordered_json root = ordered_json::parse(base, nullptr, false);
  if (root.is_discarded() || !root.is_object()) throw InputError("the sweep's scene is not a JSON object");
  root["seed"] = run.seed;
  for (const auto& [name, value] : run.set) apply_setting(root, name, value);
  rewrite_art(root, art_reference);
  return root.dump(2) + "\n";
}

std::string plan_json(const SweepPlan& plan) {
  ordered_json runs = ordered_json::array();
  for (const SweepRun& run : plan.runs) {
    ordered_json set = ordered_json::object();
    for (const auto& [name, value] : run.set) set[name] = value;
    runs.push_back({{"index", run.index},
                    {"id", run.id},
                    {"seed", run.seed},
                    {"set", set},
                    {"folder", "runs/" + run.id},
                    {"scene", "scenes/" + run.id + ".json"}});
  }
  const ordered_json j = {
      {"format_version", kPlanVersion},
      {"animpak", std::string(animpak_version)},
      {"scene", {{"file", plan.scene_file}, {"sha256", plan.scene_sha256}, {"packed_from", plan.packed_from}}},
      {"varied", plan.varied},
      {"pack", pack_json(plan.pack)},
      {"runs", runs}};
  return j.dump(2) + "\n";
}

SweepPlan read_plan(const fs::path& dir) {
  const fs::path file = dir / "plan.json";
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(file, ec)))
    throw InputError(file.string() + ": not found; `animpak sweep SCENE --out " + dir.string() +
                     "` writes a sweep's plan there");
  const json j =
      json::parse(read_folder_file(dir, "plan.json", "give the folder `animpak sweep` wrote"), nullptr, false);
  std::string field = "format_version";
  try {
    if (j.is_discarded() || !j.is_object()) throw std::exception();
    if (j.at("format_version").get<int>() > kPlanVersion) throw std::exception();
    SweepPlan plan;
    field = "scene";
    plan.scene_file = j.at("scene").at("file").get<std::string>();
    plan.scene_sha256 = j.at("scene").at("sha256").get<std::string>();
    plan.packed_from = j.at("scene").value("packed_from", "");
    // The scene's copy is a file directly in input/, never a path out of the folder.
    if (plan.scene_file.empty() || fs::path(plan.scene_file).filename() != fs::path(plan.scene_file) ||
        plan.scene_file == "." || plan.scene_file == ".." || plan.scene_file == "manifest.json")
      throw std::exception();
    field = "varied";
    plan.varied = j.at("varied").get<std::vector<std::string>>();
    field = "pack";
    const json& p = j.at("pack");
    if (!p.at("max_iterations").is_null()) plan.pack.max_iterations = p.at("max_iterations").get<std::uint64_t>();
    plan.pack.device = p.at("device").get<std::string>();
    plan.pack.grid_sort = p.at("grid_sort").get<std::string>();
    plan.pack.checkpoint_seconds = p.at("checkpoint_every").get<double>();
    for (const char* key : kFrameKeys) {
      field = std::string("pack.") + key;
      static_cast<void>(p.at(key));
    }
    FrameOptions& f = plan.pack.frames;
    f.frames = p.at("frames").get<int>();
    f.size = p.at("size").get<int>();
    f.fps = p.at("fps").get<double>();
    f.formats = p.at("format").get<std::vector<std::string>>();
    f.precision = p.at("precision").get<int>();
    f.interpolation = p.at("interpolation").get<std::string>();
    f.background = p.at("background").get<std::string>();
    f.container = p.at("container").get<std::string>();
    field = "runs";
    std::set<std::string> ids;
    for (const json& r : j.at("runs")) {
      SweepRun run;
      run.index = r.at("index").get<std::size_t>();
      run.id = r.at("id").get<std::string>();
      run.seed = r.at("seed").get<std::uint64_t>();
      field = "runs[" + std::to_string(plan.runs.size()) + "]";
      if (run.index != plan.runs.size() || !valid_run_id(run.id) || !ids.insert(run.id).second ||
          r.at("folder").get<std::string>() != "runs/" + run.id)
        throw std::exception();
      const json& set = r.at("set");
      if (!set.is_object() || set.size() != plan.varied.size()) throw std::exception();
      for (const std::string& name : plan.varied) {
        if (!set.contains(name) || !set[name].is_number()) throw std::exception();
        run.set.emplace_back(name, set[name]);
      }
      plan.runs.push_back(std::move(run));
    }
    if (plan.runs.empty() || plan.runs.size() > kMaxSweepRuns) throw std::exception();
    return plan;
  } catch (const std::exception&) {
    throw InputError(file.string() + ": " + field +
                     ": not a sweep plan this animpak reads (written by another version, or edited); plan the "
                     "sweep again with `animpak sweep SCENE --out DIR`");
  }
}

fs::path run_folder(const fs::path& dir, const SweepRun& run) { return dir / "runs" / run.id; }
fs::path run_scene_file(const fs::path& dir, const SweepRun& run) { return dir / "scenes" / (run.id + ".json"); }
fs::path run_status_file(const fs::path& dir, const SweepRun& run) { return dir / "status" / (run.id + ".json"); }

const char* step_name(RunStep step) {
  switch (step) {
    case RunStep::none:
      return "complete";
    case RunStep::pack:
      return "pack";
    case RunStep::resume:
      return "pack --resume";
    case RunStep::repack:
      return "pack --force";
    case RunStep::render:
      return "render";
    case RunStep::report:
      return "report";
  }
  return "?";
}

std::vector<std::string> step_arguments(RunStep step, const fs::path& dir, const SweepPlan& plan, const SweepRun& run) {
  const fs::path folder = run_folder(dir, run);
  const SweepPackOptions& p = plan.pack;
  const FrameOptions& f = p.frames;
  // Every value as --option=VALUE, so that no value read from plan.json is taken for an option of its own.
  std::vector<std::string> frames = {"--frames=" + std::to_string(f.frames),
                                     "--size=" + std::to_string(f.size),
                                     "--fps=" + number_text(f.fps),
                                     "--precision=" + std::to_string(f.precision),
                                     "--interpolation=" + f.interpolation,
                                     "--background=" + f.background,
                                     "--container=" + (f.no_container ? std::string("none") : f.container)};
  std::string formats;
  for (const std::string& item : f.formats) formats += (formats.empty() ? "" : ",") + item;
  frames.push_back("--format=" + formats);
  std::vector<std::string> solver = {"--grid-sort=" + p.grid_sort,
                                     "--checkpoint-every=" + number_text(p.checkpoint_seconds)};
  if (!p.device.empty()) solver.push_back("--device=" + p.device);
  if (p.max_iterations) solver.push_back("--max-iterations=" + std::to_string(*p.max_iterations));
  std::vector<std::string> args;
  switch (step) {
    case RunStep::pack:
    case RunStep::repack:
      args = {"pack", run_scene_file(dir, run).string(), "--out", folder.string()};
      if (step == RunStep::repack) args.push_back("--force");
      break;
    case RunStep::resume:
      args = {"pack", "--resume", folder.string()};
      break;
    case RunStep::render:
      args = {"render", folder.string()};
      args.insert(args.end(), frames.begin(), frames.end());
      return args;
    case RunStep::report:
      return {"report", folder.string()};
    case RunStep::none:
      return {};
  }
  args.insert(args.end(), solver.begin(), solver.end());
  args.insert(args.end(), frames.begin(), frames.end());
  return args;
}

RunStep next_step(const fs::path& dir, const SweepRun& run) {
  const fs::path folder = run_folder(dir, run);
  std::error_code ec;
  if (!fs::is_directory(fs::symlink_status(folder, ec))) return RunStep::pack;
  if (has_unfinished_pack(folder)) return RunStep::resume;
  if (!fs::is_regular_file(fs::symlink_status(folder / "state.bin", ec))) return RunStep::pack;
  const std::optional<Stats> stats = read_stats_json(folder / "stats.json");
  const bool rendered = stats && stats->frames && !stats->frames->empty();
  // A complete run is told by its stats.json and report page alone: a sweep run again over many runs does not
  // read every state (7.5 MB at the paper's Fig. 1 scale) to skip them. stats.json is written after the
  // state it describes, so a finished stop reason there is the state's.
  const std::string reason = rendered ? stats->stop_reason : "";
  if (!reason.empty() && reason != "interrupted" && reason != "running" && reason != "non_finite" &&
      fs::is_regular_file(fs::symlink_status(folder / "report.html", ec)))
    return RunStep::none;
  const Checkpoint checkpoint = read_checkpoint(folder / "state.bin", folder);
  if (checkpoint.stop_reason == "interrupted" || checkpoint.stop_reason == "running") return RunStep::resume;
  // A packing that blew up is the run's failure; running the run again starts it anew.
  if (checkpoint.stop_reason == "non_finite") return RunStep::repack;
  if (!rendered) return RunStep::render;
  if (!fs::is_regular_file(fs::symlink_status(folder / "report.html", ec))) return RunStep::report;
  return RunStep::none;
}

std::string index_ranges(const std::vector<std::size_t>& indices) {
  std::string text;
  for (std::size_t i = 0; i < indices.size();) {
    std::size_t j = i;
    while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1) ++j;
    text += (text.empty() ? "" : ",") + std::to_string(indices[i]) +
            (j > i ? "-" + std::to_string(indices[j]) : std::string());
    i = j + 1;
  }
  return text;
}

std::string slurm_script(const fs::path& dir, const SweepPlan& plan, const ClusterOptions& options) {
  const std::string home = fs::absolute(dir).lexically_normal().string();
  std::ostringstream s;
  s << "#!/bin/sh\n"
    << "# animpak sweep: one Slurm array job over " << home << "/plan.json, one task per run (" << plan.runs.size()
    << " runs).\n"
    << "# Submit it with `sbatch " << shell_word(home + "/slurm.sbatch")
    << "` (or `animpak sweep ... --submit slurm`); each task packs its run\n"
    << "# into runs/ID/ and skips a run already complete. animpak must be at the path below on every node and\n"
    << "# this folder on a file system every node shares (docs/sweeps.md).\n"
    << "#SBATCH --job-name=animpak-sweep\n"
    << "#SBATCH --array=0-" << plan.runs.size() - 1 << "\n"
    << "#SBATCH --ntasks=1\n"
    << "#SBATCH --cpus-per-task=" << options.cpus_per_task << "\n"
    << "#SBATCH --output=" << home << "/logs/slurm-%A_%a.out\n"
    << "#SBATCH --open-mode=append\n"
    << "exec " << shell_word(options.animpak) << " sweep-task " << shell_word(home) << "\n";
  return s.str();
}

std::string k8s_job(const fs::path& dir, const SweepPlan& plan, const ClusterOptions& options) {
  const std::string home = fs::absolute(dir).lexically_normal().string();
  // A name Kubernetes takes (lower case, digits, '-'), different for every folder and plan.
  const std::string name = "animpak-sweep-" + sha256_hex(home + "\n" + plan_json(plan)).substr(0, 10);
  const auto quoted = [](const std::string& text) { return json(text).dump(); };
  std::ostringstream s;
  s << "# animpak sweep: a Kubernetes Indexed Job over " << home << "/plan.json, one completion per run ("
    << plan.runs.size() << " runs).\n"
    << "# `kubectl apply -f k8s-job.yaml`. Each pod runs `animpak sweep-task DIR`, which reads its run from\n"
    << "# JOB_COMPLETION_INDEX. The image must hold animpak, and the claim below the sweep's folder, mounted at\n"
    << "# the same path; edit both for your cluster (docs/sweeps.md, \"Kubernetes\").\n"
    << "apiVersion: batch/v1\n"
    << "kind: Job\n"
    << "metadata:\n"
    << "  name: " << name << "\n"
    << "spec:\n"
    << "  completionMode: Indexed\n"
    << "  completions: " << plan.runs.size() << "\n"
    << "  parallelism: " << std::max<std::size_t>(1, std::min<std::size_t>(plan.runs.size(), options.parallelism))
    << "\n"
    << "  backoffLimit: " << plan.runs.size() << "\n"
    << "  template:\n"
    << "    spec:\n"
    << "      restartPolicy: Never\n"
    << "      containers:\n"
    << "        - name: animpak\n"
    << "          image: " << quoted(options.k8s_image) << "\n"
    << "          command: [" << quoted(options.k8s_animpak) << ", \"sweep-task\", " << quoted(home) << "]\n"
    << "          resources:\n"
    << "            requests:\n"
    << "              cpu: \"" << options.cpus_per_task << "\"\n"
    << "          volumeMounts:\n"
    << "            - name: sweep\n"
    << "              mountPath: " << quoted(home) << "\n"
    << "      volumes:\n"
    << "        - name: sweep\n"
    << "          persistentVolumeClaim:\n"
    << "            claimName: " << quoted(options.k8s_claim) << "\n";
  return s.str();
}

std::string command_lines(const fs::path& dir, const SweepPlan& plan, const ClusterOptions& options) {
  const std::string home = fs::absolute(dir).lexically_normal().string();
  std::string lines;
  for (const SweepRun& run : plan.runs)
    lines += shell_word(options.animpak) + " sweep-task " + shell_word(home) + " --index " + std::to_string(run.index) +
             "\n";
  return lines;
}

}  // namespace animpak::cli
