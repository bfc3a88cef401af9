#include "pack_output.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>
#include <tuple>

#include "animpak/curve.hpp"
#include "animpak/error.hpp"
#include "animpak/file_io.hpp"
#include "animpak/quality_summary.hpp"
#include "animpak/stats.hpp"
#include "animpak/version.hpp"
#include "evenness_output.hpp"

namespace animpak::cli {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

LevelTimes total_times(const std::vector<LevelTimes>& levels) {
  LevelTimes total;
  for (const LevelTimes& l : levels) {
    total.iterations += l.iterations;
    total.seconds += l.seconds;
    for (const NamedPhase& phase : phase_fields) total.times.*phase.seconds += l.times.*phase.seconds;
    for (const KernelTime& k : l.kernels) {
      const auto same = std::find_if(total.kernels.begin(), total.kernels.end(),
                                     [&](const KernelTime& t) { return t.name == k.name; });
      if (same == total.kernels.end()) {
        total.kernels.push_back(k);
      } else {
        same->seconds += k.seconds;
        same->launches += k.launches;
      }
    }
  }
  return total;
}

LoadedWorld world_from_checkpoint(const Checkpoint& checkpoint, bool with_state, const PackedScene& packed) {
  const auto start = std::chrono::steady_clock::now();
  SceneSpec scene = parse_scene(packed.text, packed.file, packed.file.parent_path(), packed.locate);
  scene.seed = checkpoint.seed;
  // A state at the coarse level (docs/parameters.md, "Coarse to fine") is of the scene at that level's slices.
  if (checkpoint.level_slices != 0) scene.params.element.slices = checkpoint.level_slices;
  LoadedWorld loaded{make_world(scene), 0.0};
  if (with_state) {
    const Topology& topo = loaded.world.topology;
    const SimState& s = checkpoint.state;
    // Each array against what the scene builds, named, so that the two numbers in the message differ.
    const std::tuple<const char*, std::size_t, std::size_t> sizes[] = {
        {"vertices", std::size_t(topo.vertex_count()), s.x.size()},
        {"spring ends", topo.spring_other.size(), s.spring_rest.size()},
        {"slices", std::size_t(topo.slice_count()), s.growth.size()}};
    for (const auto& [what, built, held] : sizes)
      if (built != held)
        throw InputError(packed.file.string() + ": the scene now builds " + std::to_string(built) + " " + what +
                         " but the state holds " + std::to_string(held) +
                         "; the scene or its art changed since packing, so pack it again");
    loaded.world.state = s;
  }
  loaded.setup_seconds = seconds_since(start);
  return loaded;
}

namespace {

std::string percent(double share, int decimals) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(decimals) << 100.0 * share;
  return s.str();
}

std::string summary_line(const std::string& label, const QualitySummary& q) {
  std::ostringstream s;
  s << label << ": " << q.outside << " of " << q.element_times << " element-frames outside (worst "
    << percent(q.worst_outside.share, 1) << " %), " << q.overlapping << " overlapping pair-frames in "
    << q.overlapping_pairs << " pairs (worst " << percent(q.worst_overlap.share, 1) << " %), coverage "
    << percent(q.coverage_min, 0) << "–" << percent(q.coverage_max, 0) << " %, channel CV " << std::fixed
    << std::setprecision(2) << q.channel_cv_mean;
  return s.str();
}

StatsElementShare element_share(const World& w, const ElementShare& e) {
  return {e.element >= 0 ? drawn_name(w, e.element) : std::string(), e.share};
}

StatsPairShare pair_share(const World& w, const PairShare& p) {
  auto name = [&](int i) { return i >= 0 ? drawn_name(w, i) : std::string(); };
  return {name(p.a), name(p.b), p.share};
}

// The per-frame figures; `evenness` for the frames (the points between slices are measured without it:
// docs/quality.md, "Evenness").
std::vector<StatsFrame> frame_stats(const World& w, const std::vector<FrameMetrics>& metrics, bool evenness) {
  std::vector<StatsFrame> out;
  for (const FrameMetrics& m : metrics) {
    StatsFrame f;
    f.t = m.t;
    f.coverage = m.coverage;
    f.min_gap = m.min_gap;
    f.mean_gap = m.mean_gap;
    f.channel_cv = m.channel_cv;
    for (const ElementShare& e : m.elements_outside()) f.elements_outside.push_back(element_share(w, e));
    const std::vector<PairShare> overlapping = m.overlapping();
    f.overlapping_pairs = std::int64_t(overlapping.size());
    for (const PairShare& p : overlapping) f.overlaps.push_back(pair_share(w, p));
    f.worst_outside = element_share(w, m.worst_outside());
    f.worst_overlap = pair_share(w, m.worst_overlap());
    if (evenness) {
      const double none = std::numeric_limits<double>::quiet_NaN();
      f.evenness = StatsFrameEvenness{m.element_radius, m.wall_ratio.value_or(none), m.empty_disc().value_or(none),
                                      m.empty_disc_radius, m.contact};
    }
    out.push_back(std::move(f));
  }
  return out;
}

StatsSummary summary_stats(const World& w, const QualitySummary& q) {
  StatsSummary s;
  s.times = q.times;
  s.element_frames = q.element_times;
  s.element_frames_outside = q.outside;
  s.worst_outside = element_share(w, q.worst_outside);
  s.worst_outside_t = q.worst_outside_t;
  s.overlapping_pair_frames = q.overlapping;
  s.overlapping_pairs = q.overlapping_pairs;
  s.worst_overlap = pair_share(w, q.worst_overlap);
  s.worst_overlap_t = q.worst_overlap_t;
  s.coverage_min = q.coverage_min;
  s.coverage_max = q.coverage_max;
  s.coverage_mean = q.coverage_mean;
  s.min_gap = q.min_gap;
  s.channel_cv_mean = q.channel_cv_mean;
  s.channel_cv_max = q.channel_cv_max;
  return s;
}

StatsEvennessSummary evenness_stats(const EvennessSummary& e) {
  const double none = std::numeric_limits<double>::quiet_NaN();
  return {e.wall_ratio_times,
          e.wall_ratio_min.value_or(none),
          e.wall_ratio_median.value_or(none),
          e.wall_ratio_max.value_or(none),
          e.empty_disc_median.value_or(none),
          e.empty_disc_worst.value_or(none),
          e.empty_disc_worst ? e.empty_disc_worst_t : none,
          contact_step,
          e.contact_mean};
}

// The per-frame and between-slice metrics and their summaries (docs/quality.md, "stats.json").
void set_quality(Stats& stats, const World& w, const PackingQuality& quality) {
  stats.frames = frame_stats(w, quality.frames, true);
  stats.between_slices = frame_stats(w, quality.between_slices, false);
  StatsQuality q{quality_share_threshold, summary_stats(w, summarize(quality.frames)),
                 summary_stats(w, summarize(quality.between_slices))};
  q.frames.evenness = evenness_stats(summarize_evenness(quality.frames));
  stats.quality = q;
  // docs/quality.md, "Motion"; a kink of infinity (straight lines: no acceleration inside intervals) is null.
  const MotionMetrics& m = quality.motion;
  StatsMotion motion;
  motion.acceleration_median = m.acceleration_median;
  motion.acceleration_p99 = m.acceleration_p99;
  motion.frame_peak = m.frame_peak;
  motion.kink = m.kink();
  motion.slice_ratio = m.slice_ratio;
  motion.size_over_script.emplace();
  for (std::size_t e = 0; e < m.size_over_script.size() && e < w.elements.size(); ++e)
    motion.size_over_script->push_back({w.elements[e].name, m.size_over_script[e]});
  motion.movement.emplace();
  for (std::size_t e = 0; e < m.detour.size() && e < w.elements.size(); ++e)
    motion.movement->push_back(
        {w.elements[e].name, w.elements[e].guided, m.detour[e], w.elements[e].dip, m.path_length[e]});
  stats.motion = motion;
}

}  // namespace

