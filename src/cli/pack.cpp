#include <unistd.h>

#include <nlohmann/json.hpp>

#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "animpak/checkpoint.hpp"
#include "animpak/error.hpp"
#include "animpak/opencl.hpp"
#include "animpak/run.hpp"
#include "commands.hpp"
#include "pack_output.hpp"

namespace animpak::cli {
namespace {

std::atomic<bool> interrupted{false};
extern "C" void on_sigint(int) { interrupted.store(true); }

std::string clock_text(double seconds) {
  char s[32];
  const long t = static_cast<long>(seconds);
  std::snprintf(s, sizeof s, "%02ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
  return s;
}

// Progress: a bar redrawn in place on a terminal, a plain line every few seconds otherwise. A resumed run
// starts at the iteration and the clock where the runs before it stopped.
class Progress {
 public:
  Progress(std::uint64_t max_iterations, double stop_gap, std::uint64_t first_iteration, double previous_seconds)
      : tty_(::isatty(STDERR_FILENO)),
        max_(max_iterations),
        first_(first_iteration),
        stop_gap_(stop_gap),
        start_(now() - previous_seconds),
        resumed_at_(previous_seconds) {}

  void operator()(const StepStatistics& st) {
    const double elapsed = now() - start_;
    if (!tty_ && elapsed - last_print_ < 5.0) return;
    last_print_ = elapsed;
    // The estimate extrapolates this run's pace over the iterations left, and the largest gap's recent fall
    // towards the stop gap: rough, but it moves the right way.
    const double run_seconds = elapsed - resumed_at_;
    double remaining = max_ > st.iteration && st.iteration > first_
                           ? run_seconds * double(max_ - st.iteration) / double(st.iteration - first_)
                           : 0;
    if (previous_gap_ > st.max_slice_gap && std::isfinite(previous_gap_) && std::isfinite(st.max_slice_gap)) {
      const double rate = (previous_gap_ - st.max_slice_gap) / std::max(elapsed - previous_time_, 1e-9);
      remaining = std::min(remaining, std::max(0.0, (st.max_slice_gap - stop_gap_) / rate));
    }
    previous_gap_ = st.max_slice_gap;
    previous_time_ = elapsed;
    const int width = 24;
    const int filled = static_cast<int>(width * std::clamp(elapsed / std::max(elapsed + remaining, 1e-9), 0.0, 1.0));
    std::ostringstream line;
    line << "iter " << st.iteration << "  gap "
         << (std::isfinite(st.max_slice_gap) ? std::to_string(st.max_slice_gap) : "inf") << "  growing "
         << static_cast<int>(100 * st.growing_share) << "%  overlaps " << st.overlapping_vertices << "  outside "
         << st.outside_vertices << "  g " << st.min_growth << ".." << st.max_growth << "  " << clock_text(elapsed)
         << " (~" << clock_text(remaining) << " left)";
    if (tty_)
      std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, '.') << "] " << line.str()
                << "\033[K" << std::flush;
    else
      std::cerr << "animpak: " << line.str() << "\n";
  }
  void finish() {
    if (tty_) std::cerr << "\n";
  }

 private:
  static double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  }
  bool tty_;
  std::uint64_t max_, first_;
  double stop_gap_, start_, resumed_at_, last_print_ = -1e9;
  double previous_gap_ = std::numeric_limits<double>::infinity(), previous_time_ = 0;
};

// `path` as one word of a shell command line: quoted when it holds anything but plain path characters.
std::string shell_word(const std::filesystem::path& path) {
  const std::string s = path.string();
  if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./+,:=@") ==
                        std::string::npos)
    return s;
  std::string quoted = "'";
  for (char c : s) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// A packing that stopped on its own (not interrupted) is finished: resuming it would only step it on past
// its stop, changing it. One stopped by its iteration limit continues under a larger limit.
bool finished(const Checkpoint& c, const std::optional<std::uint64_t>& max_iterations) {
  if (c.stop_reason == "interrupted" || c.stop_reason == "running") return false;
  return !(c.stop_reason == "max_iterations" && max_iterations && *max_iterations > c.state.iteration);
}

// The simulation time of the runs before a resume, from their stats.json (0 without one), so that the clock
// and stats.json count the whole packing.
double simulation_seconds(const std::filesystem::path& stats) {
  std::ifstream in(stats);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("seconds") || !j["seconds"].is_object()) return 0.0;
  const nlohmann::json& seconds = j["seconds"];
  return seconds.contains("simulation") && seconds["simulation"].is_number() ? seconds["simulation"].get<double>()
                                                                             : 0.0;
}

