#include "packed_folder.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>

#include "animpak/error.hpp"
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

void write_bytes(const fs::path& file, const std::string& bytes) {
  fs::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw InputError(file.string() + ": cannot write it; check the folder and free disk space");
}

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
  if (!fs::exists(m.file)) return std::nullopt;
  const nlohmann::json j = nlohmann::json::parse(read_bytes(m.file, "restore the folder"), nullptr, false);
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

void write_inputs(const fs::path& dir, const InputSnapshot& snapshot) {
  check_inputs_writable(dir);
  const fs::path input = dir / "input";
  fs::remove_all(input);
  const std::string scene_name = snapshot.scene_file.filename().string();
  write_bytes(input / scene_name, snapshot.scene_text);
  nlohmann::json art = nlohmann::json::array();
  std::set<std::string> names;
  for (const InputSnapshot::Art& a : snapshot.art) {
    // Art files of the same name from different folders get a number in front, so none replaces another.
    std::string name = a.source.filename().string();
    for (int n = 2; !names.insert(name).second; ++n) name = std::to_string(n) + "-" + a.source.filename().string();
    write_bytes(input / "art" / name, a.bytes);
    art.push_back({{"reference", a.written}, {"file", "art/" + name}, {"sha256", sha256_hex(a.bytes)}});
  }
  const nlohmann::json manifest = {{"format_version", kManifestVersion},
                                   {"scene",
                                    {{"file", scene_name},
                                     {"packed_from", snapshot.scene_file.string()},
                                     {"sha256", sha256_hex(snapshot.scene_text)}}},
                                   {"art", art}};
  write_bytes(input / "manifest.json", manifest.dump(2) + "\n");
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
    p.locate = [manifest](const std::string& written, const fs::path& resolved) {
      const ManifestArt* packed = manifest->find(written);
      if (!packed) return resolved;
      if (sha256_hex(read_bytes(packed->file, "restore the folder, or pass --scene FILE")) != packed->sha256)
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

void remove_rendered(const fs::path& dir) {
  for (const char* name : kAnimationFiles) fs::remove(dir / name);
  const fs::path frames = dir / "frames";
  if (!fs::is_directory(frames)) return;
  for (const fs::directory_entry& e : fs::directory_iterator(frames))
    if (e.is_regular_file() && is_frame_file(e.path())) fs::remove(e.path());
  if (fs::is_empty(frames)) fs::remove(frames);
}

fs::path render_scratch(const fs::path& dir) {
  const fs::path scratch = dir / ".render-partial";
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  return scratch;
}

void install_rendered(const fs::path& scratch, const fs::path& dir) {
  remove_rendered(dir);
  for (const char* name : kAnimationFiles)
    if (fs::exists(scratch / name)) fs::rename(scratch / name, dir / name);
  if (fs::is_directory(scratch / "frames")) {
    fs::create_directories(dir / "frames");
    for (const fs::directory_entry& e : fs::directory_iterator(scratch / "frames"))
      if (is_frame_file(e.path())) fs::rename(e.path(), dir / "frames" / e.path().filename());
  }
  fs::remove_all(scratch);
}

std::string read_bytes(const fs::path& file, const std::string& what_to_do) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot read it; " + what_to_do);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void replace_file(const fs::path& file, const std::string& bytes, const std::string& failure) {
  fs::path temporary = file;
  temporary += ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      throw InputError(file.string() + ": " + failure);
    }
  }
  fs::rename(temporary, file);
}

}  // namespace animpak::cli
