// The full `animpak`: the solver commands of run.cpp plus everything that draws (inspect, check, render, the
// frames after pack, bench --plot). Only this executable compiles this file and links animpak_render.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "animpak/error.hpp"
#include "animpak/report.hpp"  // write_bench_plot
#include "console.hpp"
#include "frontend.hpp"
#include "pack_output.hpp"
#include "validators.hpp"

namespace animpak::cli {
namespace {

constexpr const char* kFormatNames = "png, gif, mp4, svg, lottie, dotlottie or svg-anim";

FrameFormat parse_format(const std::string& name) {
  if (name == "png") return FrameFormat::png;
  if (name == "gif") return FrameFormat::gif;
  if (name == "mp4") return FrameFormat::mp4;
  if (name == "svg") return FrameFormat::svg;
  if (name == "lottie") return FrameFormat::lottie;
  if (name == "dotlottie") return FrameFormat::dotlottie;
  if (name == "svg-anim") return FrameFormat::svg_anim;
  throw UsageError("--format " + name + ": expected " + kFormatNames);
}

// The formats of one --format argument, a comma-separated list as typed ("gif, mp4" too: spaces around an
// item do not count); UsageError for an empty item or an unknown format.
std::vector<FrameFormat> format_list(const std::string& argument) {
  std::vector<FrameFormat> formats;
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = std::min(argument.find(',', begin), argument.size());
    std::string item = argument.substr(begin, end - begin);
    const auto space = [](unsigned char c) { return std::isspace(c) != 0; };
    item.erase(item.begin(), std::find_if_not(item.begin(), item.end(), space));
    item.erase(std::find_if_not(item.rbegin(), item.rend(), space).base(), item.end());
    if (item.empty())
      throw UsageError("--format \"" + argument + "\": " +
                       (argument.find_first_not_of(" \t,") == std::string::npos ? "no format given"
                                                                                : "an empty item (a comma too many)") +
                       "; give one or more of " + kFormatNames + ", separated by commas (e.g. --format gif,mp4)");
    formats.push_back(parse_format(item));
    if (end == argument.size()) return formats;
    begin = end + 1;
  }
}

Rgba parse_background(const std::string& text) {
  if (text == "white") return {1, 1, 1, 1};
  if (text == "none") return {1, 1, 1, 0};
  const auto hex_digit = [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; };
  if (text.size() != 7 || text[0] != '#' || !std::all_of(text.begin() + 1, text.end(), hex_digit))
    throw UsageError("--background " + text + ": expected white, none or a colour #rrggbb (e.g. #1e1e1e)");
  auto channel = [&](int at) { return std::stoi(text.substr(at, 2), nullptr, 16) / 255.0; };
  return {channel(1), channel(3), channel(5), 1};
}

ContainerDrawing parse_container(const FrameOptions& options) {
  if (options.no_container || options.container == "none") return ContainerDrawing::none;
  return options.container == "fill" ? ContainerDrawing::fill : ContainerDrawing::outline;
}

/// The frame options as the writers take them (the folder left empty); UsageError for a bad background or
/// one MP4 cannot carry. Called before a pack's simulation too, so that such a slip costs no packing.
FrameOutput frame_output(const FrameOptions& options) {
  FrameOutput out;
  out.count = options.frames;
  out.fps = options.fps;
  out.style.size = options.size;
  out.style.background = parse_background(options.background);
  out.style.container = parse_container(options);
  out.formats.clear();
  out.precision = options.precision;
  out.curve_tolerance = options.curve_tolerance;
  out.interpolation = options.interpolation == "hold" ? Interpolation::hold : Interpolation::linear;
  for (const std::string& argument : options.formats)
    for (FrameFormat f : format_list(argument)) out.formats.push_back(f);
  if (out.style.background.a < 1 && std::count(out.formats.begin(), out.formats.end(), FrameFormat::mp4))
    throw UsageError("--background " + options.background +
                     ": MP4 (H.264) has no transparency; give the MP4 a "
                     "colour (--background white or #rrggbb) or leave mp4 out of --format");
  return out;
}

/// Writes the frames in the requested formats into a scratch folder, swaps them in for every rendered file
/// already in `dir` and returns their quality and the files of the render before it removed.
Rendered render_frames(const World& world, const std::filesystem::path& dir, const FrameOptions& options,
                       const BesideFrames& beside) {
  FrameOutput out = frame_output(options);
  out.dir = render_scratch(dir);
  RenderProgress progress;
  out.on_progress = [&progress](const std::string& stage, int done, int total) { progress(stage, done, total); };
  std::cerr << "animpak: rendering " << out.count << " frames at " << out.style.size << " px into " << dir.string()
            << "\n";
  PackingQuality quality = write_frames(world, world.state, out);
  progress.finish();
  if (beside) beside(quality, out.dir);
  std::vector<std::filesystem::path> removed = install_rendered(out.dir, dir);
  return {std::move(quality), std::move(removed)};
}

void add_frame_options(CLI::App& cmd, FrameOptions& f) {
  cmd.add_option("--frames", f.frames, "frames in the animation")->check(CLI::Range(1, 100000));
  cmd.add_option("--size", f.size, "frame height in pixels")->check(CLI::Range(16, 8192));
  cmd.add_option("--fps", f.fps, "frames per second of gif, mp4, lottie and svg-anim")
      ->check(finite_number() & CLI::Range(1.0, 240.0));
  cmd.add_option("--format", f.formats,
                 "png, gif, mp4, svg (frames), lottie (animation.json), dotlottie (animation.lottie), svg-anim "
                 "(animation.svg); several allowed, separated by commas (gif,mp4)")
      ->check(CLI::Validator(
          [](std::string& argument) {
            try {
              format_list(argument);
            } catch (const UsageError& e) {
              return std::string(e.what()).substr(std::string("--format ").size());
            }
            return std::string();
          },
          "{png,gif,mp4,svg,lottie,dotlottie,svg-anim}"));
  cmd.add_option("--precision", f.precision,
                 "decimals of a pixel kept in lottie and svg-anim coordinates (of a --size picture)")
      ->check(CLI::Range(0, 6));
  cmd.add_option("--curve-tolerance", f.curve_tolerance,
                 "pixels (of a --size picture) the cubic Bezier curves of lottie and svg-anim paths may lie from the "
                 "art's polylines, taken from the keys' 3/4 of a pixel; 0 writes the polylines point by point")
      ->check(CLI::Range(0.0, 0.5));
  cmd.add_option("--interpolation", f.interpolation,
                 "how lottie and svg-anim move: linear (each path keyed where the curve between slices needs it, "
                 "so that the player's eased line between keys stays within 3/4 of a pixel less --curve-tolerance, "
                 "or 0.3 % of the element's size, of it) "
                 "or hold (keyed at the frames, each shown until the next)")
      ->check(CLI::IsMember({"linear", "hold"}));
  cmd.add_option("--background", f.background,
                 "white, none (transparent PNG and GIF, no Lottie background layer, no SVG backdrop) or #rrggbb");
  CLI::Option* container =
      cmd.add_option("--container", f.container,
                     "outline (a thin grey line over the elements), fill (the container art painted under them) "
                     "or none")
          ->check(CLI::IsMember({"outline", "fill", "none"}));
  cmd.add_flag("--no-container", f.no_container, "the same as --container none")->excludes(container);
}

class RenderingFrontend final : public Frontend {
 public:
  std::string name() const override { return "animpak"; }
  std::string description() const override {
    return "animpak: packs animated vector elements into a container (AnimationPak)";
  }

