// Command-line checks the parser does not make itself, shared by the commands of both executables.
#pragma once

#include <CLI/CLI.hpp>

namespace animpak::cli {

/// A finite number: CLI::Range lets NaN through (it compares false with both bounds), and `--fps nan`
/// wrote `"fr":nan` into animation.json, which is not JSON. Put before a Range: `finite_number() & Range`.
const CLI::Validator& finite_number();

}  // namespace animpak::cli
