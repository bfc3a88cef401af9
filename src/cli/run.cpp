#include <CLI/CLI.hpp>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <exception>
#include <filesystem>
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
#include "validators.hpp"

namespace animpak::cli {

const CLI::Validator& finite_number() {
  static const CLI::Validator validator(
      [](std::string& argument) {
        double value = 0.0;
        const char* end = argument.data() + argument.size();
        const auto [stop, error] = std::from_chars(argument.data(), end, value);
        return error == std::errc() && stop == end && std::isfinite(value)
                   ? std::string()
                   : "expected a finite number, got " + argument;
      },
      "FINITE");
  return validator;
}

namespace {

int fail(const std::string& program, ExitCode code, const std::string& message) {
  std::cerr << program << ": error: " << message << "\n";
  return static_cast<int>(code);
}

// Every command's options, filled by parsing, and the subcommand that holds them.
struct CommandLine {
  PackOptions pack;
  DevicesOptions devices;
  ValidateOptions validate;
  BenchOptions bench;
  ParamsOptions params;
  CLI::App *pack_cmd = nullptr, *devices_cmd = nullptr, *validate_cmd = nullptr, *bench_cmd = nullptr,
           *params_cmd = nullptr, *schema_cmd = nullptr;
};

void add_pack_command(CLI::App& app, CommandLine& cl) {
  cl.pack_cmd = app.add_subcommand("pack", "Pack a scene's animated elements into its container and render it");
  cl.pack_cmd->add_option("SCENE", cl.pack.scene, "scene file (.json)");
  cl.pack_cmd->add_option("--out", cl.pack.out, "folder for state.bin, stats.json and the frames");
  cl.pack_cmd->add_option("--resume", cl.pack.resume,
                          "continue the interrupted packing in this folder (with the scene and seed it started with)");
  cl.pack_cmd->add_flag("--force", cl.pack.force, "overwrite the packing already in --out DIR");
  cl.pack_cmd->add_flag("--still", cl.pack.still,
                        "pack the same elements standing still (no animation, guided elements as ordinary copies, "
                        "at most 12 slices): the reference an animated packing's coverage is judged against");
  cl.pack_cmd->add_flag("--preview", cl.pack.preview,
                        "stop when the coarse level (fewer slices) stops, and render it: the composition in a "
                        "fraction of the packing's time; `pack --resume DIR` goes on to the scene's slices");
  cl.pack_cmd->add_option("--still-reference", cl.pack.still_reference,
                          "a folder `pack --still` wrote for this scene: stats.json then carries its coverage "
                          "beside this packing's, and a `still:` line compares them");
  cl.pack_cmd->add_flag("--verbose", cl.pack.verbose,
                        "progress with the overlapping and outside vertex counts and the range of g");
  cl.pack_cmd->add_flag("--profile", cl.pack.profile,
                        "at the end, the time of each phase of a step and of each OpenCL kernel (also in "
                        "stats.json, \"kernels\")");
  // A seed is a whole number in [0, 2^64 - 1], written in decimal digits: the conversion would otherwise take
  // -1, 2^64 and 1e23 and turn them silently into 18446744073709551615.
  cl.pack_cmd->add_option("--seed", cl.pack.seed, "seed (overrides the scene's): a whole number from 0 to 2^64 - 1")
      ->check(CLI::Validator(
          [](std::string& argument) {
            std::uint64_t value = 0;
            const char* end = argument.data() + argument.size();
            const auto [stop, error] = std::from_chars(argument.data(), end, value);
            const bool digits = !argument.empty() && std::isdigit(static_cast<unsigned char>(argument.front()));
            return digits && error == std::errc() && stop == end
                       ? std::string()
                       : "expected a whole number from 0 to 18446744073709551615, got " + argument;
          },
          "UINT64"));
  cl.pack_cmd
      ->add_option("--checkpoint-every", cl.pack.checkpoint_seconds,
                   "seconds between the states saved during the run, which a killed pack resumes from (0: at every "
                   "statistics check)")
      ->check(finite_number() & CLI::Range(0.0, 86400.0));
  cl.pack_cmd->add_option("--max-iterations", cl.pack.max_iterations, "stop after this many iterations")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{100000000}));
  cl.pack_cmd->add_option(
      "--device", cl.pack.device,
      "solver: 'reference', or part of an OpenCL device's name (pocl, nvidia; see animpak devices); "
      "default: the first GPU, else PoCL, else the reference");
  cl.pack_cmd
      ->add_option("--grid-sort", cl.pack.grid_sort,
                   "where an OpenCL device's grids are built (the collision grid's sort, the overlap test's "
                   "broadphase, the repulsion order): auto (device on GPUs, host on CPU devices), host or device; the "
                   "results are identical")
      ->check(CLI::IsMember({"auto", "host", "device"}));
}