  void add_commands(CLI::App& app, CLI::App& pack, CLI::App& bench) override {
    inspect_cmd_ = app.add_subcommand(
        "inspect", "Build the spacetime elements of a scene or one art file and print their sizes (paper Table 1)");
    inspect_cmd_->add_option("FILE", inspect_.file, "scene (.json) or art file (.svg, .path)")->required();
    inspect_cmd_->add_option("--out", inspect_.out, "write PNG pictures of every element into this folder");
    inspect_cmd_->add_flag("--json", inspect_.json, "print the counts as JSON");
    inspect_cmd_->add_option("--slices", inspect_.slices, "number of slices n_s (overrides the scene)")
        ->check(CLI::Range(2, 1000));
    inspect_cmd_->add_option("--size", inspect_.picture_size, "picture height in pixels")->check(CLI::Range(16, 8192));

    check_cmd_ = app.add_subcommand("check",
                                    "Preflight one art file before packing: what is imported, every warning, and a "
                                    "preview as imported; a container's outline, holes and area");
    check_cmd_
        ->add_option("FILE", check_.file,
                     "art file (.svg, .path), checked as an element; or a scene (.json), whose container is checked")
        ->required();
    CLI::Option* as_container = check_cmd_->add_flag(
        "--container", check_.container,
        "check the art file as a container: its outline, holes, area and bounds instead of an element");
    check_cmd_
        ->add_option("--outline", check_.outline,
                     "with --container: the outline's path, as a scene's container.outline (default: the largest "
                     "closed path that is not a hole)")
        ->check(CLI::NonNegativeNumber)
        ->needs(as_container);
    check_cmd_
        ->add_option("--holes", check_.holes,
                     "with --container: the holes' paths, as a scene's container.holes (default: the .path "
                     "type-7 paths; SVG: none)")
        ->delimiter(',')
        ->check(CLI::NonNegativeNumber)
        ->needs(as_container);
    check_cmd_
        ->add_option("--exclude", check_.exclude,
                     "leave this SVG element out, as an element's \"exclude\" entry does: \"#id\" or \".class\" "
                     "(repeat for more)")
        ->allow_extra_args(false)
        ->excludes(as_container);
    check_cmd_->add_option("--png", check_.png,
                           "draw the art as imported at the document's viewport into this PNG (transparent "
                           "background), to hold next to a browser's rendering");
    check_cmd_->add_option("--size", check_.size, "the PNG's longer side in pixels")->check(CLI::Range(16, 8192));
    check_cmd_->add_flag("--json", check_.json, "print the report as JSON (docs/check.md)");
    check_cmd_->footer(
        "Exit codes: 0 ready to pack (warnings may remain), 2 the file cannot be imported or built "
        "into an element (or, as a container, into a container).");

    render_cmd_ = app.add_subcommand("render", "Render the frames of a saved packing again");
    render_cmd_->add_option("DIR", render_.dir, "folder written by animpak pack")->required();
    render_cmd_->add_option("--scene", render_.scene,
                            "read the scene and its art from this file and the files beside it instead of DIR/input/ "
                            "(checked against the packed scene and DIR/input/manifest.json's hashes)");
    render_cmd_->add_flag("--force", render_.force, "render with a --scene or art that differs from the packed one");
    add_frame_options(*render_cmd_, render_.frames);
    render_cmd_->add_option("--still-reference", render_.still_reference,
                            "a folder `pack --still` wrote for this scene: stats.json then carries its coverage "
                            "beside these frames', and a `still:` line compares them");
    render_cmd_->add_flag("--contact-plot", render_.contact_plot,
                          "also draw every frame's spherical contact function H(r) into DIR/contact.png");

    report_cmd_ = app.add_subcommand(
        "report",
        "Write a packing as one self-contained HTML page: its animation, quality and motion per frame, "
        "elements and provenance");
    report_cmd_->add_option("DIR", report_.dir, "folder written by animpak pack (rendered)")->required();
    report_cmd_->add_option("--out", report_.out, "the page's file (default DIR/report.html)");

    trajectory_cmd_ = app.add_subcommand(
        "trajectory",
        "Draw one element's path through the loop in one or more packings of the same container, as one SVG");
    trajectory_cmd_->add_option("DIR", trajectory_.dirs, "folders written by animpak pack, drawn in this order")
        ->required();
    trajectory_cmd_->add_option("--element", trajectory_.element, "the element's name, as stats.json names it")
        ->required();
    trajectory_cmd_->add_option("--samples", trajectory_.samples, "times along the loop the path is measured at")
        ->check(CLI::Range(8, 20000));
    trajectory_cmd_->add_option("--out", trajectory_.out, "the SVG's file (default: the first DIR's trajectory.svg)");

    add_sweep_commands(app);

    pack.add_flag("!--no-render", pack_render_, "do not render frames");
    add_frame_options(pack, pack_frames_);

    bench.add_option("--plot", bench_plot_, "draw ms/iteration against vertices into this PNG");
  }

