// state.bin: everything needed to render or resume a packing. The scene text travels inside, so the
// world can be rebuilt bit-identically (set-up is deterministic for scene + seed). It records nothing
// about the device, so the reference and a bit-identical device write byte-identical files;
// stats.json says which device ran.
//
// Layout (little-endian): "ANIMPAKS" magic, u32 version, then length-prefixed fields, the SimState
// arrays, and the SHA-256 of everything before it as 64 hex digits. Reading checks the checksum and
// every value (finite, in range, marks before their iteration), so a damaged or made-up state is refused,
// never resumed or drawn.
#pragma once

#include <filesystem>
#include <string>

#include "animpak/state.hpp"

namespace animpak {

inline constexpr std::uint32_t checkpoint_version = 6;

struct Checkpoint {
  std::string scene_text;            ///< the scene file's contents when the packing started
  std::filesystem::path scene_file;  ///< absolute in memory; stored relative to the state's folder
  std::uint64_t seed = 0;            ///< the seed actually used (scene or --seed)
  std::string stop_reason;           ///< "running" when interrupted or still going
  /// The level the state is at (docs/parameters.md, "Coarse to fine"): the slices per element of the scene's
  /// coarse level (coarse_slices), or 0 for the scene's own slices. A state stopped at its coarse level is a
  /// preview unless `pack` goes on to refine it.
  std::int32_t level_slices = 0;
  SimState state;
};

/// Writes to `file` through a checked, flushed temporary file and a rename (write_file_atomically), so
/// a crash or a full disk never leaves half a state. The scene's path is stored relative to `home`, the
/// folder the state is read from in the end (default: `file`'s own), so a state written aside and moved
/// there finds its scene.
void write_checkpoint(const std::filesystem::path& file, const Checkpoint& checkpoint,
                      const std::filesystem::path& home = {});

/// InputError naming the file for a missing, linked, special, foreign, older- or newer-version,
/// truncated, corrupted or out-of-range state. A relative scene path is resolved from `home` (default:
/// `file`'s own folder), as write_checkpoint stored it.
Checkpoint read_checkpoint(const std::filesystem::path& file, const std::filesystem::path& home = {});

}  // namespace animpak
