#include <unistd.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "animpak/checkpoint.hpp"
#include "animpak/container_motion.hpp"
#include "animpak/error.hpp"
#include "animpak/levels.hpp"
#include "animpak/opencl.hpp"
#include "animpak/progress.hpp"
#include "animpak/run.hpp"
#include "commands.hpp"
#include "console.hpp"
#include "pack_output.hpp"

namespace animpak::cli {
namespace {

// Ctrl-C, SIGTERM (timeout, docker stop, a cluster's time limit) and SIGHUP (a closed terminal) alike stop
// the run at the next grid-rebuild boundary with its state saved; the exit code is 128 + the signal's.
std::atomic<bool> interrupted{false};
std::atomic<int> interrupting_signal{0};
extern "C" void on_stop_signal(int signal) {
  interrupting_signal.store(signal);
  interrupted.store(true);
}

// The stop signals' handlers for as long as the pack runs, the ones before restored after.
class StopSignals {
 public:
  StopSignals() {
    interrupted.store(false);
    interrupting_signal.store(0);
    for (std::size_t i = 0; i < std::size(kSignals); ++i) previous_[i] = std::signal(kSignals[i], on_stop_signal);
  }
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
  ~StopSignals() {
    for (std::size_t i = 0; i < std::size(kSignals); ++i) std::signal(kSignals[i], previous_[i]);
  }
  static int exit_code() { return 128 + (interrupting_signal.load() != 0 ? interrupting_signal.load() : SIGINT); }

 private:
  static constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
  void (*previous_[std::size(kSignals)])(int);
};

// Progress: a bar redrawn in place on a terminal, a plain line every few seconds otherwise, each within 80
// columns (the element counts and g range under --verbose). The time left comes from StopModel, a model of
// the stop test fitted to the run so far, and reads "estimating" until the model has enough of the run. A
// resumed run starts at the iteration and the clock where the runs before it stopped, with their samples.
class Progress {
 public:
  Progress(const Params& params, bool has_secondary, double unit_density, std::vector<ProgressSample> previous,
           bool verbose)
      : tty_(::isatty(STDERR_FILENO)),
        verbose_(verbose),
        model_(params.stop, has_secondary, unit_density, params.growth.growth_rate * params.forces.dt),
        start_(now() - (previous.empty() ? 0.0 : previous.back().seconds)) {
    for (const ProgressSample& s : previous) model_.observe(s);
  }

  void operator()(const StepStatistics& st) {
    const double elapsed = now() - start_;
    model_.observe({st.iteration, elapsed, st.mean_growth, st.growing_share, st.max_slice_gap, st.overlapping_vertices,
                    st.outside_vertices});
    if (elapsed - last_print_ < (tty_ ? 0.5 : 5.0)) return;
    last_print_ = elapsed;
    std::optional<StopEstimate> estimate = model_.estimate();
    // At the coarse level the model sees that level's stop; the scene's slices' steps still to come are
    // added at their own cost (docs/cli.md, "Progress and the time left").
    if (estimate && fine_cost_ > 0.0) estimate->seconds_left += fine_steps_ * fine_cost_ * recent_pace();
    const std::string line = pack_progress_text(st, elapsed, estimate, verbose_);
    if (tty_) {
      const double done =
          share_.update(elapsed, estimate ? std::optional<double>(estimate->seconds_left) : std::nullopt);
      std::cerr << "\r" << progress_bar(done) << " " << line << "\033[K" << std::flush;
    } else {
      std::cerr << "animpak: " << line << "\n";
    }
  }
  void finish() {
    if (tty_) std::cerr << "\n";
  }
  /// Coarse to fine: while at the coarse level, a step at the scene's slices costs `cost` coarse steps and
  /// about `steps` of them follow the refinement; 0 once refined.
  void set_fine_level(double cost, double steps) { fine_cost_ = cost, fine_steps_ = steps; }
  const std::vector<ProgressSample>& samples() const { return model_.samples(); }

