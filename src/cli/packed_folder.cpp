#include "packed_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <regex>
#include <set>

#include "animpak/error.hpp"
#include "animpak/file_io.hpp"
#include "animpak/sha256.hpp"

namespace animpak::cli {
namespace fs = std::filesystem;
namespace {

constexpr int kManifestVersion = 1;
// Every whole-animation file a render writes (animation_file_name in src/render/writers.cpp names them),
// the contact plot `render --contact-plot` draws after the swap, and the page `animpak report` writes from
// a render: a name missing here is neither swapped in nor removed, and would outlive the render it came
// from.
const char* const kAnimationFiles[] = {"animation.gif", "animation.mp4", "animation.json", "animation.lottie",
                                       "animation.svg", "contact.png",   "report.html",    "trajectory.svg"};

// The largest file read from inside an output folder that is not state.bin: art, the manifest, stats.json.
constexpr std::uintmax_t kMaxFolderFile = 64u << 20;
// Where a new packing is written until it is whole (docs/cli.md, "What survives"), the packing before it
// moved aside while the new one is swapped in, and the mark that the new one is whole.
constexpr const char* kNewPack = ".pack-new";
constexpr const char* kOldPack = ".pack-old";
constexpr const char* kPackComplete = "complete";
// What a packing is, besides its frames: moved as a whole when a new packing replaces it.
const char* const kPackingFiles[] = {"input", "state.bin", "stats.json"};

struct ManifestArt {
  fs::path file;  ///< absolute
  std::string sha256;
};

struct Manifest {
  fs::path file;
  std::string scene_sha256;
  std::vector<std::pair<std::string, ManifestArt>> art;  ///< by the reference as written

  const ManifestArt* find(const std::string& written) const {
    for (const auto& [reference, copy] : art)
      if (reference == written) return &copy;
    return nullptr;
  }
};

std::optional<Manifest> read_manifest(const fs::path& dir) {
  Manifest m;
  m.file = dir / "input" / "manifest.json";
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(m.file, ec))) return std::nullopt;
  const nlohmann::json j =
      nlohmann::json::parse(read_folder_file(dir, "input/manifest.json", "restore the folder"), nullptr, false);
  try {
    if (j.is_discarded() || j.at("format_version").get<int>() > kManifestVersion) throw std::exception();
    m.scene_sha256 = j.at("scene").at("sha256").get<std::string>();
    for (const nlohmann::json& a : j.at("art")) {
      // A copied folder is untrusted: its manifest may only name files inside input/art/.
      const fs::path file = fs::path(a.at("file").get<std::string>()).lexically_normal();
      if (file.is_absolute() || file.empty() || *file.begin() != "art" ||
          std::any_of(file.begin(), file.end(), [](const fs::path& part) { return part == ".."; }))
        throw std::exception();
      m.art.push_back(
          {a.at("reference").get<std::string>(), {dir / "input" / file, a.at("sha256").get<std::string>()}});
    }
  } catch (const std::exception&) {
    throw InputError(m.file.string() +
                     ": not a manifest this animpak reads; restore the folder, or pass --scene "
                     "FILE with the scene it was packed from");
  }
  return m;
}

bool is_frame_file(const fs::path& file) {
  static const std::regex name(R"(frame_[0-9]{4,}\.(png|svg))");
  return std::regex_match(file.filename().string(), name);
}

}  // namespace

InputSnapshot snapshot_inputs(const fs::path& file, const std::string& text) {
  InputSnapshot s{file, text, {}};
  std::set<std::string> seen;
  parse_scene(text, file, file.parent_path(), [&](const std::string& written, const fs::path& resolved) {
    if (seen.insert(written).second && fs::is_regular_file(resolved))
      s.art.push_back({written, resolved, read_bytes(resolved, "check the scene's art paths")});
    return resolved;
  });
  return s;
}

void check_inputs_writable(const fs::path& dir) {
  const fs::path input = dir / "input";
  if (fs::exists(input) && !fs::exists(input / "manifest.json"))
    throw InputError(input.string() +
                     ": a folder animpak did not write is in the way of the scene's copy; "
                     "move it elsewhere or pack into another --out");
}

