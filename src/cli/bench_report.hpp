// The plot of `animpak bench`'s rows (animpak/bench.hpp), drawn only by `animpak` (bench_plot.cpp).
#pragma once

#include <filesystem>
#include <vector>

#include "animpak/bench.hpp"

namespace animpak::cli {

/// ms per step against vertices, one line per device and synthetic series, example and --scene scenes
/// as labelled squares; axes with ticks and a legend.
void write_bench_plot(const std::vector<BenchRow>& rows, const std::filesystem::path& file);

}  // namespace animpak::cli