 private:
  static double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  }
  // Seconds per step over the last 200 or more steps (0 before there are two samples).
  double recent_pace() const {
    const std::vector<ProgressSample>& s = model_.samples();
    if (s.size() < 2) return 0.0;
    std::size_t k = s.size() - 1;
    while (k > 0 && s.back().iteration - s[k].iteration < 200) --k;
    const double steps = double(s.back().iteration - s[k].iteration);
    return steps > 0.0 ? (s.back().seconds - s[k].seconds) / steps : 0.0;
  }
  bool tty_, verbose_;
  double fine_cost_ = 0.0, fine_steps_ = 0.0;
  StopModel model_;
  ProgressShare share_;
  double start_, last_print_ = -1e9;
};

// The steps a packing takes at the scene's slices after its coarse level (docs/parameters.md, "Coarse to
// fine"), for the time left while at the coarse level: they settle, aquatic-loop in 10.
constexpr double kFineLevelSteps = 50.0;

// A packing that stopped on its own (not interrupted) is finished: resuming it would only step it on past
// its stop, changing it. One stopped by its iteration limit continues under a larger limit.
// A state stopped at its coarse level (a preview) goes on to the scene's slices unless `preview` asks for
// the preview alone.
bool finished(const Checkpoint& c, const std::optional<std::uint64_t>& max_iterations, bool preview) {
  if (c.stop_reason == "interrupted" || c.stop_reason == "running") return false;
  if (c.level_slices != 0 && !preview && c.stop_reason != "max_iterations" && c.stop_reason != "non_finite")
    return false;
  return !(c.stop_reason == "max_iterations" && max_iterations && *max_iterations > c.state.iteration);
}

// The simulation time of the runs before a resume, from their stats.json (0 without one), so that the clock
// and stats.json count the whole packing.
double simulation_seconds(const std::filesystem::path& stats) {
  const std::optional<Stats> read = read_stats_json(stats);
  return read && read->seconds && std::isfinite(read->seconds->simulation) ? read->seconds->simulation : 0.0;
}

// The device by --device or the default rule, said in one line. A device asked for by name must work;
// one picked by the default rule falls back to the reference with the first lines of its error.
std::unique_ptr<Backend> make_backend(const std::string& request, GridSort sort, const World& world,
                                      std::string& driver, bool quiet = false) {
  const DeviceChoice choice = choose_device(request);
  if (!quiet) std::cerr << "animpak: device: " << choice.reason << "\n";
  if (!choice.reference) {
    try {
      auto backend = make_opencl_backend(world.topology, world.state, world.params, choice, sort);
      driver = choice.device.driver + " (" + choice.device.platform_version + ")";
      if (!quiet) std::cerr << "animpak: grids built on the " << grid_sort_name(backend->grid_sort()) << "\n";
      return backend;
    } catch (const OpenclError& e) {
      if (choice.explicit_request) throw;
      std::istringstream lines(e.what());
      std::string line, summary;
      for (int i = 0; i < 6 && std::getline(lines, line); ++i) summary += "\n  " + line;
      std::cerr << "animpak: " << choice.device.name
                << " cannot run the kernels; using the reference solver:" << summary << "\n";
    }
  }
  driver = "scalar reference (no OpenCL)";
  return make_reference_backend(world.topology, world.state, world.params);
}

}  // namespace