  void add_sweep_commands(CLI::App& app) {
    sweep_cmd_ = app.add_subcommand(
        "sweep",
        "Pack a scene once per seed and per value of the settings given (--set), locally or on a cluster, and "
        "gather the runs into one page to choose from (docs/sweeps.md)");
    sweep_cmd_->add_option("SCENE", sweep_.scene, "scene file (.json)");
    sweep_cmd_->add_option("--out", sweep_.out,
                           "the sweep's folder: plan.json, runs/ID/ (each run an ordinary packed folder), "
                           "sweep.html, runs.csv and the cluster files");
    sweep_cmd_->add_option("--seeds", sweep_.seeds,
                           "seeds: whole numbers and ranges, separated by commas (1-8, or 1,3,5-7); default: the "
                           "scene's seed");
    sweep_cmd_
        ->add_option("--set", sweep_.sets,
                     "NAME=V1,V2,...: pack once per value (repeatable: every combination); NAME is a parameter of "
                     "`animpak params` (k_time), slices, count, or an element's count (NAME.count); each value is "
                     "checked against the parameter's range before anything runs")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    sweep_cmd_
        ->add_option("--jobs", sweep_.jobs,
                     "packs at a time here; default: one per two cores (each pack's OpenCL device uses several), at "
                     "least one: " +
                         std::to_string(default_sweep_jobs()) + " on this machine")
        ->check(CLI::Range(1, 1024));
    sweep_cmd_->add_flag("--plan-only", sweep_.plan_only,
                         "write plan.json and the cluster files (slurm.sbatch, k8s-job.yaml, commands.txt) and run "
                         "nothing");
    sweep_cmd_
        ->add_option("--submit", sweep_.submit,
                     "submit the runs not yet complete to a cluster: slurm (one array job, with sbatch; prints the "
                     "job id)")
        ->check(CLI::IsMember({"slurm"}));
    sweep_cmd_->add_option("--cpus-per-task", sweep_.cpus_per_task, "CPUs each cluster task asks for")
        ->check(CLI::Range(1, 1024));
    sweep_cmd_->add_option("--animpak", sweep_.node_animpak,
                           "the animpak the cluster files run on every node (default: this animpak's absolute path; "
                           "in k8s-job.yaml: animpak on the image's PATH)");
    sweep_cmd_->add_option("--k8s-image", sweep_.k8s_image,
                           "the image of k8s-job.yaml's pods, one that holds animpak (default: animpak:VERSION)");
    sweep_cmd_->add_option("--k8s-claim", sweep_.k8s_claim,
                           "the PersistentVolumeClaim k8s-job.yaml mounts at the sweep folder's path");
    sweep_cmd_->add_option("--max-iterations", sweep_.pack.max_iterations, "each run: stop after this many iterations")
        ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{100000000}));
    sweep_cmd_->add_option("--device", sweep_.pack.device,
                           "each run: 'reference', or part of an OpenCL device's name (as pack --device)");
    sweep_cmd_->add_option("--grid-sort", sweep_.pack.grid_sort, "each run: auto, host or device (as pack --grid-sort)")
        ->check(CLI::IsMember({"auto", "host", "device"}));
    sweep_cmd_
        ->add_option("--checkpoint-every", sweep_.pack.checkpoint_seconds,
                     "each run: seconds between the states saved while it packs (as pack --checkpoint-every)")
        ->check(finite_number() & CLI::Range(0.0, 86400.0));
    add_frame_options(*sweep_cmd_, sweep_.pack.frames);
    collect_cmd_ = sweep_cmd_->add_subcommand(
        "collect", "Gather a sweep's runs into DIR/sweep.html (a card per run, sorted on the page) and DIR/runs.csv");
    collect_cmd_->add_option("DIR", collect_.dir, "a sweep's folder (animpak sweep --out)")->required();

