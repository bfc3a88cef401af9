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
#include "animpak/version.hpp"
#include "evenness_output.hpp"

namespace animpak::cli {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

LoadedWorld world_from_checkpoint(const Checkpoint& checkpoint, bool with_state, const PackedScene& packed) {
  const auto start = std::chrono::steady_clock::now();
  SceneSpec scene = parse_scene(packed.text, packed.file, packed.file.parent_path(), packed.locate);
  scene.seed = checkpoint.seed;
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

QualitySummary summarize(const std::vector<FrameMetrics>& metrics) {
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

nlohmann::json element_share(const World& w, const ElementShare& e) {
  return {{"element", e.element >= 0 ? nlohmann::json(drawn_name(w, e.element)) : nlohmann::json()},
          {"share", e.share}};
}

nlohmann::json pair_share(const World& w, const PairShare& p) {
  auto name = [&](int i) { return i >= 0 ? nlohmann::json(drawn_name(w, i)) : nlohmann::json(); };
  return {{"a", name(p.a)}, {"b", name(p.b)}, {"share", p.share}};
}

nlohmann::json metrics_json(const World& w, const std::vector<FrameMetrics>& metrics) {
  nlohmann::json out = nlohmann::json::array();
  for (const FrameMetrics& m : metrics) {
    nlohmann::json outside = nlohmann::json::array(), overlaps = nlohmann::json::array();
    for (const ElementShare& e : m.elements_outside()) outside.push_back(element_share(w, e));
    const std::vector<PairShare> overlapping = m.overlapping();
    for (const PairShare& p : overlapping) overlaps.push_back(pair_share(w, p));
    out.push_back({{"t", m.t},
                   {"coverage", m.coverage},
                   {"min_gap", m.min_gap},
                   {"mean_gap", m.mean_gap},
                   {"channel_cv", m.channel_cv},
                   {"overlapping_pairs", overlapping.size()},
                   {"elements_outside", outside},
                   {"overlaps", overlaps},
                   {"worst_outside", element_share(w, m.worst_outside())},
                   {"worst_overlap", pair_share(w, m.worst_overlap())}});
  }
  return out;
}

nlohmann::json summary_json(const World& w, const QualitySummary& q) {
  nlohmann::json worst_outside = element_share(w, q.worst_outside), worst_overlap = pair_share(w, q.worst_overlap);
  worst_outside["t"] = q.worst_outside_t;
  worst_overlap["t"] = q.worst_overlap_t;
  return {{"times", q.times},
          {"element_frames", q.element_times},
          {"element_frames_outside", q.outside},
          {"worst_outside", worst_outside},
          {"overlapping_pair_frames", q.overlapping},
          {"overlapping_pairs", q.overlapping_pairs},
          {"worst_overlap", worst_overlap},
          {"coverage", {{"min", q.coverage_min}, {"max", q.coverage_max}, {"mean", q.coverage_mean}}},
          {"min_gap", q.min_gap},
          {"channel_cv", {{"mean", q.channel_cv_mean}, {"max", q.channel_cv_max}}}};
}

// The per-frame and between-slice metrics and their summaries (docs/quality.md, "stats.json").
void set_quality(nlohmann::json& stats, const World& w, const PackingQuality& quality) {
  stats["frames"] = metrics_json(w, quality.frames);
  stats["between_slices"] = metrics_json(w, quality.between_slices);
  stats["quality"] = {{"share_threshold", quality_share_threshold},
                      {"frames", summary_json(w, summarize(quality.frames))},
                      {"between_slices", summary_json(w, summarize(quality.between_slices))}};
  // The points between slices are measured without evenness (docs/quality.md, "Evenness").
  for (std::size_t i = 0; i < quality.frames.size(); ++i) stats["frames"][i].update(evenness_json(quality.frames[i]));
  stats["quality"]["frames"].update(evenness_summary_json(summarize_evenness(quality.frames)));
  // docs/quality.md, "Motion"; a kink of infinity (straight lines: no acceleration inside intervals) is null.
  const MotionMetrics& m = quality.motion;
  nlohmann::json sizes = nlohmann::json::array();
  for (std::size_t e = 0; e < m.size_over_script.size() && e < w.elements.size(); ++e)
    sizes.push_back({{"element", w.elements[e].name}, {"ratio", m.size_over_script[e]}});
  nlohmann::json moves = nlohmann::json::array();
  for (std::size_t e = 0; e < m.detour.size() && e < w.elements.size(); ++e)
    moves.push_back({{"element", w.elements[e].name},
                     {"guided", w.elements[e].guided},
                     {"detour", m.detour[e]},
                     {"dip", w.elements[e].dip},
                     {"path_length", m.path_length[e]}});
  nlohmann::json peaks = nlohmann::json::array();
  for (const double peak : m.frame_peak)
    peaks.push_back(std::isfinite(peak) ? nlohmann::json(peak) : nlohmann::json(nullptr));
  stats["motion"] = {
      {"acceleration", {{"median", m.acceleration_median}, {"p99", m.acceleration_p99}, {"frame_peak", peaks}}},
      {"kink", std::isfinite(m.kink()) ? nlohmann::json(m.kink()) : nlohmann::json(nullptr)},
      {"slice_ratio", std::isfinite(m.slice_ratio) ? nlohmann::json(m.slice_ratio) : nlohmann::json(nullptr)},
      {"size_over_script", sizes},
      {"movement", moves}};
}

// Through a checked temporary file and a rename (write_file_atomically), so that a failed write never loses the statistics
// already there.
void write_json(const std::filesystem::path& file, const nlohmann::json& value) {
  write_file_atomically(file, value.dump(2) + "\n");
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

// The columns of stats.json's "progress" rows, in ProgressSample's order.
const std::vector<std::string> kProgressColumns = {
    "iteration", "seconds", "mean_growth", "growing_share", "max_gap", "overlapping_vertices", "outside_vertices"};

void write_stats(const std::filesystem::path& file, const PackReport& r) {
  using nlohmann::json;
  const World& w = r.world;
  json growth = json::array();
  for (std::size_t e = 0; e < w.elements.size(); ++e) {
    const std::int32_t begin = w.topology.element_slice_begin[e], end = w.topology.element_slice_begin[e + 1];
    float lo = w.state.growth[begin], hi = lo;
    double sum = 0;
    for (std::int32_t s = begin; s < end; ++s) {
      lo = std::min(lo, w.state.growth[s]);
      hi = std::max(hi, w.state.growth[s]);
      sum += w.state.growth[s];
    }
    growth.push_back({{"element", w.elements[e].name}, {"min", lo}, {"mean", sum / (end - begin)}, {"max", hi}});
  }
  json seconds = {{"setup", r.setup_seconds}, {"simulation", r.result.seconds}};
  for (const NamedPhase& phase : phase_fields) seconds[phase.name] = r.times.*phase.seconds;
  json stats = {
      {"format_version", kStatsFormatVersion},
      {"animpak", std::string(animpak_version)},
      {"commit", build_commit()},
      {"scene", r.checkpoint.scene_file.string()},
      {"seed", r.checkpoint.seed},
      {"device", r.device},
      {"driver", r.driver},
      {"elements", w.elements.size()},
      {"vertices", w.topology.vertex_count()},
      {"springs", w.topology.spring_other.size() / 2},
      {"envelope_triangles", w.topology.envelope_count()},
      {"iterations", r.result.last_good.iteration},
      {"stop_reason", r.checkpoint.stop_reason},
      {"secondary_since", r.result.last_good.secondary_since},
      {"seconds", seconds},
      {"final_growth", growth},
  };
  json rows = json::array();
  for (const ProgressSample& p : r.progress)
    rows.push_back({p.iteration, p.seconds, p.mean_growth, p.growing_share,
                    std::isfinite(p.max_gap) ? json(p.max_gap) : json(nullptr),  // no neighbour yet: JSON has no inf
                    p.overlapping, p.outside});
  // With the stop test's settings and the world's unit mesh density, the rows are a trace StopModel can be
  // replayed over (scripts/progress-trace.py; docs/cli.md, "Progress and the time left").
  const Params::Stop& stop = w.params.stop;
  stats["progress"] = {
      {"columns", kProgressColumns},
      {"rows", rows},
      {"unit_mesh_density", unit_mesh_density(w)},
      {"stall", {{"window", stop.stall_window}, {"growth", stop.stall_growth}, {"tests", stop.stall_tests}}},
      {"secondary", w.topology.has_secondary()}};
  if (!r.kernels.empty()) {
    json kernels = json::array();
    for (const KernelTime& k : r.kernels)
      kernels.push_back({{"name", k.name}, {"phase", k.phase}, {"seconds", k.seconds}, {"launches", k.launches}});
    stats["kernels"] = kernels;
  }
  set_quality(stats, w, r.quality);
  write_json(file, stats);
}

nlohmann::json read_stats_json(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(std::filesystem::symlink_status(file, ec)))
    return nlohmann::json(nlohmann::json::value_t::discarded);
  return nlohmann::json::parse(
      read_folder_file(file.parent_path(), file.filename(), "move it away; animpak writes its statistics there"),
      nullptr, false);
}

std::vector<ProgressSample> read_progress(const std::filesystem::path& file) {
  const nlohmann::json j = read_stats_json(file);
  std::vector<ProgressSample> out;
  if (j.is_discarded() || !j.is_object() || !j.contains("progress") || !j["progress"].is_object()) return out;
  const nlohmann::json& p = j["progress"];
  if (!p.contains("columns") || p["columns"] != nlohmann::json(kProgressColumns) || !p.contains("rows") ||
      !p["rows"].is_array())
    return out;
  for (const nlohmann::json& row : p["rows"]) {
    if (!row.is_array() || row.size() != kProgressColumns.size()) return {};
    for (std::size_t c = 0; c < row.size(); ++c)
      if (!row[c].is_number() && !(c == 4 && row[c].is_null())) return {};
    out.push_back({row[0].get<std::uint64_t>(), row[1].get<double>(), row[2].get<double>(), row[3].get<double>(),
                   row[4].is_null() ? std::numeric_limits<double>::infinity() : row[4].get<double>(),
                   row[5].get<std::int64_t>(), row[6].get<std::int64_t>()});
  }
  return out;
}

StillReference read_still_reference(const std::filesystem::path& folder) {
  const std::filesystem::path file = folder / "stats.json";
  const std::string what = "--still-reference " + folder.string() + ": ";
  const std::string remedy =
      "; pack the scene standing still first: animpak pack SCENE --still --out " + folder.string();
  if (!std::filesystem::exists(file)) throw InputError(what + "cannot read " + file.string() + remedy);
  const nlohmann::json stats = read_stats_json(file);
  if (stats.is_discarded() || !stats.is_object()) throw InputError(what + file.string() + " is not JSON" + remedy);
  const nlohmann::json* mean = nullptr;
  if (stats.contains("quality") && stats["quality"].is_object() && stats["quality"].contains("frames")) {
    const nlohmann::json& frames = stats["quality"]["frames"];
    if (frames.is_object() && frames.contains("coverage") && frames["coverage"].is_object() &&
        frames["coverage"].contains("mean"))
      mean = &frames["coverage"]["mean"];
  }
  if (mean == nullptr || !mean->is_number() || !(mean->get<double>() > 0.0))
    throw InputError(what + file.string() +
                     " has no frame coverage (quality.frames.coverage.mean): the packing was not rendered; render "
                     "it with animpak render " +
                     folder.string());
  return {folder, mean->get<double>()};
}

std::string add_still_reference(const std::filesystem::path& file, const StillReference& still,
                                const PackingQuality& quality) {
  nlohmann::json stats = read_stats_json(file);
  if (stats.is_discarded() || !stats.is_object()) return {};
  const QualitySummary q = summarize(quality.frames);
  const double lowest = q.coverage_min / still.coverage, mean = q.coverage_mean / still.coverage;
  stats["still_reference"] = {{"folder", std::filesystem::absolute(still.folder).lexically_normal().string()},
                              {"coverage", still.coverage},
                              {"lowest_over_still", lowest},
                              {"mean_over_still", mean}};
  write_json(file, stats);
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
  const nlohmann::json stats = read_stats_json(stats_file);
  if (stats.is_discarded() || !stats.is_object() || !stats.contains("animpak") || !stats["animpak"].is_string())
    return std::nullopt;
  int major = 0, minor = 0;
  if (std::sscanf(stats["animpak"].get<std::string>().c_str(), "%d.%d", &major, &minor) != 2) return std::nullopt;
  if (major > 0 || minor >= 8) return std::nullopt;
  return minor >= 4 ? curve_monotone : curve_linear;
}

std::optional<StillReference> stored_still_reference(const std::filesystem::path& file) {
  const nlohmann::json stats = read_stats_json(file);
  if (stats.is_discarded() || !stats.is_object() || !stats.contains("still_reference")) return std::nullopt;
  const nlohmann::json& ref = stats["still_reference"];
  if (!ref.is_object() || !ref.contains("coverage") || !ref["coverage"].is_number() || !ref.contains("folder") ||
      !ref["folder"].is_string() || !(ref["coverage"].get<double>() > 0.0))
    return std::nullopt;
  return StillReference{ref["folder"].get<std::string>(), ref["coverage"].get<double>()};
}

std::string update_stats_quality(const std::filesystem::path& file, const std::filesystem::path& written_to,
                                 const Checkpoint& checkpoint, const World& world, const PackingQuality& quality) {
  nlohmann::json stats = read_stats_json(file);
  // A stats.json that is not this packing's (not JSON, another tool's, another packing's counts) is kept
  // aside, not merged into: `report` would refuse the mix and send the user back here.
  const auto differs = [&](const char* key, const nlohmann::json& value) {
    return stats.contains(key) && stats[key] != value;
  };
  std::string note;
  std::error_code ec;
  const bool present = std::filesystem::exists(std::filesystem::symlink_status(file, ec));
  if (present && (stats.is_discarded() || !stats.is_object() || !stats.contains("format_version") ||
                  differs("elements", world.elements.size()) || differs("seed", checkpoint.seed) ||
                  differs("iterations", checkpoint.state.iteration))) {
    std::filesystem::path aside = file;
    aside.replace_filename("stats.foreign.json");
    std::filesystem::rename(file, aside);
    note = file.string() + " was not this packing's statistics; kept as " + aside.filename().string() +
           ", and a new one written";
    stats = nlohmann::json(nlohmann::json::value_t::discarded);
  }
  if (stats.is_discarded()) {
    // No stats.json of its own (copied without it, or kept aside above): what the checkpoint itself knows.
    stats = {{"format_version", kStatsFormatVersion},    {"animpak", std::string(animpak_version)},
             {"scene", checkpoint.scene_file.string()},  {"seed", checkpoint.seed},
             {"elements", world.elements.size()},        {"vertices", world.topology.vertex_count()},
             {"iterations", checkpoint.state.iteration}, {"stop_reason", checkpoint.stop_reason}};
  }
  set_quality(stats, world, quality);
  stats["rendered_by"] = build_commit();
  write_json(written_to, stats);
  return note;
}

}  // namespace animpak::cli
