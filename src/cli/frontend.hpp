// What sets `animpak` and the solver-only `animpak-solve` apart. Both parse their command line in run.cpp
// (the animpak_cli library); each executable's main() hands run() its own Frontend: render_commands.cpp
// (inspect, render, frames after pack, bench --plot; links Cairo and OpenImageIO) or solver_commands.cpp
// (nothing that draws, so the binary runs where only an OpenCL driver is installed). CMake picks the file,
// not #ifdefs, and the library never calls into an executable.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "commands.hpp"

namespace CLI {
class App;
}

namespace animpak::cli {

class Frontend {
 public:
  virtual ~Frontend() = default;

  /// The program's name, as in --help, --version and error messages.
  virtual std::string name() const = 0;
  virtual std::string description() const = 0;

  /// Adds this executable's own commands to `app` and its own options to the shared `pack` and `bench`.
  virtual void add_commands(CLI::App& app, CLI::App& pack, CLI::App& bench) = 0;

  /// Runs this executable's own command when the command line chose one; nullopt otherwise.
  virtual std::optional<int> run_own_command() = 0;

  /// What pack does after writing state.bin; read after parsing, so it follows the options.
  virtual FrameRenderer frame_renderer() const = 0;
  /// What bench does with its rows beside the table and JSON; empty when nothing.
  virtual BenchPlotter bench_plotter() const = 0;
};

}  // namespace animpak::cli