    task_cmd_ =
        app.add_subcommand("sweep-task", "Run one run of a sweep's plan: what each task of a cluster's array job runs");
    task_cmd_->add_option("DIR", task_.dir, "a sweep's folder (animpak sweep --out), with its plan.json")->required();
    task_cmd_
        ->add_option("--index", task_.index,
                     "the run's index in plan.json; default: SLURM_ARRAY_TASK_ID (Slurm) or JOB_COMPLETION_INDEX "
                     "(Kubernetes)")
        ->check(CLI::Range(0LL, 100000000LL));
  }

  std::optional<int> run_own_command() override {
    if (collect_cmd_->parsed()) return sweep_collect(collect_);
    if (sweep_cmd_->parsed()) {
      frame_output(sweep_.pack.frames);  // a bad frame option fails before the plan, not in every run
      return sweep(sweep_);
    }
    if (task_cmd_->parsed()) return sweep_task(task_);
    if (inspect_cmd_->parsed()) return inspect(inspect_);
    if (check_cmd_->parsed()) return check(check_);
    if (render_cmd_->parsed()) return render(render_);
    if (report_cmd_->parsed()) return report(report_);
    if (trajectory_cmd_->parsed()) return trajectory(trajectory_);
    return std::nullopt;
  }

  FrameRenderer frame_renderer() const override {
    if (!pack_render_) return {};
    frame_output(pack_frames_);  // a bad option fails now, not after the packing
    return [frames = pack_frames_](const World& world, const std::filesystem::path& dir, const BesideFrames& beside) {
      return render_frames(world, dir, frames, beside);
    };
  }

  BenchPlotter bench_plotter() const override {
    if (!bench_plot_) return {};
    return [file = *bench_plot_](const std::vector<BenchRow>& rows) { write_bench_plot(rows, file); };
  }

 private:
  CLI::App* inspect_cmd_ = nullptr;
  CLI::App* check_cmd_ = nullptr;
  CLI::App* render_cmd_ = nullptr;
  CLI::App* report_cmd_ = nullptr;
  ReportOptions report_;
  CLI::App* trajectory_cmd_ = nullptr;
  TrajectoryOptions trajectory_;
  InspectOptions inspect_;
  CheckOptions check_;
  RenderOptions render_;
  CLI::App* sweep_cmd_ = nullptr;
  CLI::App* collect_cmd_ = nullptr;
  CLI::App* task_cmd_ = nullptr;
  SweepOptions sweep_;
  SweepCollectOptions collect_;
  SweepTaskOptions task_;
  bool pack_render_ = true;
  FrameOptions pack_frames_;
  std::optional<std::filesystem::path> bench_plot_;
};

}  // namespace

