#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "animpak/error.hpp"
#include "animpak/opencl.hpp"
#include "animpak/version.hpp"
#include "commands.hpp"
#include "frontend.hpp"

namespace animpak::cli {
namespace {

int fail(const std::string& program, ExitCode code, const std::string& message) {
  std::cerr << program << ": error: " << message << "\n";
  return static_cast<int>(code);
}

}  // namespace

int run(int argc, char** argv, std::unique_ptr<Frontend> frontend) {
  const std::string program = frontend->name();
  CLI::App app{frontend->description(), program};
  app.set_version_flag("--version",
                       program + " " + std::string(animpak_version) + " (commit " + std::string(build_commit()) + ")");
  app.require_subcommand(1);
  app.footer("Exit codes: 0 success, 1 usage error, 2 bad input, 3 internal error, 4 validate found a device "
             "that differs from the reference, 130 pack interrupted by Ctrl-C (state.bin holds the state so far; "
             "pack --resume DIR continues it).");

  PackOptions pack_options;
  CLI::App* pack_cmd = app.add_subcommand("pack", "Pack a scene's animated elements into its container and render it");
  pack_cmd->add_option("SCENE", pack_options.scene, "scene file (.json)");
  pack_cmd->add_option("--out", pack_options.out, "folder for state.bin, stats.json and the frames");
  pack_cmd->add_option("--resume", pack_options.resume,
                       "continue the interrupted packing in this folder (with the scene and seed it started with)");
  pack_cmd->add_flag("--force", pack_options.force, "overwrite the packing already in --out DIR");
  pack_cmd->add_option("--seed", pack_options.seed, "seed (overrides the scene's)");
  pack_cmd->add_option("--max-iterations", pack_options.max_iterations, "stop after this many iterations")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{100000000}));
  pack_cmd->add_option("--device", pack_options.device,
                       "solver: 'reference', or part of an OpenCL device's name (pocl, nvidia; see animpak devices); "
                       "default: the first GPU, else PoCL, else the reference");
  pack_cmd->add_option("--grid-sort", pack_options.grid_sort,
                       "where the collision grid is sorted on an OpenCL device: auto (device on GPUs, host on CPU "
                       "devices), host or device; the results are identical")
      ->check(CLI::IsMember({"auto", "host", "device"}));

  DevicesOptions devices_options;
  CLI::App* devices_cmd =
      app.add_subcommand("devices", "List the OpenCL platforms and devices and whether animpak's kernels build on each");
  devices_cmd->add_flag("--verbose", devices_options.verbose, "print every device's kernel build log");

  ValidateOptions validate_options;
  CLI::App* validate_cmd = app.add_subcommand(
      "validate", "Step the reference and an OpenCL device side by side and compare every force and state bit for bit");
  validate_cmd->add_option("SCENE", validate_options.scene, "scene file (.json)")->required();
  validate_cmd->add_option("--device", validate_options.device,
                           "part of an OpenCL device's name (pocl, nvidia; see animpak devices); default: the device "
                           "pack would choose");
  validate_cmd->add_option("--steps", validate_options.steps, "steps to compare")->check(CLI::Range(1, 100000));
  validate_cmd->add_flag("--all-devices", validate_options.all_devices, "every OpenCL device, one summary row each");
  validate_cmd->add_flag("--json", validate_options.json, "print the results as JSON");
  validate_cmd->add_option("--grid-sort", validate_options.grid_sort, "auto, host or device (see pack --grid-sort)")
      ->check(CLI::IsMember({"auto", "host", "device"}));

  BenchOptions bench_options;
  CLI::App* bench_cmd = app.add_subcommand(
      "bench", "Time solver steps per phase on synthetic worlds and the example scenes, or on your own scenes");
  bench_cmd->add_option("--device", bench_options.devices,
                         "devices to time beside the reference: name fragments (pocl, nvidia), see animpak devices")
      ->delimiter(',');
  bench_cmd->add_option("--series", bench_options.series,
                        "synthetic worlds: constant (density: the container grows with the copies; the default), "
                        "dense (more copies in the same container) or both; with --scene, none unless given")
      ->check(CLI::IsMember({"constant", "dense", "both"}));
  bench_cmd->add_option("--scene", bench_options.scenes,
                        "time this scene file too (repeatable); without --series, instead of the synthetic worlds "
                        "and the example scenes");
  bench_cmd->add_option("--state", bench_options.states,
                        "time steps from this packed state: a folder written by pack, or its state.bin "
                        "(repeatable); without --series, instead of the synthetic worlds and the example scenes");
  bench_cmd->add_option("--sizes", bench_options.sizes, "target vertex counts of the synthetic worlds")
      ->delimiter(',')
      ->check(CLI::Range(100, 10000000));
  bench_cmd->add_option("--steps", bench_options.steps, "timed steps per world")->check(CLI::Range(1, 100000));
  bench_cmd->add_option("--warmup", bench_options.warmup, "untimed steps before timing")->check(CLI::Range(0, 100000));
  bench_cmd->add_option("--repeat", bench_options.repeat,
                        "rounds per world: each device timed once per round, in turn; rows give the median round, "
                        "its spread (slowest - fastest) and the median of the rounds' speedups")
      ->check(CLI::Range(1, 1000));
  bench_cmd->add_option("--slices", bench_options.slices, "slices n_s of the dense worlds, and of the constant series at 45 copies (it "
                        "gives larger worlds more, docs/benchmark.md)")->check(CLI::Range(2, 1000));
  bench_cmd->add_option("--examples", bench_options.examples, "the examples folder (element art, example scenes)");
  bench_cmd->add_flag("!--no-example-scenes", bench_options.example_scenes, "time only the synthetic worlds");
  bench_cmd->add_option("--json", bench_options.json, "write the results as JSON");
  bench_cmd->add_option("--grid-sort", bench_options.grid_sort,
                        "auto, host or device (see pack --grid-sort), or both: time each OpenCL device with each")
      ->check(CLI::IsMember({"auto", "host", "device", "both"}));
  ParamsOptions params_options;
  CLI::App* params_cmd = app.add_subcommand(
      "params", "List the constants a scene's \"params\" may override, with their defaults and ranges");
  params_cmd->add_flag("--markdown", params_options.markdown,
                       "print the table of docs/parameters.md, with the paper's values");
  CLI::App* schema_cmd =
      app.add_subcommand("schema", "Print the JSON Schema of the scene file (docs/scene.schema.json)");
  frontend->add_commands(app, *pack_cmd, *bench_cmd);

  try {
    app.parse(argc, argv);
    if (pack_cmd->parsed()) {
      std::string refused;
      const std::pair<bool, const char*> options_given[] = {{!pack_options.scene.empty(), "SCENE"},
                                                            {!pack_options.out.empty(), "--out"},
                                                            {pack_options.seed.has_value(), "--seed"},
                                                            {pack_options.force, "--force"}};
      for (const auto& [given, name] : options_given)
        if (pack_options.resume && given) refused += (refused.empty() ? "" : ", ") + std::string(name);
      if (!refused.empty())
        throw CLI::ValidationError("--resume", refused + " cannot apply to a resumed packing: it keeps the folder, "
                                               "scene and seed it started with (state.bin)");
      if (!pack_options.resume && (pack_options.scene.empty() || pack_options.out.empty()))
        throw CLI::ValidationError("SCENE", "pack needs SCENE and --out DIR (or --resume DIR)");
    }
  } catch (const CLI::ParseError& e) {
    // --help and --version arrive here too, with exit code 0.
    const int code = app.exit(e);
    return code == 0 ? 0 : static_cast<int>(ExitCode::usage);
  }

  try {
    pack_options.program = program;
    if (pack_cmd->parsed()) return pack(pack_options, frontend->frame_renderer());
    if (bench_cmd->parsed()) return bench(bench_options, frontend->bench_plotter());
    if (devices_cmd->parsed()) return devices(devices_options);
    if (validate_cmd->parsed()) return validate(validate_options);
    if (params_cmd->parsed()) return params(params_options);
    if (schema_cmd->parsed()) return schema();
    if (const std::optional<int> code = frontend->run_own_command()) return *code;
    return fail(program, ExitCode::usage, "no command given; see " + program + " --help");
  } catch (const UsageError& e) {
    return fail(program, ExitCode::usage, e.what());
  } catch (const InputError& e) {
    return fail(program, ExitCode::bad_input, e.what());
  } catch (const OpenclError& e) {
    return fail(program, ExitCode::internal, std::string("OpenCL: ") + e.what() + "\n(try --device reference)");
  } catch (const std::bad_alloc&) {
    return fail(program, ExitCode::internal, "out of memory; try a smaller scene (fewer slices or elements)");
  } catch (const std::exception& e) {
    return fail(program, ExitCode::internal, std::string("internal error: ") + e.what() +
                                                 "; please report it with the command and input files");
  }
}

}  // namespace animpak::cli
