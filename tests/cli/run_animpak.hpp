// Runs the animpak executables as a user would and captures what they print.
#pragma once

#include <sys/wait.h>

#include <cstdio>
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

/// LeakSanitizer's own crash at exit (its stop-the-world tracer faulting while it suspends the
/// process's threads; google/sanitizers#1353), not a leak report: under the sanitizer build the animpak
/// executables leave PoCL's worker threads running at exit, and the tracer crashes on them now and then.
inline bool is_leak_sanitizer_tracer_crash(const std::string& err) {
  return err.find("Tracer caught signal") != std::string::npos &&
         err.find("LeakSanitizer has encountered a fatal error") != std::string::npos;
}

/// One run of `command` (stdin from /dev/null), with its exit code and what it printed.
inline CommandResult run_command_once(const std::string& command_line) {
  // The captured output lives only as long as this call.
  const animpak::test::TempDir dir("animpak-cli-");
  const auto out = dir / "out.txt", err = dir / "err.txt";
  const std::string command = command_line + " </dev/null >" + out.string() + " 2>" + err.string();
  const int status = std::system(command.c_str());
  CommandResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

/// `command_line` run as a user would; a run that ended in LeakSanitizer's tracer crash is run once more
/// (a leak LeakSanitizer reports, or any other failure, is returned as it is). The retry is said on
/// stderr, so a test log shows it.
inline CommandResult run_command(const std::string& command_line) {
  CommandResult r = run_command_once(command_line);
  if (is_leak_sanitizer_tracer_crash(r.err)) {
    std::fprintf(stderr, "run_animpak: LeakSanitizer's tracer crashed at exit (not a leak); running again: %s\n",
                 command_line.c_str());
    r = run_command_once(command_line);
  }
  return r;
}

/// `args` is appended to the executable's path as is (tests pass only their own, shell-safe words);
/// `environment`, e.g. "ANIMPAK_KERNEL_DIR=/tmp/k", is put before it, for this command only.
inline CommandResult run_executable(const std::string& executable, const std::string& args,
                                    const std::string& environment = {}) {
  return run_command(environment + " " + executable + " " + args);
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