std::string read_whole(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The device by --device or the default rule, said in one line. A device asked for by name must work;
// one picked by the default rule falls back to the reference with the first lines of its error.
std::unique_ptr<Backend> make_backend(const std::string& request, GridSort sort, const World& world,
                                      std::string& driver) {
  const DeviceChoice choice = choose_device(request);
  std::cerr << "animpak: device: " << choice.reason << "\n";
  if (!choice.reference) {
    try {
      auto backend = make_opencl_backend(world.topology, world.state, world.params, choice, sort);
      driver = choice.device.driver + " (" + choice.device.platform_version + ")";
      std::cerr << "animpak: collision grid sorted on the " << grid_sort_name(backend->grid_sort()) << "\n";
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
  Checkpoint checkpoint;
  std::filesystem::path out = options.out;
  std::optional<InputSnapshot> inputs;
  double previous_seconds = 0.0;
  if (options.resume) {
    out = *options.resume;
    checkpoint = read_checkpoint(out / "state.bin");
    if (finished(checkpoint, options.max_iterations)) {
      std::cerr << "animpak: " << out.string() << " holds a finished packing (stopped after "
                << checkpoint.state.iteration << " iterations: " << checkpoint.stop_reason
                << "); nothing to resume, nothing changed. `animpak render " << shell_word(out) << "` renders it again"
                << (checkpoint.stop_reason == "max_iterations" ? "; a larger --max-iterations continues it" : "")
                << "\n";
      return 0;
    }
    previous_seconds = simulation_seconds(out / "stats.json");
  } else {
    if (std::filesystem::exists(out / "state.bin") && !options.force)
      throw UsageError(out.string() + " already holds a packing (" + (out / "state.bin").string() +
                       "); pass --force to overwrite it, or --resume " + out.string() + " to continue it");
    check_inputs_writable(out);
    checkpoint.scene_file = std::filesystem::absolute(options.scene);
    const SceneSpec scene = load_scene(checkpoint.scene_file);  // validates and names the file on every error
    checkpoint.scene_text = read_whole(checkpoint.scene_file);
    checkpoint.seed = options.seed.value_or(scene.seed);
    inputs = snapshot_inputs(checkpoint.scene_file, checkpoint.scene_text);
  }
  // Rendered files are this run's to replace only where a packing was: a fresh --out may hold the user's own.
  const bool replaces_packing = std::filesystem::exists(out / "state.bin");
  std::filesystem::create_directories(out);
  const PackedScene scene =
      options.resume ? packed_scene(out, checkpoint) : PackedScene{checkpoint.scene_text, checkpoint.scene_file, {}};
  LoadedWorld loaded = world_from_checkpoint(checkpoint, options.resume.has_value(), scene);
  World& world = loaded.world;
  if (options.max_iterations) world.params.stop.max_iterations = static_cast<int>(*options.max_iterations);
  // A resumed run repeats no set-up report (the seeding it did not do again), only its warnings.
  for (const std::string& note : world.notes)
    if (!options.resume || note.rfind("warning:", 0) == 0) std::cerr << "animpak: " << note << "\n";
  if (options.resume)
    std::cerr << "animpak: resuming " << (out / "state.bin").string() << " at iteration " << checkpoint.state.iteration
              << " after " << clock_text(previous_seconds) << "\n";
  std::cerr << "animpak: " << world.elements.size() << " elements, " << world.topology.vertex_count() << " vertices, "
            << world.topology.spring_other.size() / 2 << " springs, " << world.topology.envelope_count()
            << " envelope triangles\n";

  std::string driver;
  std::unique_ptr<Backend> backend =
      make_backend(options.device, parse_grid_sort(options.grid_sort, "--grid-sort"), world, driver);
  Progress progress(static_cast<std::uint64_t>(world.params.stop.max_iterations), world.params.stop.stop_gap,
                    checkpoint.state.iteration, previous_seconds);
  RunControl control;
  control.max_iterations = static_cast<std::uint64_t>(world.params.stop.max_iterations);
  control.interrupt = &interrupted;
  control.on_check = [&](const StepStatistics& st) { progress(st); };
  interrupted.store(false);
  auto previous = std::signal(SIGINT, on_sigint);
  RunResult result = run_simulation(*backend, world.params, control);
  std::signal(SIGINT, previous);
  progress.finish();
  result.seconds += previous_seconds;

  checkpoint.stop_reason = stop_reason_name(result.reason);
  checkpoint.state = result.last_good;
  write_checkpoint(out / "state.bin", checkpoint);
  world.state = result.last_good;
  if (inputs) write_inputs(out, *inputs);
  // Frames of an earlier state must not stay beside this one, not even while the render below runs.
  if (replaces_packing) remove_rendered(out);

  PackReport report{world, result, backend->times(), checkpoint, {}, loaded.setup_seconds, backend->name(), driver};
  if (result.reason == StopReason::non_finite) {
    write_stats(out / "stats.json", report);
    const std::int32_t v = result.last.first_bad_vertex;
    const ElementInstance& e = world.elements[world.topology.element[v]];
    throw std::runtime_error("the simulation produced NaN/Inf at element " + e.name + ", slice " +
                             std::to_string(world.topology.slice[v] - e.slice_begin) + " near iteration " +
                             std::to_string(result.last.iteration) + "; the last finite state (iteration " +
                             std::to_string(result.last_good.iteration) + ") is in " + (out / "state.bin").string() +
                             "; lower params.dt or the stiffnesses");
  }
  std::cerr << "animpak: stopped after " << result.last_good.iteration << " iterations (" << checkpoint.stop_reason
            << ") in " << clock_text(result.seconds) << "; state in " << (out / "state.bin").string() << "\n";
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
    std::string command = options.program + " pack --resume " + shell_word(out);
    if (options.max_iterations) command += " --max-iterations " + std::to_string(*options.max_iterations);
    std::cerr << "animpak: interrupted; continue with: " << command << "\n";
  }
  // stats.json first, so that a render that fails (ffmpeg, a full disk) leaves this run's, not the last one's.
  write_stats(out / "stats.json", report);
  if (render_frames && result.reason != StopReason::interrupted) {
    report.quality = render_frames(world, out);
    write_stats(out / "stats.json", report);
  }
  if (!report.quality.frames.empty()) std::cout << quality_lines(report.quality);
  return result.reason == StopReason::interrupted ? static_cast<int>(ExitCode::interrupted) : 0;
}

}  // namespace animpak::cli
