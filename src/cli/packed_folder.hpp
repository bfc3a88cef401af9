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

/// Creates `dir` and writes and removes a file in it, so a read-only folder, a file named as the folder
/// or a full disk is refused before any simulation.
void check_folder_writable(const std::filesystem::path& dir);

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
/// from `dir`, and frames/ when that leaves it empty; nothing else. Returns the files it removed, relative
/// to `dir` (frames/frame_0000.png, animation.gif), the frames first, each kind in name order.
std::vector<std::filesystem::path> remove_rendered(const std::filesystem::path& dir);

/// DIR/.render-partial, emptied: where a render is written before install_rendered swaps it in, so that
/// an interrupted render leaves the previous one whole.
std::filesystem::path render_scratch(const std::filesystem::path& dir);

/// Replaces the rendered files in `dir` (and stats.json, when the scratch folder holds one) with those in
/// `scratch`, each checked and flushed to disk before the first old one goes, then removes `scratch`.
/// Returns the rendered files of the run before that it removed (remove_rendered's list): those the new
/// render wrote again are among them.
std::vector<std::filesystem::path> install_rendered(const std::filesystem::path& scratch,
                                                    const std::filesystem::path& dir);

/// A file named by the user (a scene, --scene): a regular file, links followed, at most 64 MB;
/// InputError `<file>: <why>; <what_to_do>`.
std::string read_bytes(const std::filesystem::path& file, const std::string& what_to_do);

/// A file inside an output folder: no link below `dir` followed, only a regular file opened.
std::string read_folder_file(const std::filesystem::path& dir, const std::filesystem::path& relative,
                             const std::string& what_to_do);

/// One run per folder (docs/cli.md, "What survives"): an advisory lock (flock) on DIR/.animpak.lock,
/// held until the object is destroyed or the process ends, however it ends. A second run is refused at
/// once with InputError naming the one that holds it.
/// An advisory lock (flock) on `file`, taken without waiting; a link in its place is refused (`link_fix`
/// says what to do). Returns its descriptor (closing it lets the lock go), or -1 when another process
/// holds it, with `held_by` set to what that process wrote in the file. A non-empty `holder` is written
/// in the file for the next one to read. Other failures are InputError naming `what` ("the folder's lock").
int take_lock_file(const std::filesystem::path& file, const std::string& holder, const std::string& what,
                   const std::string& link_fix, std::string& held_by);

class FolderLock {
 public:
  FolderLock(const std::filesystem::path& dir, const std::string& command);
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  ~FolderLock();

 private:
  int fd_ = -1;
};

// A new packing (a fresh pack, or --force over a packing) is written into DIR/.pack-new until it ends:
// input/ first, then state.bin at every checkpoint. Only when it is whole is it swapped in for the
// packing before it (moved to DIR/.pack-old meanwhile, then removed), so a kill at any moment leaves
// either the packing before or the new one, never a mix (docs/cli.md, "What survives").

/// DIR/.pack-new.
std::filesystem::path new_pack_dir(const std::filesystem::path& dir);
/// A new packing was started and not swapped in (killed): `pack --resume DIR` continues it.
bool has_unfinished_pack(const std::filesystem::path& dir);
/// Clears what an earlier new packing left and makes DIR/.pack-new.
void start_new_pack(const std::filesystem::path& dir);
/// Marks DIR/.pack-new whole and swaps it in, removing the packing before and its rendered files; returns
/// those files (remove_rendered's list; empty when there was no packing before).
std::vector<std::filesystem::path> install_new_pack(const std::filesystem::path& dir);
/// Finishes a swap a kill cut short (every command calls it under the lock before reading the folder);
/// true when it swapped a packing in. The rendered files of the packing it replaced are added to `removed`
/// when given.
bool recover_folder(const std::filesystem::path& dir, std::vector<std::filesystem::path>* removed = nullptr);

}  // namespace animpak::cli
