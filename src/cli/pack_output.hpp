// What `pack` and `render` share: the world rebuilt from a checkpoint, and stats.json. Drawing the frames
// lives in render_commands.cpp, so that animpak-solve links no rendering library.
#pragma once

#include "animpak/checkpoint.hpp"
#include "animpak/render.hpp"
#include "animpak/run.hpp"
#include "commands.hpp"

namespace animpak::cli {

struct LoadedWorld {
  World world;
  double setup_seconds = 0.0;
};

/// Rebuilds the world from the scene text inside the checkpoint (set-up is deterministic), and with
/// `with_state` puts the checkpoint's state in it after checking that the sizes match.
LoadedWorld world_from_checkpoint(const Checkpoint& checkpoint, bool with_state);

struct PackReport {
  const World& world;
  const RunResult& result;
  const PhaseTimes& times;
  const Checkpoint& checkpoint;
  std::vector<FrameMetrics> frames;
  double setup_seconds = 0.0;
  std::string device;  ///< the backend's name
  std::string driver;  ///< the device's driver and platform version
};

void write_stats(const std::filesystem::path& file, const PackReport& report);

}  // namespace animpak::cli