void add_devices_and_validate_commands(CLI::App& app, CommandLine& cl) {
  cl.devices_cmd = app.add_subcommand(
      "devices", "List the OpenCL platforms and devices and whether animpak's kernels build on each");
  cl.devices_cmd->add_flag("--verbose", cl.devices.verbose, "print every device's kernel build log");

  cl.validate_cmd = app.add_subcommand(
      "validate", "Step the reference and an OpenCL device side by side and compare every force and state bit for bit");
  cl.validate_cmd->add_option("SCENE", cl.validate.scene, "scene file (.json)")->required();
  cl.validate_cmd->add_option(
      "--device", cl.validate.device,
      "part of an OpenCL device's name (pocl, nvidia; see animpak devices); default: the device "
      "pack would choose");
  cl.validate_cmd->add_option("--steps", cl.validate.steps, "steps to compare")->check(CLI::Range(1, 100000));
  cl.validate_cmd->add_flag("--all-devices", cl.validate.all_devices, "every OpenCL device, one summary row each");
  cl.validate_cmd->add_flag("--json", cl.validate.json, "print the results as JSON");
  cl.validate_cmd->add_option("--grid-sort", cl.validate.grid_sort, "auto, host or device (see pack --grid-sort)")
      ->check(CLI::IsMember({"auto", "host", "device"}));
}

void add_bench_command(CLI::App& app, CommandLine& cl) {
  cl.bench_cmd = app.add_subcommand(
      "bench", "Time solver steps per phase on synthetic worlds and the example scenes, or on your own scenes");
  cl.bench_cmd
      ->add_option("--device", cl.bench.devices,
                   "devices to time beside the reference: name fragments (pocl, nvidia), see animpak devices")
      ->delimiter(',');
  cl.bench_cmd
      ->add_option("--series", cl.bench.series,
                   "synthetic worlds: constant (density: the container grows with the copies; the default), "
                   "dense (more copies in the same container) or both; with --scene, none unless given")
      ->check(CLI::IsMember({"constant", "dense", "both"}));
  cl.bench_cmd->add_option("--scene", cl.bench.scenes,
                           "time this scene file too (repeatable); without --series, instead of the synthetic worlds "
                           "and the example scenes");
  cl.bench_cmd->add_option("--state", cl.bench.states,
                           "time steps from this packed state: a folder written by pack, or its state.bin "
                           "(repeatable); without --series, instead of the synthetic worlds and the example scenes");
  cl.bench_cmd->add_option("--sizes", cl.bench.sizes, "target vertex counts of the synthetic worlds")
      ->delimiter(',')
      ->check(CLI::Range(100, 10000000));
  cl.bench_cmd->add_option("--steps", cl.bench.steps, "timed steps per world")->check(CLI::Range(1, 100000));
  cl.bench_cmd->add_option("--warmup", cl.bench.warmup, "untimed steps before timing")->check(CLI::Range(0, 100000));
  cl.bench_cmd
      ->add_option("--repeat", cl.bench.repeat,
                   "rounds per world: each device timed once per round, in turn; rows give the median round, "
                   "its spread (slowest - fastest) and the median of the rounds' speedups")
      ->check(CLI::Range(1, 1000));
  cl.bench_cmd
      ->add_option("--slices", cl.bench.slices,
                   "slices n_s of the dense worlds, and of the constant series at 45 copies (it "
                   "gives larger worlds more, docs/benchmark.md)")
      ->check(CLI::Range(2, 1000));
  cl.bench_cmd->add_option("--examples", cl.bench.examples, "the examples folder (element art, example scenes)");
  cl.bench_cmd->add_flag("!--no-example-scenes", cl.bench.example_scenes, "time only the synthetic worlds");
  cl.bench_cmd->add_option("--json", cl.bench.json, "write the results as JSON");
  cl.bench_cmd
      ->add_option("--grid-sort", cl.bench.grid_sort,
                   "auto, host or device (see pack --grid-sort), or both: time each OpenCL device with each")
      ->check(CLI::IsMember({"auto", "host", "device", "both"}));
}

void add_reference_commands(CLI::App& app, CommandLine& cl) {
  cl.params_cmd = app.add_subcommand(
      "params", "List the constants a scene's \"params\" may override, with their defaults and ranges");
  cl.params_cmd->add_flag("--markdown", cl.params.markdown,
                          "print the table of docs/parameters.md, with the paper's values");
  cl.schema_cmd = app.add_subcommand("schema", "Print the JSON Schema of the scene file (docs/scene.schema.json)");
}