// A kink as a whole number, or in powers of ten once it is past a thousand (straight lines between slices
// give 10⁸ and more).
std::string kink_text(double kink) {
  if (!std::isfinite(kink)) return "inf";
  char text[32];
  std::snprintf(text, sizeof text, kink < 1000.0 ? "%.0f" : "%.1e", kink);
  return text;
}

// The slices' visibility, or n/a when no frame lies away from a slice (as many slices as frames).
std::string slices_text(double ratio) {
  if (!std::isfinite(ratio)) return "n/a";
  char text[32];
  std::snprintf(text, sizeof text, ratio < 1000.0 ? "%.1f" : "%.1e", ratio);
  return text;
}

std::string motion_line(const MotionMetrics& m) {
  std::vector<double> sizes = m.size_over_script;
  std::sort(sizes.begin(), sizes.end());
  char line[256];
  const double kink = m.kink();
  std::snprintf(line, sizeof line,
                "motion: kink %s (acceleration 99th percentile over median), slices %s (acceleration next to a "
                "slice over elsewhere), area over the script's varies %.2fx (median element; worst %.2fx)",
                kink_text(kink).c_str(), slices_text(m.slice_ratio).c_str(),
                sizes.empty() ? 1.0 : sizes[sizes.size() / 2], sizes.empty() ? 1.0 : sizes.back());
  // How far the unguided elements move over the loop where a traveller passes them.
  if (std::find(m.guided.begin(), m.guided.end(), true) == m.guided.end()) return line;
  std::vector<double> detours, paths;
  for (std::size_t e = 0; e < m.detour.size(); ++e)
    if (e >= m.guided.size() || !m.guided[e]) detours.push_back(m.detour[e]), paths.push_back(m.path_length[e]);
  if (detours.empty()) return line;
  std::sort(detours.begin(), detours.end());
  std::sort(paths.begin(), paths.end());
  char moves[200];
  std::snprintf(moves, sizeof moves,
                ", unguided elements stray %.3f from their mean place (median; largest %.3f) on a path of %.3f a "
                "loop (median; longest %.3f)",
                detours[detours.size() / 2], detours.back(), paths[paths.size() / 2], paths.back());
  std::string out = std::string(line) + moves;
  int dipping = 0;
  double deepest = 1.0;
  for (const double d : m.dip)
    if (d < 1.0) ++dipping, deepest = std::min(deepest, d);
  if (dipping > 0) {
    char dips[160];
    std::snprintf(dips, sizeof dips, "; %d scripts give way to a traveller, down to %.2fx their size", dipping,
                  deepest);
    out += dips;
  }
  return out;
}

