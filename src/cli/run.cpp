#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

#include "animpak/error.hpp"
#include "commands.hpp"

namespace animpak::cli {
namespace {

int fail(ExitCode code, const std::string& message) {
  std::cerr << "animpak: error: " << message << "\n";
  return static_cast<int>(code);
}

}  // namespace

int run(int argc, char** argv) {
  CLI::App app{"animpak: packs animated vector elements into a container (AnimationPak)", "animpak"};
  app.set_version_flag("--version", "animpak 0.1.0");
  app.require_subcommand(1);
  app.footer("Exit codes: 0 success, 1 usage error, 2 bad input, 3 internal error.");

  InspectOptions inspect_options;
  CLI::App* inspect_cmd = app.add_subcommand(
      "inspect", "Build the spacetime elements of a scene or one art file and print their sizes (paper Table 1)");
  inspect_cmd->add_option("FILE", inspect_options.file, "scene (.json) or art file (.svg, .path)")->required();
  inspect_cmd->add_option("--out", inspect_options.out, "write PNG pictures of every element into this folder");
  inspect_cmd->add_flag("--json", inspect_options.json, "print the counts as JSON");
  inspect_cmd->add_option("--slices", inspect_options.slices, "number of slices n_s (overrides the scene)")
      ->check(CLI::Range(2, 1000));
  inspect_cmd->add_option("--size", inspect_options.picture_size, "picture height in pixels")
      ->check(CLI::Range(16, 8192));

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version arrive here too, with exit code 0.
    const int code = app.exit(e);
    return code == 0 ? 0 : static_cast<int>(ExitCode::usage);
  }

  try {
    if (inspect_cmd->parsed()) return inspect(inspect_options);
    return fail(ExitCode::usage, "no command given; see animpak --help");
  } catch (const UsageError& e) {
    return fail(ExitCode::usage, e.what());
  } catch (const InputError& e) {
    return fail(ExitCode::bad_input, e.what());
  } catch (const std::bad_alloc&) {
    return fail(ExitCode::internal, "out of memory; try a smaller scene (fewer slices or elements)");
  } catch (const std::exception& e) {
    return fail(ExitCode::internal, std::string("internal error: ") + e.what() +
                                        "; please report it with the command and input files");
  }
}

}  // namespace animpak::cli
