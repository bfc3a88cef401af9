// What makes a folder `animpak pack` wrote hold one run and travel (docs/cli.md, "The output folder"): input/
// carries the scene and every art file it references, with their SHA-256 in input/manifest.json, and a
// render is written into a scratch folder and swapped in whole, replacing every file of the run before.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "animpak/checkpoint.hpp"
#include "animpak/scene_spec.hpp"

namespace animpak::cli {

/// The scene and its art as read when packing, kept in memory until state.bin is written beside them.
struct InputSnapshot {
  struct Art {
    std::string written;  ///< the reference as written in the scene
    std::filesystem::path source;
    std::string bytes;
  };
  std::filesystem::path scene_file;
  std::string scene_text;
  std::vector<Art> art;  ///< container first, then the elements, each reference once
};

/// Parses `text` (the scene at `file`) and reads every art file it references.
InputSnapshot snapshot_inputs(const std::filesystem::path& file, const std::string& text);

/// InputError when DIR/input exists but animpak did not write it (no manifest): checked before a pack
/// starts, so that the folder in the way costs no packing.
void check_inputs_writable(const std::filesystem::path& dir);

/// Replaces DIR/input/ with the snapshot: the scene, its art under art/, and manifest.json.
void write_inputs(const std::filesystem::path& dir, const InputSnapshot& snapshot);

/// The scene a packed folder is rebuilt from, and where its art is read.
struct PackedScene {
  std::string text;
  std::filesystem::path file;  ///< for messages; relative art references start at its folder
  ArtLocator locate;           ///< empty: the art beside `file`
};

/// Without `scene`: DIR/input/'s copies, checked against their hashes, or for a folder without input/ the
/// art beside the scene path state.bin records. With `scene` (render --scene): that file and the art beside
/// it, which must be what was packed (the scene text, the manifest's hashes) unless `force`.
PackedScene packed_scene(const std::filesystem::path& dir, const Checkpoint& checkpoint,
                         const std::optional<std::filesystem::path>& scene = {}, bool force = false);

/// Removes the files a render writes (frames/frame_NNNN.png and .svg, animation.gif, .mp4, .json, .lottie,
/// .svg, contact.png) and the pictures made from them (report.html, trajectory.svg)
/// from `dir`, and frames/ when that leaves it empty; nothing else.
void remove_rendered(const std::filesystem::path& dir);

/// DIR/.render-partial, emptied: where a render is written before install_rendered swaps it in, so that
/// an interrupted render leaves the previous one whole.
std::filesystem::path render_scratch(const std::filesystem::path& dir);

/// Replaces the rendered files in `dir` with those in `scratch`, then removes `scratch`.
void install_rendered(const std::filesystem::path& scratch, const std::filesystem::path& dir);

/// The file's bytes; InputError `<file>: cannot read it; <what_to_do>`.
std::string read_bytes(const std::filesystem::path& file, const std::string& what_to_do);

/// Writes `bytes` to `file` through `file`.tmp and a rename, so that a failed write never loses the file
/// already there (stats.json, report.html); InputError `<file>: <failure>` when the write fails.
void replace_file(const std::filesystem::path& file, const std::string& bytes, const std::string& failure);

}  // namespace animpak::cli