void check_folder_writable(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(file_error(dir, "cannot create the output folder", ec.value()));
  if (!fs::is_directory(dir)) throw InputError(dir.string() + ": not a folder; give --out a folder's path");
  const fs::path probe = dir / ".animpak-write-test";
  write_file_atomically(probe, "animpak\n");
  fs::remove(probe, ec);
}

void write_inputs(const fs::path& dir, const InputSnapshot& snapshot) {
  check_inputs_writable(dir);
  const fs::path input = dir / "input";
  fs::remove_all(input);
  fs::create_directories(input / "art");
  const std::string scene_name = snapshot.scene_file.filename().string();
  write_file_atomically(input / scene_name, snapshot.scene_text);
  nlohmann::json art = nlohmann::json::array();
  std::set<std::string> names;
  for (const InputSnapshot::Art& a : snapshot.art) {
    // Art files of the same name from different folders get a number in front, so none replaces another.
    std::string name = a.source.filename().string();
    for (int n = 2; !names.insert(name).second; ++n) name = std::to_string(n) + "-" + a.source.filename().string();
    write_file_atomically(input / "art" / name, a.bytes);
    art.push_back({{"reference", a.written}, {"file", "art/" + name}, {"sha256", sha256_hex(a.bytes)}});
  }
  const nlohmann::json manifest = {{"format_version", kManifestVersion},
                                   {"scene",
                                    {{"file", scene_name},
                                     {"packed_from", snapshot.scene_file.string()},
                                     {"sha256", sha256_hex(snapshot.scene_text)}}},
                                   {"art", art}};
  // The manifest last: a folder with one has every file it names.
  write_file_atomically(input / "manifest.json", manifest.dump(2) + "\n");
  sync_folder(input / "art");
  sync_folder(input);
}

PackedScene packed_scene(const fs::path& dir, const Checkpoint& checkpoint, const std::optional<fs::path>& scene,
                         bool force) {
  const std::optional<Manifest> manifest = read_manifest(dir);
  const std::string state = (dir / "state.bin").string();
  if (scene) {
    PackedScene p{read_bytes(*scene, "check the --scene path"), *scene, {}};
    if (p.text != checkpoint.scene_text && !force)
      throw InputError(scene->string() + ": differs from the scene packed in " + state +
                       ", and a different scene builds a different packing; give the scene it was packed from, or "
                       "add --force to render with this one");
    if (!manifest || force) return p;
    p.locate = [manifest, force](const std::string& written, const fs::path& resolved) {
      const ManifestArt* packed = manifest->find(written);
      if (!packed || (fs::is_regular_file(resolved) &&
                      sha256_hex(read_bytes(resolved, "check the scene's art paths")) != packed->sha256))
        throw InputError(resolved.string() + ": art \"" + written +
                         "\" is not the file packed (its SHA-256 is not "
                         "the one in " +
                         manifest->file.string() +
                         "), and different art builds a different "
                         "packing; give the packed art, or add --force to render with this one");
      return resolved;
    };
    return p;
  }
  PackedScene p{checkpoint.scene_text, checkpoint.scene_file, {}};
  if (manifest) {
    if (sha256_hex(checkpoint.scene_text) != manifest->scene_sha256)
      throw InputError(manifest->file.string() + ": belongs to another packing than " + state +
                       "; restore the folder, or pass --scene FILE with the scene it was packed from");
    p.locate = [manifest, dir](const std::string& written, const fs::path&) {
      const ManifestArt* packed = manifest->find(written);
      // Never the original scene's folder: what is there now is not checked against anything.
      if (!packed)
        throw InputError(manifest->file.string() + ": names no copy of art \"" + written +
                         "\", which the packed scene uses; restore the folder, or pass --scene FILE with the "
                         "scene it was packed from");
      const std::string what_to_do = "restore the folder, or pass --scene FILE";
      if (sha256_hex(read_folder_file(dir, packed->file.lexically_relative(dir), what_to_do)) != packed->sha256)
        throw InputError(packed->file.string() + ": changed since it was packed (its SHA-256 is not the one in " +
                         manifest->file.string() + "); restore it, or pass --scene FILE with the packed art");
      return packed->file;
    };
    return p;
  }
  // Folders packed before input/ existed: the art must still be where the scene was.
  p.locate = [dir, file = checkpoint.scene_file](const std::string& written, const fs::path& resolved) {
    if (!fs::is_regular_file(resolved))
      throw InputError(file.string() + ": cannot read art \"" + written + "\" (resolved to " + resolved.string() +
                       "), and " + dir.string() +
                       " has no input/ copy of it; pass --scene FILE, the scene "
                       "file beside its art");
    return resolved;
  };
  return p;
}