std::string quality_lines(const PackingQuality& quality) {
  return summary_line("quality", summarize(quality.frames)) + "\n" +
         summary_line("between slices", summarize(quality.between_slices)) + "\n" +
         evenness_line(summarize_evenness(quality.frames)) + "\n" +
         (quality.frames.size() >= 3 ? motion_line(quality.motion) + "\n" : "");
}

Stats pack_stats(const PackReport& r) {
  const World& w = r.world;
  Stats stats;
  stats.animpak = std::string(animpak_version);
  stats.commit = std::string(build_commit());
  stats.scene = r.checkpoint.scene_file.string();
  stats.seed = r.checkpoint.seed;
  stats.device = r.device;
  stats.driver = r.driver;
  stats.elements = w.elements.size();
  stats.vertices = w.topology.vertex_count();
  stats.springs = std::int64_t(w.topology.spring_other.size() / 2);
  stats.envelope_triangles = w.topology.envelope_count();
  stats.iterations = r.result.last_good.iteration;
  stats.stop_reason = r.checkpoint.stop_reason;
  stats.secondary_since = r.result.last_good.secondary_since;
  StatsSeconds seconds{r.setup_seconds, r.result.seconds, {}};
  for (const NamedPhase& phase : phase_fields) seconds.phases[phase.name] = r.times.*phase.seconds;
  stats.seconds = seconds;
  stats.final_growth.emplace();
  for (std::size_t e = 0; e < w.elements.size(); ++e) {
    const std::int32_t begin = w.topology.element_slice_begin[e], end = w.topology.element_slice_begin[e + 1];
    float lo = w.state.growth[begin], hi = lo;
    double sum = 0;
    for (std::int32_t s = begin; s < end; ++s) {
      lo = std::min(lo, w.state.growth[s]);
      hi = std::max(hi, w.state.growth[s]);
      sum += w.state.growth[s];
    }
    stats.final_growth->push_back({w.elements[e].name, lo, sum / (end - begin), hi});
  }
  // With the stop test's settings and the world's unit mesh density, the rows are a trace StopModel can be
  // replayed over (scripts/progress-trace.py; docs/cli.md, "Progress and the time left"). A max_gap of
  // infinity (no neighbour yet) is null: JSON has no inf.
  StatsProgress progress;
  for (const ProgressSample& p : r.progress)
    progress.rows.push_back(
        {p.iteration, p.seconds, p.mean_growth, p.growing_share, p.max_gap, p.overlapping, p.outside});
  const Params::Stop& stop = w.params.stop;
  progress.unit_mesh_density = unit_mesh_density(w);
  progress.stall = StatsProgress::Stall{stop.stall_window, stop.stall_growth, stop.stall_tests};
  progress.secondary = w.topology.has_secondary();
  stats.progress = progress;
  if (r.checkpoint.level_slices != 0) stats.level_slices = r.checkpoint.level_slices;
  if (r.levels.size() > 1) {
    stats.levels.emplace();
    for (const LevelTimes& l : r.levels) stats.levels->push_back({l.slices, l.iterations, l.seconds});
  }
  if (!r.kernels.empty()) {
    stats.kernels.emplace();
    for (const KernelTime& k : r.kernels) stats.kernels->push_back({k.name, k.phase, k.seconds, k.launches});
  }
  set_quality(stats, w, r.quality);
  return stats;
}

