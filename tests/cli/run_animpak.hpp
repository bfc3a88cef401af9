// Runs the animpak executable as a user would and captures what it prints.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

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
inline CommandResult run_animpak(const std::string& args, const std::string& environment = {}) {
  static int counter = 0;
  const auto dir = std::filesystem::temp_directory_path() / ("animpak-cli-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto out = dir / ("out" + std::to_string(counter) + ".txt");
  const auto err = dir / ("err" + std::to_string(counter++) + ".txt");
  const std::string command = environment + " " + std::string(ANIMPAK_EXE) + " " + args + " </dev/null >" + out.string() + " 2>" + err.string();
  const int status = std::system(command.c_str());
  CommandResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

inline std::string shapes_dir() { return std::string(ANIMPAK_SOURCE_DIR) + "/examples/shapes"; }
