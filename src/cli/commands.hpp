// The subcommands of `animpak`. Each returns an exit code; errors are thrown and mapped in run().
#pragma once

#include <filesystem>
#include <optional>

namespace animpak::cli {

struct InspectOptions {
  std::filesystem::path file;           ///< a scene (.json) or one art file (.svg, .path)
  std::optional<std::filesystem::path> out;  ///< folder for the PNG pictures
  bool json = false;                    ///< print counts as JSON on stdout
  std::optional<int> slices;            ///< override n_s
  int picture_size = 512;
};

int inspect(const InspectOptions& options);

/// Parses the command line and runs the chosen subcommand; never throws.
int run(int argc, char** argv);

}  // namespace animpak::cli
