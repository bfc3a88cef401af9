// What a packed folder's stats.json holds (docs/quality.md, "stats.json"), as types: one writer to the file's
// JSON and one reader from it (src/io/stats_file.cpp). `pack` and `render` write the file through it, and
// `report`, `sweep collect` and the tests read it through it (the command line's read_stats_json reads the
// file itself, without following a link).
//
// Two conventions keep the file's bytes what they are when a file is read and written again:
// - a number JSON cannot hold (an infinite kink, no wall ratio) is null in the file and NaN here, so a
//   `double` field is a number or NaN; an element name that is null in the file is empty here;
// - a std::optional field is one a file may lack (a later version added it, or one writer leaves it out):
//   absent in the file, nullopt here, and the writer leaves it out again.
// Top-level fields the model does not know, or cannot read (another version's shape), are kept as they are in
// `kept`, so that `render`, which rewrites the file, loses none of them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace animpak {

/// stats.json's `format_version`: raised when a field is renamed, moved or changes meaning, so that scripts
/// reading the file can tell; adding a field leaves it.
inline constexpr int kStatsFormatVersion = 1;

/// An element's share of its art outside the container at one time; `element` is empty when no element is.
struct StatsElementShare {
  std::string element;
  double share = 0.0;
  bool operator==(const StatsElementShare&) const = default;
};

/// A pair's overlap over the smaller art's area; `a` and `b` are empty when no pair overlaps.
struct StatsPairShare {
  std::string a, b;
  double share = 0.0;
  bool operator==(const StatsPairShare&) const = default;
};

/// One time's evenness (docs/quality.md, "Evenness"); the points between slices have none.
struct StatsFrameEvenness {
  double element_radius = 0.0;
  double wall_ratio = 0.0;  ///< NaN: none
  double empty_disc = 0.0;  ///< in element radii; NaN: none
  double empty_disc_radius = 0.0;
  std::vector<double> contact;  ///< H(r) at r = k · step · ρ
  bool operator==(const StatsFrameEvenness&) const = default;
};

/// One entry of `frames` or `between_slices`.
struct StatsFrame {
  double t = 0.0;
  double coverage = 0.0;
  double min_gap = 0.0;
  double mean_gap = 0.0;
  double channel_cv = 0.0;
  std::int64_t overlapping_pairs = 0;
  std::vector<StatsElementShare> elements_outside;
  std::vector<StatsPairShare> overlaps;
  StatsElementShare worst_outside;
  StatsPairShare worst_overlap;
  std::optional<StatsFrameEvenness> evenness;
  bool operator==(const StatsFrame&) const = default;
};

/// The evenness of a set of times summed up (`quality.frames` only).
struct StatsEvennessSummary {
  std::int64_t wall_ratio_times = 0;
  double wall_ratio_min = 0.0, wall_ratio_median = 0.0, wall_ratio_max = 0.0;        ///< NaN: none
  double empty_disc_median = 0.0, empty_disc_worst = 0.0, empty_disc_worst_t = 0.0;  ///< NaN: none
  double contact_step = 0.0;
  std::vector<double> contact_mean;
  bool operator==(const StatsEvennessSummary&) const = default;
};

/// `quality.frames` or `quality.between_slices`: the measured times summed up (QualitySummary's fields).
struct StatsSummary {
  std::int64_t times = 0;
  std::int64_t element_frames = 0;
  std::int64_t element_frames_outside = 0;
  StatsElementShare worst_outside;
  double worst_outside_t = 0.0;
  std::int64_t overlapping_pair_frames = 0;
  std::int64_t overlapping_pairs = 0;
  StatsPairShare worst_overlap;
  double worst_overlap_t = 0.0;
  double coverage_min = 0.0, coverage_max = 0.0, coverage_mean = 0.0;
  double min_gap = 0.0;
  double channel_cv_mean = 0.0, channel_cv_max = 0.0;
  std::optional<StatsEvennessSummary> evenness;
  bool operator==(const StatsSummary&) const = default;
};

struct StatsQuality {
  double share_threshold = 0.0;
  StatsSummary frames, between_slices;
  bool operator==(const StatsQuality&) const = default;
};

/// docs/quality.md, "Motion".
struct StatsMotion {
  double acceleration_median = 0.0, acceleration_p99 = 0.0;
  std::optional<std::vector<double>> frame_peak;  ///< per frame; NaN where a frame has none
  double kink = 0.0;                              ///< NaN: infinite (straight lines between slices)
  std::optional<double> slice_ratio;              ///< NaN: no frame lies away from a slice
  struct Size {
    std::string element;
    double ratio = 0.0;
    bool operator==(const Size&) const = default;
  };
  std::optional<std::vector<Size>> size_over_script;
  struct Movement {
    std::string element;
    bool guided = false;
    double detour = 0.0, dip = 0.0, path_length = 0.0;
    bool operator==(const Movement&) const = default;
  };
  std::optional<std::vector<Movement>> movement;
  bool operator==(const StatsMotion&) const = default;
};