void write_stats(const std::filesystem::path& file, const PackReport& report) {
  write_stats_file(file, pack_stats(report));
}

std::optional<Stats> read_stats_json(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(std::filesystem::symlink_status(file, ec))) return std::nullopt;
  const std::string text =
      read_folder_file(file.parent_path(), file.filename(), "move it away; animpak writes its statistics there");
  try {
    return parse_stats(text, file);
  } catch (const InputError&) {
    return std::nullopt;  // not a packing's stats.json
  }
}

std::vector<ProgressSample> read_progress(const std::filesystem::path& file) {
  const std::optional<Stats> stats = read_stats_json(file);
  std::vector<ProgressSample> out;
  if (!stats || !stats->progress) return out;
  for (const StatsProgressRow& row : stats->progress->rows)
    out.push_back({row.iteration, row.seconds, row.mean_growth, row.growing_share,
                   std::isnan(row.max_gap) ? std::numeric_limits<double>::infinity() : row.max_gap,
                   row.overlapping_vertices, row.outside_vertices});
  return out;
}

StillReference read_still_reference(const std::filesystem::path& folder) {
  const std::filesystem::path file = folder / "stats.json";
  const std::string what = "--still-reference " + folder.string() + ": ";
  const std::string remedy =
      "; pack the scene standing still first: animpak pack SCENE --still --out " + folder.string();
  if (!std::filesystem::exists(file)) throw InputError(what + "cannot read " + file.string() + remedy);
  const std::optional<Stats> stats = read_stats_json(file);
  if (!stats) throw InputError(what + file.string() + " is not a packing's stats.json" + remedy);
  const double mean = stats->quality ? stats->quality->frames.coverage_mean : 0.0;
  if (!(mean > 0.0))
    throw InputError(what + file.string() +
                     " has no frame coverage (quality.frames.coverage.mean): the packing was not rendered; render "
                     "it with animpak render " +
                     folder.string());
  return {folder, mean};
}