int pack(const PackOptions& options, const FrameRenderer& render_frames) {
  // Read before the packing, so that a wrong folder is refused before minutes of work, not after.
  std::optional<StillReference> still;
  if (options.still_reference) still = read_still_reference(*options.still_reference);
  // From here to the end of the simulation a stop signal stops the run at its first boundary, saved; the
  // render after it is stopped by Ctrl-C as any command is (it writes into a scratch folder).
  std::optional<StopSignals> signals(std::in_place);
  Checkpoint checkpoint;
  const std::filesystem::path out = options.resume ? *options.resume : options.out;
  const auto holds_packing = [&] { return std::filesystem::exists(out / "state.bin") || has_unfinished_pack(out); };
  const auto refuse_packing = [&] {
    throw UsageError(out.string() + " already holds a packing (" +
                     (std::filesystem::exists(out / "state.bin") ? (out / "state.bin").string()
                                                                 : "unfinished, in " + new_pack_dir(out).string()) +
                     "); pass --force to overwrite it, or --resume " + out.string() + " to continue it");
  };
  std::optional<SceneSpec> new_scene;
  if (options.resume) {
    if (!std::filesystem::is_directory(out))
      throw InputError((out / "state.bin").string() + ": cannot read the state file (" + out.string() +
                       " is not a folder); give the folder `animpak pack --out` wrote");
  } else {
    // The scene before the folder: a scene that cannot be packed leaves no folder behind.
    if (!options.force && holds_packing()) refuse_packing();
    check_inputs_writable(out);
    checkpoint.scene_file = std::filesystem::absolute(options.scene);
    new_scene = load_scene(checkpoint.scene_file);  // validates and names the file on every error
  }
  check_folder_writable(out);  // a read-only folder, a file in the way or a full disk: before any work
  const FolderLock lock(out, "animpak pack " + out.string());
  // The rendered files of the run before that this one removes, listed with the files it writes.
  std::vector<std::filesystem::path> removed;
  recover_folder(out, &removed);
  // A new packing is written beside the folder's packing until it ends (packed_folder.hpp); a resume of
  // a packing already swapped in writes where it is.
  const bool staged = !options.resume || has_unfinished_pack(out);
  const std::filesystem::path run_dir = staged ? new_pack_dir(out) : out;
  double previous_seconds = 0.0;
  if (options.resume) {
    checkpoint = read_checkpoint(run_dir / "state.bin", out);
    if (staged && finished(checkpoint, options.max_iterations, options.preview)) {
      // Killed after its last state was written and before the swap: nothing left but the swap.
      install_new_pack(out);
      std::cerr << "animpak: " << out.string() << ": swapped in the finished packing a killed pack left in "
                << run_dir.string() << "\n";
    }
    if (finished(checkpoint, options.max_iterations, options.preview)) {
      std::cerr << "animpak: " << out.string() << " holds a finished packing (stopped after "
                << checkpoint.state.iteration << " iterations: " << checkpoint.stop_reason
                << "); nothing to resume, nothing changed. `animpak render " << shell_word(out.string())
                << "` renders it again"
                << (checkpoint.stop_reason == "max_iterations" ? "; a larger --max-iterations continues it" : "")
                << "\n";
      return 0;
    }
    if (!staged) previous_seconds = simulation_seconds(out / "stats.json");
  } else {
    if (!options.force && holds_packing()) refuse_packing();  // again, now that the folder is this run's
    checkpoint.scene_text = read_bytes(checkpoint.scene_file, "check the scene file's path");
    if (options.still) {
      const double mean_scale = ContainerMotion(new_scene->container.animation, {}, 1.0, new_scene->loop).mean_scale();
      checkpoint.scene_text = still_scene_text(checkpoint.scene_text, *new_scene, mean_scale);
      std::cerr << "animpak: packing the still reference: the same elements standing still"
                << (new_scene->guided.empty() ? "" : ", guided elements as ordinary copies") << ", "
                << std::min(new_scene->params.element.slices, still_slices) << " slices\n";
    }
    checkpoint.seed = options.seed.value_or(new_scene->seed);
    // The copy of the scene and its art first, so that a checkpoint can be resumed from the folder alone.
    start_new_pack(out);
    write_inputs(run_dir, snapshot_inputs(checkpoint.scene_file, checkpoint.scene_text));
  }
  // A new packing builds from the scene where it is (its messages name the user's files, not the copies,
  // whose bytes are the same); a resume from the folder's copies.
  const PackedScene scene = options.resume ? packed_scene(run_dir, checkpoint)
                                           : PackedScene{checkpoint.scene_text, checkpoint.scene_file, {}};
  // The scene at a level: its own slices (0) or its coarse level's (docs/parameters.md, "Coarse to fine").
  const auto build_level = [&](std::int32_t level, bool with_state) {
    Checkpoint at_level = checkpoint;
    at_level.level_slices = level;
    try {
      return world_from_checkpoint(at_level, with_state, scene);
    } catch (...) {
      // A new packing that cannot be built (art too complex, too many elements) leaves nothing staged.
      if (!options.resume) std::filesystem::remove_all(run_dir);
      throw;
    }
  };
  // `loaded` is the scene at its own slices; a new packing starts at its coarse level when it has one, a
  // resumed one at the level its state is at.
  LoadedWorld loaded = build_level(0, options.resume && checkpoint.level_slices == 0);
  if (!options.resume) checkpoint.level_slices = coarse_slices(loaded.world.params);
  std::optional<LoadedWorld> coarse;
  if (checkpoint.level_slices != 0) {
    coarse = build_level(checkpoint.level_slices, options.resume.has_value());
    loaded.setup_seconds += coarse->setup_seconds;
    if (const std::string why = level_mismatch(coarse->world, loaded.world); !why.empty()) {
      if (options.resume)
        throw InputError(checkpoint.scene_file.string() + ": the state is at the coarse level, but " + why +
                         "; pack the scene again");
      std::cerr << "animpak: warning: no coarse level: " << why << "; packing at the scene's "
                << loaded.world.params.element.slices << " slices throughout\n";
      coarse.reset();
      checkpoint.level_slices = 0;
    }
  }
  if (options.preview && checkpoint.level_slices == 0 && !options.resume) {
    std::filesystem::remove_all(run_dir);
    throw UsageError(checkpoint.scene_file.string() + ": --preview: the scene has no coarse level (" +
                     std::to_string(loaded.world.params.element.slices) + " slices, params.coarse_step " +
                     std::to_string(loaded.world.params.element.coarse_step) +
                     "; docs/parameters.md, \"Coarse to fine\"); pack it without --preview");
  }
  World* level_world = coarse ? &coarse->world : &loaded.world;
  // --max-iterations replaces the scene's limit for this run; run_simulation stops there (an absolute count).
  if (options.max_iterations)
    for (World* w : {&loaded.world, coarse ? &coarse->world : nullptr})
      if (w) w->params.stop.max_iterations = static_cast<int>(*options.max_iterations);
  // A resumed run repeats no set-up report (the seeding it did not do again), only its warnings; the
  // scene's own slices say them (the coarse level's would warn of motions its slices cannot follow).
  for (const std::string& note : loaded.world.notes)
    if (!options.resume || note.rfind("warning:", 0) == 0) std::cerr << "animpak: " << note << "\n";
  if (options.resume)
    std::cerr << "animpak: resuming " << (run_dir / "state.bin").string() << " at iteration "
              << checkpoint.state.iteration << " after " << clock_text(previous_seconds) << "\n";
  if (coarse)
    std::cerr << "animpak: coarse to fine: " << checkpoint.level_slices << " slices until they stop"
              << (options.preview ? " (the preview)"
                                  : ", then the scene's " + std::to_string(loaded.world.params.element.slices))
              << "\n";
  std::cerr << "animpak: " << level_world->elements.size() << " elements, " << level_world->topology.vertex_count()
            << " vertices, " << level_world->topology.spring_other.size() / 2 << " springs, "
            << level_world->topology.envelope_count() << " envelope triangles\n";

  const std::uint64_t checkpoint_start = checkpoint.state.iteration;
  std::string driver;
  const GridSort sort = parse_grid_sort(options.grid_sort, "--grid-sort");
  std::unique_ptr<Backend> backend = make_backend(options.device, sort, *level_world, driver);
  std::vector<ProgressSample> previous_samples =
      options.resume && !staged ? read_progress(out / "stats.json") : std::vector<ProgressSample>{};
  if (previous_samples.empty() && previous_seconds > 0)  // a stats.json from before the samples were kept
    previous_samples.push_back({checkpoint.state.iteration, previous_seconds});
  Progress progress(loaded.world.params, loaded.world.topology.has_secondary(), unit_mesh_density(loaded.world),
                    previous_samples, options.verbose);
  if (coarse)
    progress.set_fine_level(double(loaded.world.topology.vertex_count()) / coarse->world.topology.vertex_count(),
                            kFineLevelSteps);
  RunControl control;
  control.interrupt = &interrupted;
  control.on_check = [&](const StepStatistics& st) { progress(st); };
  // The state so far, every --checkpoint-every seconds: a run killed outright (SIGKILL, a power cut)
  // resumes from the last one to the bytes of a run never stopped.
  control.checkpoint_seconds = options.checkpoint_seconds;
  control.on_checkpoint = [&](const SimState& state) {
    Checkpoint saved = checkpoint;
    saved.stop_reason = stop_reason_name(StopReason::running);
    saved.state = state;
    write_checkpoint(run_dir / "state.bin", saved, out);
  };
  // Each level runs to its own stop; a coarse level that stopped (not interrupted, not out of iterations) is
  // refined to the scene's slices and the packing goes on there, unless this is a preview.
  const auto level_stop = [](const std::string& reason) {
    return reason == "gap" || reason == "stalled" || reason == "unsettled";
  };
  RunResult result;
  result.last_good = checkpoint.state;
  result.reason = StopReason::running;
  bool resumed_stopped = options.resume && level_stop(checkpoint.stop_reason);
  std::vector<LevelTimes> levels;
  double simulated = 0.0;
  for (;;) {
    if (!resumed_stopped) {
      const std::uint64_t first = level_world->state.iteration;
      result = run_simulation(*backend, level_world->params, control);
      simulated += result.seconds;
      levels.push_back({level_world->params.element.slices, result.last_good.iteration - first, result.seconds,
                        backend->times(), backend->kernel_times()});
    }
    const std::string reason = resumed_stopped ? checkpoint.stop_reason : stop_reason_name(result.reason);
    resumed_stopped = false;
    if (!coarse || options.preview || !level_stop(reason)) break;
    loaded.world.state = refine_state(coarse->world, result.last_good, loaded.world);
    std::cerr << "animpak: the " << checkpoint.level_slices << "-slice level stopped after "
              << result.last_good.iteration << " iterations (" << reason << "); refined to "
              << loaded.world.params.element.slices << " slices\n";
    checkpoint.level_slices = 0;
    progress.set_fine_level(0.0, 0.0);
    coarse.reset();
    level_world = &loaded.world;
    result.last_good = loaded.world.state;
    backend = make_backend(options.device, sort, loaded.world, driver, true);
  }
  result.seconds = simulated;
  World& world = *level_world;
  signals.reset();
  progress.finish();
  result.seconds += previous_seconds;

  checkpoint.stop_reason = stop_reason_name(result.reason);
  checkpoint.state = result.last_good;
  write_checkpoint(run_dir / "state.bin", checkpoint, out);
  world.state = result.last_good;
  // The new packing swapped in whole, the frames of the one before removed with it; a resumed packing's
  // own frames are of an earlier state, so they go too, before the render below runs.
  const std::vector<std::filesystem::path> replaced = staged ? install_new_pack(out) : remove_rendered(out);
  removed.insert(removed.end(), replaced.begin(), replaced.end());

  const LevelTimes total = total_times(levels);
  PackReport report{world,           result, total.times,        checkpoint,    {},    loaded.setup_seconds,
                    backend->name(), driver, progress.samples(), total.kernels, levels};
  if (result.reason == StopReason::non_finite) {
    write_stats(out / "stats.json", report);
    const std::int32_t v = result.last.first_bad_vertex;
    const ElementInstance& e = world.elements[world.topology.element[v]];
    // Exit 2: what makes a step blow up is the scene's params (a stiffness of 1e300 is in range).
    throw InputError(checkpoint.scene_file.string() + ": the simulation produced NaN/Inf at element " + e.name +
                     ", slice " + std::to_string(world.topology.slice[v] - e.slice_begin) + " near iteration " +
                     std::to_string(result.last.iteration) + "; the last finite state (iteration " +
                     std::to_string(result.last_good.iteration) + ") is in " + (out / "state.bin").string() +
                     "; lower params.dt or the stiffnesses");
  }
  std::cerr << "animpak: stopped after " << result.last_good.iteration << " iterations (" << checkpoint.stop_reason
            << ") in " << clock_text(result.seconds) << "\n";
  if (checkpoint.level_slices != 0 && result.reason != StopReason::interrupted)
    std::cerr << "animpak: a preview at " << checkpoint.level_slices << " slices; `" << options.program
              << " pack --resume " << shell_word(out.string()) << "` goes on to the scene's "
              << loaded.world.params.element.slices << "\n";
  // This run's own share (a resumed run's earlier time is in result.seconds, not in the phase times).
  if (options.profile) {
    // Each level's own, then (coarse to fine) the run's sum.
    if (levels.size() > 1)
      for (const LevelTimes& l : levels)
        std::cerr << "level of " << l.slices
                  << " slices: " << profile_text(l.times, l.kernels, l.iterations, l.seconds);
    std::cerr << profile_text(report.times, report.kernels, result.last_good.iteration - checkpoint_start,
                              result.seconds - previous_seconds);
  }
  if (world.topology.has_secondary()) {
    if (result.last_good.secondary_since != 0)
      std::cerr << "animpak: the secondary elements grew from iteration " << result.last_good.secondary_since
                << ", when the primary ones had stopped\n";
    else
      std::cerr << "animpak: the secondary elements kept their start size: the primary ones had not stopped growing\n";
  }
  if (result.reason == StopReason::unsettled)
    std::cerr << "animpak: warning: " << result.last.overlapping_vertices
              << " vertices still overlap another element and " << result.last.outside_vertices
              << " lie outside the container after " << world.params.stop.settle_iterations
              << " settling steps; more slices (top-level \"slices\") or a larger params.settle_iterations may help\n";
  if (result.reason == StopReason::interrupted) {
    std::string command = options.program + " pack --resume " + shell_word(out.string());
    if (options.max_iterations) command += " --max-iterations " + std::to_string(*options.max_iterations);
    if (options.preview) command += " --preview";
    std::cerr << "animpak: interrupted; continue with: " << command << "\n";
  }
  // stats.json first, so that a render that fails (ffmpeg, a full disk) leaves this run's, not the last one's.
  write_stats(out / "stats.json", report);
  std::string still_line;
  if (render_frames && result.reason != StopReason::interrupted) {
    Rendered rendered =
        render_frames(world, out, [&](const PackingQuality& quality, const std::filesystem::path& scratch) {
          report.quality = quality;
          write_stats(scratch / "stats.json", report);
          if (still && !quality.frames.empty())
            still_line = add_still_reference(scratch / "stats.json", *still, quality);
        });
    report.quality = std::move(rendered.quality);
    removed.insert(removed.end(), rendered.removed.begin(), rendered.removed.end());
  }
  std::cerr << written_files(out, WrittenBy::pack, removed);
  if (!report.quality.frames.empty()) std::cout << quality_lines(report.quality) << still_line;
  return result.reason == StopReason::interrupted ? StopSignals::exit_code() : 0;
}

}  // namespace animpak::cli