std::vector<fs::path> remove_rendered(const fs::path& dir) {
  std::vector<fs::path> animations, frame_files;
  for (const char* name : kAnimationFiles)
    if (fs::remove(dir / name)) animations.push_back(name);
  const fs::path frames = dir / "frames";
  // A frames/ that is a link is not this folder's: nothing in the folder it points to is removed.
  std::error_code ec;
  if (fs::is_directory(fs::symlink_status(frames, ec))) {
    for (const fs::directory_entry& e : fs::directory_iterator(frames))
      if (e.is_regular_file() && is_frame_file(e.path()))
        frame_files.push_back(fs::path("frames") / e.path().filename());
    std::sort(frame_files.begin(), frame_files.end());
    for (const fs::path& file : frame_files) fs::remove(dir / file);
    if (fs::is_empty(frames)) fs::remove(frames);
  }
  frame_files.insert(frame_files.end(), animations.begin(), animations.end());
  return frame_files;
}

fs::path render_scratch(const fs::path& dir) {
  const fs::path scratch = dir / ".render-partial";
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  return scratch;
}

std::vector<fs::path> install_rendered(const fs::path& scratch, const fs::path& dir) {
  // Every file in `scratch` was checked and flushed by its writer (write_file_atomically; ffmpeg's output
  // by run_ffmpeg), so a render that failed on a full disk never gets here and leaves the one before whole.
  refuse_links_below(dir, "frames", "move the link away; frames/ is written by animpak render");
  std::vector<fs::path> removed = remove_rendered(dir);
  for (const char* name : kAnimationFiles)
    if (fs::exists(scratch / name)) fs::rename(scratch / name, dir / name);
  // The statistics of these frames (BesideFrames), over those of the frames before.
  if (fs::exists(scratch / "stats.json")) fs::rename(scratch / "stats.json", dir / "stats.json");
  if (fs::is_directory(scratch / "frames")) {
    fs::create_directories(dir / "frames");
    for (const fs::directory_entry& e : fs::directory_iterator(scratch / "frames"))
      if (is_frame_file(e.path())) fs::rename(e.path(), dir / "frames" / e.path().filename());
  }
  fs::remove_all(scratch);
  sync_folder(dir / "frames");
  sync_folder(dir);
  return removed;
}

std::string read_bytes(const fs::path& file, const std::string& what_to_do) {
  return read_regular_file(file, what_to_do, kMaxFolderFile, true);
}

std::string read_folder_file(const fs::path& dir, const fs::path& relative, const std::string& what_to_do) {
  refuse_links_below(dir, relative, what_to_do);
  return read_regular_file(dir / relative, what_to_do, kMaxFolderFile);
}

int take_lock_file(const fs::path& file, const std::string& holder, const std::string& what,
                   const std::string& link_fix, std::string& held_by) {
  refuse_links_below(file.parent_path(), file.filename(), link_fix);
  const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0644);
  if (fd < 0) throw InputError(file_error(file, "cannot take " + what, errno));
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    std::string text(200, '\0');
    const ssize_t n = ::pread(fd, text.data(), text.size(), 0);
    text.resize(n > 0 ? std::size_t(n) : 0);
    while (!text.empty() && (text.back() == '\n' || text.back() == '\0')) text.pop_back();
    ::close(fd);
    if (error != EWOULDBLOCK) throw InputError(file_error(file, "cannot take " + what, error));
    held_by = text;
    return -1;
  }
  // Who holds it, for the message a second run prints; the lock works without it.
  if (!holder.empty() && ::ftruncate(fd, 0) == 0) {
    const ssize_t written = ::pwrite(fd, holder.data(), holder.size(), 0);
    static_cast<void>(written);
  }
  return fd;
}