int render(const RenderOptions& options) {
  // Read first, so that a wrong folder is refused before the frames are drawn.
  std::optional<StillReference> still;
  if (options.still_reference) still = read_still_reference(*options.still_reference);
  const FolderLock lock(options.dir, "animpak render " + options.dir.string());
  std::vector<std::filesystem::path> removed;
  if (recover_folder(options.dir, &removed))
    std::cerr << "animpak: finished swapping in the packing a killed pack left whole in " << options.dir.string()
              << "\n";
  const Checkpoint checkpoint = read_checkpoint(options.dir / "state.bin");
  const PackedScene packed = packed_scene(options.dir, checkpoint, options.scene, options.force);
  LoadedWorld loaded = world_from_checkpoint(checkpoint, true, packed);
  const std::filesystem::path stats = options.dir / "stats.json";
  // The frames show the curve the solver kept the elements apart on: an older folder's own.
  if (const std::optional<int> curve = packed_motion_curve(stats, packed.text)) {
    loaded.world.params.forces.motion_curve = *curve;
    std::cerr << "animpak: " << stats.string() << " says an older animpak packed this folder, on "
              << (*curve == 1 ? "the monotone cubic" : "straight lines") << " between slices; rendering on it ("
              << "\"motion_curve\": " << *curve << "; the scene's params can name another)\n";
  }
  if (!still) still = stored_still_reference(stats);
  std::string note, still_line;
  Rendered rendered =
      render_frames(loaded.world, options.dir, options.frames,
                    [&](const PackingQuality& frames, const std::filesystem::path& scratch) {
                      if (options.contact_plot) write_contact_plot(frames.frames, scratch / "contact.png");
                      if (frames.frames.empty()) return;
                      note = update_stats_quality(stats, scratch / "stats.json", checkpoint, loaded.world, frames);
                      if (still) still_line = add_still_reference(scratch / "stats.json", *still, frames);
                    });
  const PackingQuality& quality = rendered.quality;
  removed.insert(removed.end(), rendered.removed.begin(), rendered.removed.end());
  std::cerr << "animpak: rendered " << quality.frames.size() << " frames into " << options.dir.string() << "\n";
  if (!note.empty()) std::cerr << "animpak: " << note << "\n";
  std::cerr << written_files(options.dir, WrittenBy::render, removed);
  std::cout << quality_lines(quality) << still_line;
  return 0;
}

}  // namespace animpak::cli

int main(int argc, char** argv) {
  return animpak::cli::run(argc, argv, std::make_unique<animpak::cli::RenderingFrontend>());
}
