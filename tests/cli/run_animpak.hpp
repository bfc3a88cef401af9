// Runs the animpak executables as a user would and captures what they print.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "temp_dir.hpp"

struct CommandResult {
  int code = -1;
  std::string out, err;
};

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// `args` is appended to the executable's path as is (tests pass only their own, shell-safe words);
/// `environment`, e.g. "ANIMPAK_KERNEL_DIR=/tmp/k", is put before it, for this command only.
inline CommandResult run_executable(const std::string& executable, const std::string& args,
                                    const std::string& environment = {}) {
  // The captured output lives only as long as this call.
  const animpak::test::TempDir dir("animpak-cli-");
  const auto out = dir / "out.txt", err = dir / "err.txt";
  const std::string command = environment + " " + executable + " " + args + " </dev/null >" + out.string() + " 2>" + err.string();
  const int status = std::system(command.c_str());
  CommandResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

/// The full `animpak`, with the rendering commands.
inline CommandResult run_animpak(const std::string& args, const std::string& environment = {}) {
  return run_executable(ANIMPAK_EXE, args, environment);
}

/// The solver-only `animpak-solve`, linked without Cairo and OpenImageIO.
inline CommandResult run_animpak_solve(const std::string& args, const std::string& environment = {}) {
  return run_executable(ANIMPAK_SOLVE_EXE, args, environment);
}

inline std::string shapes_dir() { return std::string(ANIMPAK_SOURCE_DIR) + "/examples/shapes"; }