FolderLock::FolderLock(const fs::path& dir, const std::string& command) {
  if (!fs::is_directory(dir))
    throw InputError(dir.string() + ": not a folder (" + (fs::exists(dir) ? "a file" : "it does not exist") +
                     "); give the folder `animpak pack --out` wrote");
  std::string held_by;
  fd_ = take_lock_file(dir / ".animpak.lock", "pid " + std::to_string(::getpid()) + ": " + command + "\n",
                       "the folder's lock", "remove the link; animpak keeps its lock there", held_by);
  if (fd_ < 0)
    throw InputError(dir.string() + ": another animpak is using this folder" +
                     (held_by.empty() ? std::string() : " (" + held_by + ")") +
                     "; wait for it to end, or stop it, and run this command again");
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock; the file stays, empty of meaning until the next run
}

fs::path new_pack_dir(const fs::path& dir) { return dir / kNewPack; }

bool has_unfinished_pack(const fs::path& dir) {
  std::error_code ec;
  return fs::is_regular_file(fs::symlink_status(dir / kNewPack / "state.bin", ec)) &&
         !fs::exists(fs::symlink_status(dir / kNewPack / kPackComplete, ec));
}

void start_new_pack(const fs::path& dir) {
  refuse_links_below(dir, kNewPack, "remove the link; animpak writes a new packing there");
  fs::remove_all(dir / kNewPack);
  fs::remove_all(dir / kOldPack);
  fs::create_directories(dir / kNewPack);
}

std::vector<fs::path> install_new_pack(const fs::path& dir) {
  const fs::path staged = dir / kNewPack;
  sync_folder(staged);
  write_file_atomically(staged / kPackComplete, "");
  sync_folder(staged);
  std::vector<fs::path> removed;
  recover_folder(dir, &removed);
  return removed;
}

bool recover_folder(const fs::path& dir, std::vector<fs::path>* removed) {
  const fs::path staged = dir / kNewPack, old = dir / kOldPack;
  std::error_code ec;
  // What a write killed midway left (write_file_atomically's temporaries): only names animpak writes.
  std::vector<std::string> written = {"state.bin", "stats.json", ".animpak-write-test"};
  written.insert(written.end(), std::begin(kAnimationFiles), std::end(kAnimationFiles));
  for (const std::string& name : written)
    if (fs::is_regular_file(fs::symlink_status(dir / (name + ".partial"), ec)))
      fs::remove(dir / (name + ".partial"), ec);
  if (!fs::exists(fs::symlink_status(staged / kPackComplete, ec))) {
    // No whole new packing: whatever a kill left in .pack-old goes back (the new one is not swapped in).
    if (fs::is_directory(fs::symlink_status(old, ec))) {
      for (const char* name : kPackingFiles)
        if (fs::exists(fs::symlink_status(old / name, ec)) && !fs::exists(fs::symlink_status(dir / name, ec)))
          fs::rename(old / name, dir / name);
      fs::remove_all(old);
    }
    return false;
  }
  // A whole new packing: swapped in, or the swap a kill cut short finished. Each step can be repeated.
  refuse_links_below(dir, kOldPack, "remove the link; animpak keeps the packing it replaces there");
  fs::create_directories(old);
  for (const char* name : kPackingFiles) {
    const bool incoming = fs::exists(fs::symlink_status(staged / name, ec));
    if ((incoming || std::string(name) == "stats.json") && fs::exists(fs::symlink_status(dir / name, ec))) {
      fs::remove_all(old / name);
      fs::rename(dir / name, old / name);
    }
    if (incoming) fs::rename(staged / name, dir / name);
  }
  const bool replaced = fs::exists(fs::symlink_status(old / "state.bin", ec));
  sync_folder(dir);
  // Frames of the packing before must not stay beside this one.
  if (replaced) {
    const std::vector<fs::path> rendered = remove_rendered(dir);
    if (removed) removed->insert(removed->end(), rendered.begin(), rendered.end());
  }
  fs::remove_all(old);
  fs::remove_all(staged);
  sync_folder(dir);
  return true;
}

}  // namespace animpak::cli