// What the parser cannot say itself: a resume keeps the scene, folder and seed it started with.
void check_pack_options(const PackOptions& pack) {
  std::string refused;
  const std::pair<bool, const char*> options_given[] = {{!pack.scene.empty(), "SCENE"},
                                                        {!pack.out.empty(), "--out"},
                                                        {pack.seed.has_value(), "--seed"},
                                                        {pack.force, "--force"},
                                                        {pack.still, "--still"}};
  for (const auto& [given, name] : options_given)
    if (pack.resume && given) refused += (refused.empty() ? "" : ", ") + std::string(name);
  if (!refused.empty())
    throw CLI::ValidationError("--resume", refused +
                                               " cannot apply to a resumed packing: it keeps the folder, "
                                               "scene and seed it started with (state.bin)");
  if (!pack.resume && (pack.scene.empty() || pack.out.empty()))
    throw CLI::ValidationError("SCENE", "pack needs SCENE and --out DIR (or --resume DIR)");
}

// The chosen command, with every error mapped to its exit code and one line.
int run_command(const std::string& program, CommandLine& cl, Frontend& frontend) {
  try {
    cl.pack.program = program;
    if (cl.pack_cmd->parsed()) return pack(cl.pack, frontend.frame_renderer());
    if (cl.bench_cmd->parsed()) return bench(cl.bench, frontend.bench_plotter());
    if (cl.devices_cmd->parsed()) return devices(cl.devices);
    if (cl.validate_cmd->parsed()) return validate(cl.validate);
    if (cl.params_cmd->parsed()) return params(cl.params);
    if (cl.schema_cmd->parsed()) return schema();
    if (const std::optional<int> code = frontend.run_own_command()) return *code;
    return fail(program, ExitCode::usage, "no command given; see " + program + " --help");
  } catch (const UsageError& e) {
    return fail(program, ExitCode::usage, e.what());
  } catch (const InputError& e) {
    return fail(program, ExitCode::bad_input, e.what());
  } catch (const std::filesystem::filesystem_error& e) {
    // The folder or disk, not animpak: a rename across a link, a file where a folder should be.
    return fail(program, ExitCode::bad_input,
                (e.path1().empty() ? std::string() : e.path1().string() + ": ") + e.code().message() +
                    "; check the folder (permissions, free space, nothing in the way) and run the command again");
  } catch (const OpenclError& e) {
    return fail(program, ExitCode::internal, std::string("OpenCL: ") + e.what() + "\n(try --device reference)");
  } catch (const std::bad_alloc&) {
    return fail(program, ExitCode::internal, "out of memory; try a smaller scene (fewer slices or elements)");
  } catch (const std::exception& e) {
    return fail(program, ExitCode::internal,
                std::string("internal error: ") + e.what() + "; please report it with the command and input files");
  }
}

}  // namespace

int run(int argc, char** argv, std::unique_ptr<Frontend> frontend) {
  const std::string program = frontend->name();
  CLI::App app{frontend->description(), program};
  app.set_version_flag("--version",
                       program + " " + std::string(animpak_version) + " (commit " + std::string(build_commit()) + ")");
  app.require_subcommand(1);
  app.footer(
      "Exit codes: 0 success, 1 usage error, 2 bad input or environment (a file, a folder, a full disk; a "
      "sweep's run that failed), 3 internal error, 4 validate found a device that differs from the reference, "
      "130 pack or sweep interrupted by Ctrl-C (143 by SIGTERM, 129 by SIGHUP; state.bin holds the state so "
      "far; pack --resume DIR, or the same sweep, continues it).");

  // Every option's default in --help; subcommands copy this from the app when they are added.
  app.option_defaults()->always_capture_default();
  CommandLine cl;
  add_pack_command(app, cl);
  add_devices_and_validate_commands(app, cl);
  add_bench_command(app, cl);
  add_reference_commands(app, cl);
  frontend->add_commands(app, *cl.pack_cmd, *cl.bench_cmd);
  try {
    app.parse(argc, argv);
    if (cl.pack_cmd->parsed()) check_pack_options(cl.pack);
  } catch (const CLI::ParseError& e) {
    // --help and --version arrive here too, with exit code 0.
    const int code = app.exit(e);
    return code == 0 ? 0 : static_cast<int>(ExitCode::usage);
  }
  return run_command(program, cl, *frontend);
}

}  // namespace animpak::cli