std::string add_still_reference(const std::filesystem::path& file, const StillReference& still,
                                const PackingQuality& quality) {
  std::optional<Stats> stats = read_stats_json(file);
  if (!stats) return {};
  const QualitySummary q = summarize(quality.frames);
  const double lowest = q.coverage_min / still.coverage, mean = q.coverage_mean / still.coverage;
  stats->still_reference = StatsStillReference{std::filesystem::absolute(still.folder).lexically_normal().string(),
                                               still.coverage, lowest, mean};
  write_stats_file(file, *stats);
  std::ostringstream line;
  line << std::fixed << std::setprecision(1) << "still: the same elements standing still cover "
       << 100.0 * still.coverage << " %; the lowest frame here covers " << std::setprecision(2) << lowest
       << " of that, the mean " << mean << "\n";
  return line.str();
}

std::optional<int> packed_motion_curve(const std::filesystem::path& stats_file, const std::string& scene_text) {
  const nlohmann::json scene = nlohmann::json::parse(scene_text, nullptr, false);
  if (scene.is_object() && scene.contains("params") && scene["params"].is_object() &&
      scene["params"].contains("motion_curve"))
    return std::nullopt;  // the scene names its curve: that is the one it was packed on
  // The version alone, from the file's text: a folder of 0.1.x, whose stats.json has no format_version yet (not
  // one parse_stats reads), is one this asks about.
  std::error_code ec;
  if (!std::filesystem::exists(std::filesystem::symlink_status(stats_file, ec))) return std::nullopt;
  const nlohmann::json stats =
      nlohmann::json::parse(read_folder_file(stats_file.parent_path(), stats_file.filename(),
                                             "move it away; animpak writes its statistics there"),
                            nullptr, false);
  if (!stats.is_object() || !stats.contains("animpak") || !stats["animpak"].is_string()) return std::nullopt;
  int major = 0, minor = 0;
  if (std::sscanf(stats["animpak"].get<std::string>().c_str(), "%d.%d", &major, &minor) != 2) return std::nullopt;
  if (major > 0 || minor >= 8) return std::nullopt;
  return minor >= 4 ? curve_monotone : curve_linear;
}

std::optional<StillReference> stored_still_reference(const std::filesystem::path& file) {
  const std::optional<Stats> stats = read_stats_json(file);
  if (!stats || !stats->still_reference || !(stats->still_reference->coverage > 0.0)) return std::nullopt;
  return StillReference{stats->still_reference->folder, stats->still_reference->coverage};
}

std::string update_stats_quality(const std::filesystem::path& file, const std::filesystem::path& written_to,
                                 const Checkpoint& checkpoint, const World& world, const PackingQuality& quality) {
  std::optional<Stats> stats = read_stats_json(file);
  // A stats.json that is not this packing's (not JSON, another tool's, another packing's counts) is kept
  // aside, not merged into: `report` would refuse the mix and send the user back here.
  std::string note;
  std::error_code ec;
  const bool present = std::filesystem::exists(std::filesystem::symlink_status(file, ec));
  if (present && (!stats || stats->elements != world.elements.size() || stats->seed != checkpoint.seed ||
                  stats->iterations != checkpoint.state.iteration)) {
    std::filesystem::path aside = file;
    aside.replace_filename("stats.foreign.json");
    std::filesystem::rename(file, aside);
    note = file.string() + " was not this packing's statistics; kept as " + aside.filename().string() +
           ", and a new one written";
    stats.reset();
  }
  if (!stats) {
    // No stats.json of its own (copied without it, or kept aside above): what the checkpoint itself knows.
    stats.emplace();
    stats->animpak = std::string(animpak_version);
    stats->scene = checkpoint.scene_file.string();
    stats->seed = checkpoint.seed;
    stats->elements = world.elements.size();
    stats->vertices = world.topology.vertex_count();
    stats->iterations = checkpoint.state.iteration;
    stats->stop_reason = checkpoint.stop_reason;
  }
  set_quality(*stats, world, quality);
  stats->rendered_by = std::string(build_commit());
  write_stats_file(written_to, *stats);
  return note;
}

}  // namespace animpak::cli