/// One statistics check of the packing (ProgressSample's fields, in kStatsProgressColumns' order).
struct StatsProgressRow {
  std::uint64_t iteration = 0;
  double seconds = 0.0, mean_growth = 0.0, growing_share = 0.0;
  double max_gap = 0.0;  ///< NaN: no neighbour yet
  std::int64_t overlapping_vertices = 0, outside_vertices = 0;
  bool operator==(const StatsProgressRow&) const = default;
};

/// The columns of `progress.rows`.
inline const std::vector<std::string> kStatsProgressColumns = {
    "iteration", "seconds", "mean_growth", "growing_share", "max_gap", "overlapping_vertices", "outside_vertices"};

/// `progress`: every statistics check, and what replays the stop test over them (docs/cli.md, "Progress and the
/// time left").
struct StatsProgress {
  std::vector<std::string> columns = kStatsProgressColumns;
  std::vector<StatsProgressRow> rows;
  std::optional<double> unit_mesh_density;
  struct Stall {
    std::int64_t window = 0;
    double growth = 0.0;
    std::int64_t tests = 0;
    bool operator==(const Stall&) const = default;
  };
  std::optional<Stall> stall;
  std::optional<bool> secondary;
  bool operator==(const StatsProgress&) const = default;
};

struct StatsGrowth {
  std::string element;
  double min = 0.0, mean = 0.0, max = 0.0;
  bool operator==(const StatsGrowth&) const = default;
};

struct StatsKernel {
  std::string name, phase;
  double seconds = 0.0;
  std::uint64_t launches = 0;
  bool operator==(const StatsKernel&) const = default;
};

/// One level of a coarse-to-fine packing (docs/parameters.md, "Coarse to fine"), in the order they ran: its
/// slices per element, and this run's iterations and simulation seconds at it (a resumed run: its own).
struct StatsLevel {
  std::int64_t slices = 0;
  std::uint64_t iterations = 0;
  double seconds = 0.0;
  bool operator==(const StatsLevel&) const = default;
};

/// `seconds`: the set-up, the simulation, and each phase by its name (phase_fields).
struct StatsSeconds {
  double setup = 0.0, simulation = 0.0;
  std::map<std::string, double> phases;
  bool operator==(const StatsSeconds&) const = default;
};

/// `still_reference` (docs/quality.md, "Still reference").
struct StatsStillReference {
  std::string folder;
  double coverage = 0.0, lowest_over_still = 0.0, mean_over_still = 0.0;
  bool operator==(const StatsStillReference&) const = default;
};

/// The whole file. `render` without a stats.json of the packing's own writes only the fields the
/// checkpoint knows (format_version to stop_reason, not the optional ones) and the quality.
struct Stats {
  std::int64_t format_version = kStatsFormatVersion;
  std::string animpak;  ///< the version that wrote it
  std::optional<std::string> commit;
  std::string scene;
  std::uint64_t seed = 0;
  std::optional<std::string> device, driver;
  std::uint64_t elements = 0;
  std::int64_t vertices = 0;
  std::optional<std::int64_t> springs, envelope_triangles;
  std::uint64_t iterations = 0;
  std::string stop_reason;
  std::optional<std::uint64_t> secondary_since;
  std::optional<StatsSeconds> seconds;
  std::optional<std::vector<StatsGrowth>> final_growth;
  std::optional<StatsProgress> progress;
  std::optional<std::vector<StatsKernel>> kernels;
  /// The level the state is at: the coarse level's slices per element, or absent at the scene's own.
  std::optional<std::int64_t> level_slices;
  std::optional<std::vector<StatsLevel>> levels;  ///< the levels this run stepped, when it stepped two
  std::optional<std::vector<StatsFrame>> frames, between_slices;
  std::optional<StatsQuality> quality;
  std::optional<StatsMotion> motion;
  std::optional<StatsStillReference> still_reference;
  std::optional<std::string> rendered_by;
  /// Top-level fields this model does not know or cannot read, each as its JSON text, written back as they are.
  std::map<std::string, std::string> kept;
  bool operator==(const Stats&) const = default;
};

/// The file's text: the JSON object, keys sorted, indented by two, and a newline.
std::string stats_json_text(const Stats& stats);

/// Reads the text of a stats.json. InputError naming `file` when it is not JSON, not an object, or lacks one
/// of the fields every stats.json has (format_version, animpak, scene, seed, elements, vertices, iterations,
/// stop_reason).
Stats parse_stats(const std::string& text, const std::filesystem::path& file);

/// Writes `stats` to `file` through a checked temporary file and a rename (write_file_atomically), so that a
/// failed write never loses the statistics already there.
void write_stats_file(const std::filesystem::path& file, const Stats& stats);

}  // namespace animpak
