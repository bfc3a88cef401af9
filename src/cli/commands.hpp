// The subcommands of `animpak` and `animpak-solve`. Each returns an exit code; errors are thrown and mapped
// in run().
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "animpak/bench.hpp"   // BenchRow, for the bench plotter
#include "animpak/render.hpp"  // PackingQuality, plain structs: declaring it links nothing from animpak_render

namespace animpak::cli {

/// The commit this program was built from, read at build time (cmake/Commit.cmake): an abbreviated hash,
/// with "-dirty" when tracked files had uncommitted changes, or "unknown" outside a git checkout.
std::string_view build_commit();

// inspect, check and render draw, so only `animpak` defines them (inspect.cpp, check.cpp, render_commands.cpp).
struct InspectOptions {
  std::filesystem::path file;                ///< a scene (.json) or one art file (.svg, .path)
  std::optional<std::filesystem::path> out;  ///< folder for the PNG pictures
  bool json = false;                         ///< print counts as JSON on stdout
  std::optional<int> slices;                 ///< override n_s
  int picture_size = 512;
};

int inspect(const InspectOptions& options);

struct CheckOptions {
  std::filesystem::path file;                ///< one art file (.svg, .path), or a scene (.json): its container
  bool container = false;                    ///< check the art file as a container
  std::optional<int> outline;                ///< as a container: the outline's path (container.outline)
  std::vector<int> holes;                    ///< as a container: the holes' paths (container.holes); none: default
  std::vector<std::string> exclude;          ///< SVG elements to leave out, as an element's `exclude` does
  std::optional<std::filesystem::path> png;  ///< draw the art as imported into this PNG
  int size = 512;                            ///< the PNG's longer side in pixels
  bool json = false;                         ///< print the report as JSON on stdout
};

/// The preflight before packing one art file: what is imported, every warning; 0 when it can be packed. A
/// container (--container, or a scene's) reports its outline, holes, area and bounds instead of an element.
int check(const CheckOptions& options);

struct FrameOptions {
  int frames = 100;
  int size = 512;
  double fps = 25.0;
  std::vector<std::string> formats{"png", "gif"};
  std::string background = "white";      ///< white, none (transparent) or #rrggbb
  std::string container = "outline";     ///< outline, fill (its art's paint) or none
  bool no_container = false;             ///< --no-container: container none
  int precision = 2;                     ///< lottie, svg-anim: decimals of a pixel
  double curve_tolerance = 0.05;         ///< lottie, svg-anim: pixels between the Béziers and the polylines
  std::string interpolation = "linear";  ///< lottie, svg-anim: linear or hold
};

struct PackOptions {
  std::filesystem::path scene;
  std::filesystem::path out;
  std::optional<std::filesystem::path> resume;  ///< continue from DIR/state.bin
  std::optional<std::uint64_t> seed;
  std::optional<std::uint64_t> max_iterations;
  std::string device;              ///< empty: the default rule (first GPU, else PoCL, else the reference)
  std::string grid_sort = "auto";  ///< auto, host or device (GridSort)
  bool force = false;              ///< overwrite the packing already in `out`
  bool still = false;              ///< pack the scene's still reference (still_scene_text)
  /// stop at the coarse level's stop and render it (docs/parameters.md, "Coarse to fine"); `--resume` without
  /// it goes on to the scene's slices
  bool preview = false;
  /// a folder `pack --still` wrote: stats.json carries its coverage beside this packing's
  std::optional<std::filesystem::path> still_reference;
  bool verbose = false;              ///< the progress line with overlaps, outside and the g range
  bool profile = false;              ///< print the time per phase and per kernel at the end (profile_text)
  double checkpoint_seconds = 60.0;  ///< state.bin written at most this often during the run (0: every check)
  std::string program = "animpak";   ///< for the resume command printed after Ctrl-C
};

/// Writes, into the render's scratch folder, the files that belong with the frames just drawn (stats.json
/// with their metrics, contact.png): they are swapped in with the frames, or not at all.
using BesideFrames = std::function<void(const PackingQuality& quality, const std::filesystem::path& scratch)>;

/// What a render left in its folder: the quality of its frames and between slices, and the rendered files
/// of the run before that it removed (relative to the folder; install_rendered).
struct Rendered {
  PackingQuality quality;
  std::vector<std::filesystem::path> removed;
};

/// Called by pack after state.bin is written (unless interrupted) with the final world and the output folder;
/// returns the quality of the frames and between slices for stats.json. Empty: pack writes no frames (--no-render).
using FrameRenderer =
    std::function<Rendered(const World& world, const std::filesystem::path& dir, const BesideFrames& beside)>;

int pack(const PackOptions& options, const FrameRenderer& render_frames);

/// What every run of a sweep passes to its `pack`, besides its scene and folder (docs/sweeps.md).
struct SweepPackOptions {
  std::optional<std::uint64_t> max_iterations;
  std::string device;              ///< empty: pack's default rule
  std::string grid_sort = "auto";  ///< auto, host or device
  double checkpoint_seconds = 60.0;
  FrameOptions frames;
};

struct SweepOptions {
  std::filesystem::path scene;
  std::filesystem::path out;
  std::string seeds;                         ///< "1-8", "1,3,5-7"; empty: the scene's seed
  std::vector<std::string> sets;             ///< "NAME=V1,V2,...": a parameter, slices, count or ELEMENT.count
  std::optional<int> jobs;                   ///< packs at a time; unset: one per two cores (default_sweep_jobs)
  bool plan_only = false;                    ///< write the plan and the cluster files, run nothing
  std::string submit;                        ///< "slurm": submit the plan with sbatch (implies plan_only)
  int cpus_per_task = 2;                     ///< the CPUs each cluster task asks for
  std::string node_animpak;                  ///< the animpak the cluster files run; empty: this one's absolute path
  std::string k8s_image;                     ///< the Indexed Job's image; empty: animpak:VERSION
  std::string k8s_claim = "animpak-sweeps";  ///< the PersistentVolumeClaim that holds DIR
  SweepPackOptions pack;
};

/// Plans a sweep of seeds and scene settings into DIR/plan.json and runs it (or only writes the cluster files).
int sweep(const SweepOptions& options);

struct SweepTaskOptions {
  std::filesystem::path dir;
  std::optional<long long> index;  ///< unset: SLURM_ARRAY_TASK_ID or JOB_COMPLETION_INDEX
};

/// Runs one run of a sweep's plan (a cluster's array task).
int sweep_task(const SweepTaskOptions& options);

struct SweepCollectOptions {
  std::filesystem::path dir;
};

/// Writes DIR/sweep.html and DIR/runs.csv from the runs of DIR/plan.json.
int sweep_collect(const SweepCollectOptions& options);

/// Packs a local sweep runs at a time by default: one per two cores, at least one.
int default_sweep_jobs();

struct DevicesOptions {
  bool verbose = false;  ///< print every device's kernel build log
};

/// Lists every OpenCL platform and device and whether animpak's kernels build on it.
int devices(const DevicesOptions& options);

struct RenderOptions {
  std::filesystem::path dir;                   ///< a folder `animpak pack` wrote
  std::optional<std::filesystem::path> scene;  ///< the scene and its art elsewhere than DIR/input/
  bool force = false;                          ///< render with a `scene` or art that differs from the packed one
  FrameOptions frames;
  bool contact_plot = false;  ///< also draw the frames' contact functions into DIR/contact.png
  std::optional<std::filesystem::path> still_reference;  ///< as PackOptions::still_reference
};

int render(const RenderOptions& options);

struct ReportOptions {
  std::filesystem::path dir;                 ///< a folder `animpak pack` wrote, rendered
  std::optional<std::filesystem::path> out;  ///< default DIR/report.html
};

/// Writes the packing in `dir` as one self-contained HTML page (animpak/report.hpp).
int report(const ReportOptions& options);

struct TrajectoryOptions {
  std::vector<std::filesystem::path> dirs;   ///< folders `animpak pack` wrote, all of one container
  std::string element;                       ///< the element's name in each of them
  int samples = 400;                         ///< times along the loop, evenly spaced
  std::optional<std::filesystem::path> out;  ///< default dirs[0]/trajectory.svg
};

/// Draws element `element`'s path through the loop in every folder into one SVG (animpak/report.hpp),
/// and prints each path's length and acceleration.
int trajectory(const TrajectoryOptions& options);

struct BenchOptions {
  std::vector<std::string> devices{"reference"};
  std::vector<int> sizes{10000, 50000, 100000};  ///< target vertex counts of the synthetic worlds
  int steps = 20;                                ///< timed steps per world
  int warmup = 3;                                ///< untimed steps first (caches, allocations)
  /// rounds per world: every device is timed once per round, in turn, and each row reports the median
  /// round (with the fastest and slowest), so that a load that comes and goes hits all devices alike
  int repeat = 1;
  int slices = 20;  ///< n_s of the synthetic worlds
  /// constant, dense or both (docs/benchmark.md); unset: constant, or none when `scenes` or `states` is given
  std::optional<std::string> series;
  std::vector<std::filesystem::path> scenes;  ///< the user's own scene files, timed by name
  /// packed folders (or their state.bin): timed from the packed state, where the neighbours are close
  std::vector<std::filesystem::path> states;
  std::filesystem::path examples = "examples";  ///< the element art and the example scenes
  bool example_scenes = true;  ///< also time examples/{default,aquarium,annulus} (not with `scenes` or `states`)
  std::optional<std::filesystem::path> json;
  std::string grid_sort = "auto";  ///< auto, host, device, or both: each OpenCL device timed with each sort
};

/// Called by bench with every row after the table and the JSON are written (the --plot picture).
using BenchPlotter = std::function<void(const std::vector<BenchRow>& rows)>;

int bench(const BenchOptions& options, const BenchPlotter& plot);

struct ValidateOptions {
  std::filesystem::path scene;
  std::optional<std::string> device;  ///< part of a device name; unset: the device pack would choose
  int steps = 20;
  bool all_devices = false;  ///< every OpenCL device, one summary row each
  bool json = false;
  std::string grid_sort = "auto";  ///< auto, host or device (GridSort)
};

/// Steps the reference and OpenCL devices side by side and compares every force and state array bit
/// for bit; 0 when identical, ExitCode::differs when not.
int validate(const ValidateOptions& options);

struct ParamsOptions {
  bool markdown = false;  ///< the table of docs/parameters.md, with the paper's values
};

/// Prints every constant a scene's `params` may override: name, default, range, meaning.
int params(const ParamsOptions& options);

/// Prints the JSON Schema of the scene file (docs/scene.schema.json).
int schema();

class Frontend;

/// Parses the command line for the shared commands and `frontend`'s own (frontend.hpp) and runs the
/// chosen one; never throws. Each executable's main() passes its frontend.
int run(int argc, char** argv, std::unique_ptr<Frontend> frontend);

}  // namespace animpak::cli
