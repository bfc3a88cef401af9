// stats.json's writer and reader (animpak/stats.hpp; docs/quality.md, "stats.json"). nlohmann::json keeps an
// object's keys sorted, so the text is the same whichever order the fields are set in.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

#include "animpak/error.hpp"
#include "animpak/file_io.hpp"
#include "animpak/stats.hpp"

namespace animpak {
namespace {

using nlohmann::json;

// A field of the wrong shape: the section that holds it is kept as it is (Stats::kept).
struct StatsShapeError {
  std::string key;
};

// --- writing -------------------------------------------------------------------------------------------------

// NaN (none) is written as null, as nlohmann::json writes any number JSON cannot hold.
json number_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }
json name_or_null(const std::string& name) { return name.empty() ? json(nullptr) : json(name); }

json numbers_or_null(const std::vector<double>& values) {
  json out = json::array();
  for (const double v : values) out.push_back(number_or_null(v));
  return out;
}

json element_share_json(const StatsElementShare& e) {
  return {{"element", name_or_null(e.element)}, {"share", e.share}};
}

json pair_share_json(const StatsPairShare& p) {
  return {{"a", name_or_null(p.a)}, {"b", name_or_null(p.b)}, {"share", p.share}};
}

json frame_json(const StatsFrame& f) {
  json elements_outside = json::array(), overlaps = json::array();
  for (const StatsElementShare& e : f.elements_outside) elements_outside.push_back(element_share_json(e));
  for (const StatsPairShare& p : f.overlaps) overlaps.push_back(pair_share_json(p));
  json out = {{"t", number_or_null(f.t)},
              {"coverage", number_or_null(f.coverage)},
              {"min_gap", number_or_null(f.min_gap)},
              {"mean_gap", number_or_null(f.mean_gap)},
              {"channel_cv", number_or_null(f.channel_cv)},
              {"overlapping_pairs", f.overlapping_pairs},
              {"elements_outside", elements_outside},
              {"overlaps", overlaps},
              {"worst_outside", element_share_json(f.worst_outside)},
              {"worst_overlap", pair_share_json(f.worst_overlap)}};
  if (const auto& e = f.evenness) {
    out["element_radius"] = number_or_null(e->element_radius);
    out["wall_ratio"] = number_or_null(e->wall_ratio);
    out["empty_disc"] = number_or_null(e->empty_disc);
    out["empty_disc_radius"] = number_or_null(e->empty_disc_radius);
    out["contact"] = numbers_or_null(e->contact);
  }
  return out;
}

json frames_json(const std::vector<StatsFrame>& frames) {
  json out = json::array();
  for (const StatsFrame& f : frames) out.push_back(frame_json(f));
  return out;
}

json summary_json(const StatsSummary& q) {
  json worst_outside = element_share_json(q.worst_outside), worst_overlap = pair_share_json(q.worst_overlap);
  worst_outside["t"] = number_or_null(q.worst_outside_t);
  worst_overlap["t"] = number_or_null(q.worst_overlap_t);
  json out = {{"times", q.times},
              {"element_frames", q.element_frames},
              {"element_frames_outside", q.element_frames_outside},
              {"worst_outside", worst_outside},
              {"overlapping_pair_frames", q.overlapping_pair_frames},
              {"overlapping_pairs", q.overlapping_pairs},
              {"worst_overlap", worst_overlap},
              {"coverage",
               {{"min", number_or_null(q.coverage_min)},
                {"max", number_or_null(q.coverage_max)},
                {"mean", number_or_null(q.coverage_mean)}}},
              {"min_gap", number_or_null(q.min_gap)},
              {"channel_cv", {{"mean", number_or_null(q.channel_cv_mean)}, {"max", number_or_null(q.channel_cv_max)}}}};
  if (const auto& e = q.evenness) {
    out["wall_ratio"] = {{"times", e->wall_ratio_times},
                         {"min", number_or_null(e->wall_ratio_min)},
                         {"median", number_or_null(e->wall_ratio_median)},
                         {"max", number_or_null(e->wall_ratio_max)}};
    out["empty_disc"] = {{"median", number_or_null(e->empty_disc_median)},
                         {"worst", number_or_null(e->empty_disc_worst)},
                         {"worst_t", number_or_null(e->empty_disc_worst_t)}};
    out["contact"] = {{"step", number_or_null(e->contact_step)}, {"mean", numbers_or_null(e->contact_mean)}};
  }
  return out;
}

json motion_json(const StatsMotion& m) {
  json acceleration = {{"median", number_or_null(m.acceleration_median)}, {"p99", number_or_null(m.acceleration_p99)}};
  if (m.frame_peak) acceleration["frame_peak"] = numbers_or_null(*m.frame_peak);
  json out = {{"acceleration", acceleration}, {"kink", number_or_null(m.kink)}};
  if (m.slice_ratio) out["slice_ratio"] = number_or_null(*m.slice_ratio);
  if (m.size_over_script) {
    json sizes = json::array();
    for (const StatsMotion::Size& s : *m.size_over_script)
      sizes.push_back({{"element", s.element}, {"ratio", number_or_null(s.ratio)}});
    out["size_over_script"] = sizes;
  }
  if (m.movement) {
    json moves = json::array();
    for (const StatsMotion::Movement& e : *m.movement)
      moves.push_back({{"element", e.element},
                       {"guided", e.guided},
                       {"detour", number_or_null(e.detour)},
                       {"dip", number_or_null(e.dip)},
                       {"path_length", number_or_null(e.path_length)}});
    out["movement"] = moves;
  }
  return out;
}

json progress_json(const StatsProgress& p) {
  json rows = json::array();
  for (const StatsProgressRow& r : p.rows)
    rows.push_back({r.iteration, number_or_null(r.seconds), number_or_null(r.mean_growth),
                    number_or_null(r.growing_share), number_or_null(r.max_gap), r.overlapping_vertices,
                    r.outside_vertices});
  json out = {{"columns", p.columns}, {"rows", rows}};
  if (p.unit_mesh_density) out["unit_mesh_density"] = number_or_null(*p.unit_mesh_density);
  if (p.stall)
    out["stall"] = {
        {"window", p.stall->window}, {"growth", number_or_null(p.stall->growth)}, {"tests", p.stall->tests}};
  if (p.secondary) out["secondary"] = *p.secondary;
  return out;
}

json stats_json(const Stats& s) {
  json out = {{"format_version", s.format_version},
              {"animpak", s.animpak},
              {"scene", s.scene},
              {"seed", s.seed},
              {"elements", s.elements},
              {"vertices", s.vertices},
              {"iterations", s.iterations},
              {"stop_reason", s.stop_reason}};
  if (s.commit) out["commit"] = *s.commit;
  if (s.device) out["device"] = *s.device;
  if (s.driver) out["driver"] = *s.driver;
  if (s.springs) out["springs"] = *s.springs;
  if (s.envelope_triangles) out["envelope_triangles"] = *s.envelope_triangles;
  if (s.secondary_since) out["secondary_since"] = *s.secondary_since;
  if (s.seconds) {
    json seconds = {{"setup", number_or_null(s.seconds->setup)}, {"simulation", number_or_null(s.seconds->simulation)}};
    for (const auto& [name, value] : s.seconds->phases) seconds[name] = number_or_null(value);
    out["seconds"] = seconds;
  }
  if (s.final_growth) {
    json growth = json::array();
    for (const StatsGrowth& g : *s.final_growth)
      growth.push_back({{"element", g.element},
                        {"min", number_or_null(g.min)},
                        {"mean", number_or_null(g.mean)},
                        {"max", number_or_null(g.max)}});
    out["final_growth"] = growth;
  }
  if (s.progress) out["progress"] = progress_json(*s.progress);
  if (s.kernels) {
    json kernels = json::array();
    for (const StatsKernel& k : *s.kernels)
      kernels.push_back(
          {{"name", k.name}, {"phase", k.phase}, {"seconds", number_or_null(k.seconds)}, {"launches", k.launches}});
    out["kernels"] = kernels;
  }
  if (s.level_slices) out["level_slices"] = *s.level_slices;
  if (s.levels) {
    json levels = json::array();
    for (const StatsLevel& l : *s.levels)
      levels.push_back({{"slices", l.slices}, {"iterations", l.iterations}, {"seconds", number_or_null(l.seconds)}});
    out["levels"] = levels;
  }
  if (s.frames) out["frames"] = frames_json(*s.frames);
  if (s.between_slices) out["between_slices"] = frames_json(*s.between_slices);
  if (s.quality)
    out["quality"] = {{"share_threshold", number_or_null(s.quality->share_threshold)},
                      {"frames", summary_json(s.quality->frames)},
                      {"between_slices", summary_json(s.quality->between_slices)}};
  if (s.motion) out["motion"] = motion_json(*s.motion);
  if (const auto& r = s.still_reference)
    out["still_reference"] = {{"folder", r->folder},
                              {"coverage", number_or_null(r->coverage)},
                              {"lowest_over_still", number_or_null(r->lowest_over_still)},
                              {"mean_over_still", number_or_null(r->mean_over_still)}};
  if (s.rendered_by) out["rendered_by"] = *s.rendered_by;
  for (const auto& [key, text] : s.kept) out[key] = json::parse(text);
  return out;
}

// --- reading -------------------------------------------------------------------------------------------------

const json& field(const json& object, const char* key) {
  if (!object.is_object() || !object.contains(key)) throw StatsShapeError{key};
  return object[key];
}

// A number, or null (NaN).
double number(const json& value, const char* key) {
  if (value.is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (!value.is_number()) throw StatsShapeError{key};
  return value.get<double>();
}
double number_in(const json& object, const char* key) { return number(field(object, key), key); }

template <class Int>
Int whole(const json& object, const char* key) {
  const json& value = field(object, key);
  if (!value.is_number_integer()) throw StatsShapeError{key};
  return value.get<Int>();
}

std::string text(const json& object, const char* key) {
  const json& value = field(object, key);
  if (!value.is_string()) throw StatsShapeError{key};
  return value.get<std::string>();
}

std::string name_of(const json& object, const char* key) {
  const json& value = field(object, key);
  if (value.is_null()) return {};
  if (!value.is_string()) throw StatsShapeError{key};
  return value.get<std::string>();
}

bool flag(const json& object, const char* key) {
  const json& value = field(object, key);
  if (!value.is_boolean()) throw StatsShapeError{key};
  return value.get<bool>();
}

const json& array(const json& object, const char* key) {
  const json& value = field(object, key);
  if (!value.is_array()) throw StatsShapeError{key};
  return value;
}

std::vector<double> numbers(const json& object, const char* key) {
  std::vector<double> out;
  for (const json& v : array(object, key)) out.push_back(number(v, key));
  return out;
}

StatsElementShare read_element_share(const json& j) { return {name_of(j, "element"), number_in(j, "share")}; }
StatsPairShare read_pair_share(const json& j) { return {name_of(j, "a"), name_of(j, "b"), number_in(j, "share")}; }

StatsFrame read_frame(const json& j) {
  StatsFrame f;
  f.t = number_in(j, "t");
  f.coverage = number_in(j, "coverage");
  f.min_gap = number_in(j, "min_gap");
  f.mean_gap = number_in(j, "mean_gap");
  f.channel_cv = number_in(j, "channel_cv");
  f.overlapping_pairs = whole<std::int64_t>(j, "overlapping_pairs");
  for (const json& e : array(j, "elements_outside")) f.elements_outside.push_back(read_element_share(e));
  for (const json& p : array(j, "overlaps")) f.overlaps.push_back(read_pair_share(p));
  f.worst_outside = read_element_share(field(j, "worst_outside"));
  f.worst_overlap = read_pair_share(field(j, "worst_overlap"));
  if (j.contains("element_radius"))
    f.evenness =
        StatsFrameEvenness{number_in(j, "element_radius"), number_in(j, "wall_ratio"), number_in(j, "empty_disc"),
                           number_in(j, "empty_disc_radius"), numbers(j, "contact")};
  return f;
}

std::vector<StatsFrame> read_frames(const json& j) {
  if (!j.is_array()) throw StatsShapeError{"frames"};
  std::vector<StatsFrame> out;
  for (const json& f : j) out.push_back(read_frame(f));
  return out;
}

StatsSummary read_summary(const json& j) {
  StatsSummary q;
  q.times = whole<std::int64_t>(j, "times");
  q.element_frames = whole<std::int64_t>(j, "element_frames");
  q.element_frames_outside = whole<std::int64_t>(j, "element_frames_outside");
  q.worst_outside = read_element_share(field(j, "worst_outside"));
  q.worst_outside_t = number_in(field(j, "worst_outside"), "t");
  q.overlapping_pair_frames = whole<std::int64_t>(j, "overlapping_pair_frames");
  q.overlapping_pairs = whole<std::int64_t>(j, "overlapping_pairs");
  q.worst_overlap = read_pair_share(field(j, "worst_overlap"));
  q.worst_overlap_t = number_in(field(j, "worst_overlap"), "t");
  const json& coverage = field(j, "coverage");
  q.coverage_min = number_in(coverage, "min");
  q.coverage_max = number_in(coverage, "max");
  q.coverage_mean = number_in(coverage, "mean");
  q.min_gap = number_in(j, "min_gap");
  q.channel_cv_mean = number_in(field(j, "channel_cv"), "mean");
  q.channel_cv_max = number_in(field(j, "channel_cv"), "max");
  if (j.contains("wall_ratio")) {
    StatsEvennessSummary e;
    const json &wall = field(j, "wall_ratio"), &disc = field(j, "empty_disc"), &contact = field(j, "contact");
    e.wall_ratio_times = whole<std::int64_t>(wall, "times");
    e.wall_ratio_min = number_in(wall, "min");
    e.wall_ratio_median = number_in(wall, "median");
    e.wall_ratio_max = number_in(wall, "max");
    e.empty_disc_median = number_in(disc, "median");
    e.empty_disc_worst = number_in(disc, "worst");
    e.empty_disc_worst_t = number_in(disc, "worst_t");
    e.contact_step = number_in(contact, "step");
    e.contact_mean = numbers(contact, "mean");
    q.evenness = e;
  }
  return q;
}

StatsMotion read_motion(const json& j) {
  StatsMotion m;
  const json& acceleration = field(j, "acceleration");
  m.acceleration_median = number_in(acceleration, "median");
  m.acceleration_p99 = number_in(acceleration, "p99");
  if (acceleration.contains("frame_peak")) m.frame_peak = numbers(acceleration, "frame_peak");
  m.kink = number_in(j, "kink");
  if (j.contains("slice_ratio")) m.slice_ratio = number_in(j, "slice_ratio");
  if (j.contains("size_over_script")) {
    m.size_over_script.emplace();
    for (const json& s : array(j, "size_over_script"))
      m.size_over_script->push_back({text(s, "element"), number_in(s, "ratio")});
  }
  if (j.contains("movement")) {
    m.movement.emplace();
    for (const json& e : array(j, "movement"))
      m.movement->push_back({text(e, "element"), flag(e, "guided"), number_in(e, "detour"), number_in(e, "dip"),
                             number_in(e, "path_length")});
  }
  return m;
}

StatsProgress read_progress_section(const json& j) {
  StatsProgress p;
  p.columns.clear();
  for (const json& c : array(j, "columns")) {
    if (!c.is_string()) throw StatsShapeError{"columns"};
    p.columns.push_back(c.get<std::string>());
  }
  // Rows of other columns than these are another version's: the section is kept as it is.
  if (p.columns != kStatsProgressColumns) throw StatsShapeError{"columns"};
  for (const json& row : array(j, "rows")) {
    if (!row.is_array() || row.size() != kStatsProgressColumns.size() || !row[0].is_number_integer() ||
        !row[5].is_number_integer() || !row[6].is_number_integer())
      throw StatsShapeError{"rows"};
    p.rows.push_back({row[0].get<std::uint64_t>(), number(row[1], "rows"), number(row[2], "rows"),
                      number(row[3], "rows"), number(row[4], "rows"), row[5].get<std::int64_t>(),
                      row[6].get<std::int64_t>()});
  }
  if (j.contains("unit_mesh_density")) p.unit_mesh_density = number_in(j, "unit_mesh_density");
  if (j.contains("stall")) {
    const json& stall = field(j, "stall");
    p.stall = StatsProgress::Stall{whole<std::int64_t>(stall, "window"), number_in(stall, "growth"),
                                   whole<std::int64_t>(stall, "tests")};
  }
  if (j.contains("secondary")) p.secondary = flag(j, "secondary");
  return p;
}

StatsSeconds read_seconds(const json& j) {
  StatsSeconds s;
  s.setup = number_in(j, "setup");
  s.simulation = number_in(j, "simulation");
  for (const auto& [name, value] : j.items())
    if (name != "setup" && name != "simulation") s.phases[name] = number(value, "seconds");
  return s;
}

std::vector<StatsGrowth> read_growth(const json& j) {
  std::vector<StatsGrowth> out;
  if (!j.is_array()) throw StatsShapeError{"final_growth"};
  for (const json& g : j)
    out.push_back({text(g, "element"), number_in(g, "min"), number_in(g, "mean"), number_in(g, "max")});
  return out;
}

std::vector<StatsKernel> read_kernels(const json& j) {
  std::vector<StatsKernel> out;
  if (!j.is_array()) throw StatsShapeError{"kernels"};
  for (const json& k : j)
    out.push_back({text(k, "name"), text(k, "phase"), number_in(k, "seconds"), whole<std::uint64_t>(k, "launches")});
  return out;
}

std::vector<StatsLevel> read_levels(const json& j) {
  std::vector<StatsLevel> out;
  if (!j.is_array()) throw StatsShapeError{"levels"};
  for (const json& l : j)
    out.push_back({whole<std::int64_t>(l, "slices"), whole<std::uint64_t>(l, "iterations"), number_in(l, "seconds")});
  return out;
}

StatsQuality read_quality(const json& j) {
  return {number_in(j, "share_threshold"), read_summary(field(j, "frames")), read_summary(field(j, "between_slices"))};
}

StatsStillReference read_still(const json& j) {
  return {text(j, "folder"), number_in(j, "coverage"), number_in(j, "lowest_over_still"),
          number_in(j, "mean_over_still")};
}

// The optional top-level fields: each read into the model, or kept as it is when its shape is not this
// model's.
template <class T, class Read>
void optional_field(const json& root, const char* key, std::optional<T>& out, Stats& stats, Read read) {
  if (!root.contains(key)) return;
  try {
    out = read(root[key]);
  } catch (const StatsShapeError&) {
    stats.kept[key] = root[key].dump();
  }
}

}  // namespace

std::string stats_json_text(const Stats& stats) { return stats_json(stats).dump(2) + "\n"; }

void write_stats_file(const std::filesystem::path& file, const Stats& stats) {
  write_file_atomically(file, stats_json_text(stats));
}

Stats parse_stats(const std::string& source, const std::filesystem::path& file) {
  const json root = json::parse(source, nullptr, false);
  if (root.is_discarded() || !root.is_object())
    throw InputError(file.string() + ": not a JSON object; move it away, and animpak writes its statistics there");
  Stats s;
  try {
    s.format_version = whole<std::int64_t>(root, "format_version");
    s.animpak = text(root, "animpak");
    s.scene = text(root, "scene");
    s.seed = whole<std::uint64_t>(root, "seed");
    s.elements = whole<std::uint64_t>(root, "elements");
    s.vertices = whole<std::int64_t>(root, "vertices");
    s.iterations = whole<std::uint64_t>(root, "iterations");
    s.stop_reason = text(root, "stop_reason");
  } catch (const StatsShapeError& e) {
    throw InputError(file.string() + ": \"" + e.key +
                     "\" is missing or not what animpak writes there; it is not a packing's stats.json: move it "
                     "away, or render the folder again, which writes a new one");
  }
  const auto as_text = [](const json& j) {
    if (!j.is_string()) throw StatsShapeError{};
    return j.get<std::string>();
  };
  const auto as_whole = [](const json& j) {
    if (!j.is_number_integer()) throw StatsShapeError{};
    return j.get<std::int64_t>();
  };
  optional_field(root, "commit", s.commit, s, as_text);
  optional_field(root, "device", s.device, s, as_text);
  optional_field(root, "driver", s.driver, s, as_text);
  optional_field(root, "rendered_by", s.rendered_by, s, as_text);
  optional_field(root, "springs", s.springs, s, as_whole);
  optional_field(root, "envelope_triangles", s.envelope_triangles, s, as_whole);
  optional_field(root, "secondary_since", s.secondary_since, s, [](const json& j) {
    if (!j.is_number_integer()) throw StatsShapeError{};
    return j.get<std::uint64_t>();
  });
  optional_field(root, "seconds", s.seconds, s, read_seconds);
  optional_field(root, "final_growth", s.final_growth, s, read_growth);
  optional_field(root, "progress", s.progress, s, read_progress_section);
  optional_field(root, "kernels", s.kernels, s, read_kernels);
  optional_field(root, "level_slices", s.level_slices, s, as_whole);
  optional_field(root, "levels", s.levels, s, read_levels);
  optional_field(root, "frames", s.frames, s, read_frames);
  optional_field(root, "between_slices", s.between_slices, s, read_frames);
  optional_field(root, "quality", s.quality, s, read_quality);
  optional_field(root, "motion", s.motion, s, read_motion);
  optional_field(root, "still_reference", s.still_reference, s, read_still);
  static const char* const known[] = {
      "format_version",  "animpak", "scene",           "seed",         "elements",    "vertices", "iterations",
      "stop_reason",     "commit",  "device",          "driver",       "rendered_by", "springs",  "envelope_triangles",
      "secondary_since", "seconds", "final_growth",    "progress",     "kernels",     "frames",   "between_slices",
      "quality",         "motion",  "still_reference", "level_slices", "levels"};
  for (const auto& [key, value] : root.items())
    if (std::find(std::begin(known), std::end(known), key) == std::end(known)) s.kept[key] = value.dump();
  return s;
}

}  // namespace animpak
