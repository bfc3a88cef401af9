// state.bin: everything needed to render or resume a packing. The scene text travels inside, so the
// world can be rebuilt bit-identically (set-up is deterministic for scene + seed). It records nothing
// about the device, so the reference and a bit-identical device write byte-identical files;
// stats.json says which device ran.
//
// Layout (little-endian): "ANIMPAKS" magic, u32 version, then length-prefixed fields, the SimState
// arrays, and an FNV-1a 64 checksum of everything before it.
#pragma once

#include <filesystem>
#include <string>

#include "animpak/state.hpp"

namespace animpak {

inline constexpr std::uint32_t checkpoint_version = 4;

struct Checkpoint {
  std::string scene_text;            ///< the scene file's contents when the packing started
  std::filesystem::path scene_file;  ///< absolute in memory; stored relative to the state's folder
  std::uint64_t seed = 0;            ///< the seed actually used (scene or --seed)
  std::string stop_reason;           ///< "running" when interrupted or still going
  SimState state;
};

/// Writes to `file` through a temporary file and a rename, so a crash never leaves half a state.
void write_checkpoint(const std::filesystem::path& file, const Checkpoint& checkpoint);

/// InputError naming the file for a missing, foreign, newer-version, truncated or corrupted state.
Checkpoint read_checkpoint(const std::filesystem::path& file);

}  // namespace animpak
