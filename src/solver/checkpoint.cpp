#include "animpak/checkpoint.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>

#include "animpak/error.hpp"

namespace animpak {
namespace {

constexpr char magic[8] = {'A', 'N', 'I', 'M', 'P', 'A', 'K', 'S'};
constexpr std::uint64_t max_array = std::uint64_t{1} << 32;

std::uint64_t fnv1a(const std::string& bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ull;
  return h;
}

class Writer {
 public:
  template <class T>
  void put(T value) {
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  void put_string(const std::string& s) {
    put<std::uint64_t>(s.size());
    bytes_ += s;
  }
  template <class T>
  void put_array(const std::vector<T>& v) {
    put<std::uint64_t>(v.size());
    bytes_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  std::string& bytes() { return bytes_; }

 private:
  std::string bytes_;
};

class Reader {
 public:
  Reader(const std::string& bytes, std::size_t end, std::string file)
      : bytes_(bytes), end_(end), file_(std::move(file)) {}
  template <class T>
  T get() {
    need(sizeof(T));
    T value;
    std::memcpy(&value, bytes_.data() + pos_, sizeof value);
    pos_ += sizeof value;
    return value;
  }
  std::string get_string() {
    const auto n = get<std::uint64_t>();
    need(n);
    std::string s = bytes_.substr(pos_, n);
    pos_ += n;
    return s;
  }
  template <class T>
  std::vector<T> get_array() {
    const auto n = get<std::uint64_t>();
    if (n > max_array) fail("an array length is implausible");
    need(n * sizeof(T));
    std::vector<T> v(n);
    std::memcpy(v.data(), bytes_.data() + pos_, n * sizeof(T));
    pos_ += n * sizeof(T);
    return v;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(file_ + ": " + what + "; the state file is damaged, pack the scene again");
  }

 private:
  void need(std::uint64_t n) const {
    if (n > end_ - pos_) fail("ends early (truncated)");
  }
  const std::string& bytes_;
  std::size_t end_, pos_ = sizeof magic + sizeof(std::uint32_t);
  std::string file_;
};

}  // namespace

void write_checkpoint(const std::filesystem::path& file, const Checkpoint& c) {
  Writer w;
  w.bytes().append(magic, sizeof magic);
  w.put<std::uint32_t>(checkpoint_version);
  w.put_string(c.scene_text);
  // The scene's path relative to the state's own folder, so the folder and its scene can move
  // together (e.g. a checkout carried to a GPU machine); absolute when they share no root.
  const std::filesystem::path base = std::filesystem::absolute(file).parent_path();
  const std::filesystem::path relative = c.scene_file.is_absolute() ? c.scene_file.lexically_relative(base) : "";
  w.put_string((relative.empty() ? c.scene_file : relative).generic_string());
  w.put<std::uint64_t>(c.seed);
  w.put_string(c.stop_reason);
  w.put<std::uint64_t>(c.state.iteration);
  w.put<std::uint64_t>(c.state.settling_since);
  w.put<std::uint64_t>(c.state.secondary_since);
  w.put<std::uint64_t>(c.state.mark_iteration);
  w.put<double>(c.state.mark_growth);
  for (const double m : {c.state.mark_growth_1, c.state.mark_growth_2, c.state.mark_growth_3}) w.put<double>(m);
  for (const auto* a : {&c.state.x, &c.state.y, &c.state.t, &c.state.vx, &c.state.vy, &c.state.vt, &c.state.spring_rest,
                        &c.state.growth})
    w.put_array(*a);
  w.put<std::uint64_t>(fnv1a(w.bytes()));

  const std::filesystem::path temp = file.string() + ".tmp";
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    out.write(w.bytes().data(), static_cast<std::streamsize>(w.bytes().size()));
    if (!out) throw InputError(file.string() + ": cannot write the state; check the folder and free disk space");
  }
  std::filesystem::rename(temp, file);
}

Checkpoint read_checkpoint(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot read the state file; give the folder `animpak pack --out` wrote");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string name = file.string();
  // A file cut inside or right after the header still starts like a state file: it is truncated,
  // not foreign.
  if (std::memcmp(bytes.data(), magic, std::min(bytes.size(), sizeof magic)) != 0 || bytes.empty())
    throw InputError(name + ": not an animpak state file (wrong magic bytes)");
  if (bytes.size() < sizeof magic + 4 + 8)
    throw InputError(name + ": ends early (truncated); the state file is damaged, pack the scene again");
  std::uint32_t version;
  std::memcpy(&version, bytes.data() + sizeof magic, sizeof version);
  // Version 2 is version 3 without secondary_since (it had no secondary elements); version 3 is version 4
  // without the stall test's earlier marks (it tested once per window: a resumed run starts them afresh).
  if (version < 2 || version > checkpoint_version)
    throw InputError(name + ": state format version " + std::to_string(version) +
                     ", this animpak reads versions 2 to " + std::to_string(checkpoint_version) +
                     "; pack the scene again with this version");
  const std::size_t body = bytes.size() - sizeof(std::uint64_t);
  std::uint64_t stored;
  std::memcpy(&stored, bytes.data() + body, sizeof stored);
  Reader r(bytes, body, name);
  if (fnv1a(bytes.substr(0, body)) != stored) r.fail("checksum mismatch (truncated or modified)");

  Checkpoint c;
  c.scene_text = r.get_string();
  c.scene_file = r.get_string();
  if (c.scene_file.is_relative())
    c.scene_file = (std::filesystem::absolute(file).parent_path() / c.scene_file).lexically_normal();
  c.seed = r.get<std::uint64_t>();
  c.stop_reason = r.get_string();
  c.state.iteration = r.get<std::uint64_t>();
  c.state.settling_since = r.get<std::uint64_t>();
  if (version >= 3) c.state.secondary_since = r.get<std::uint64_t>();
  c.state.mark_iteration = r.get<std::uint64_t>();
  c.state.mark_growth = r.get<double>();
  if (version >= 4)
    for (double* m : {&c.state.mark_growth_1, &c.state.mark_growth_2, &c.state.mark_growth_3}) *m = r.get<double>();
  for (auto* a : {&c.state.x, &c.state.y, &c.state.t, &c.state.vx, &c.state.vy, &c.state.vt, &c.state.spring_rest,
                  &c.state.growth})
    *a = r.get_array<float>();
  const std::size_t n = c.state.x.size();
  for (const auto* a : {&c.state.y, &c.state.t, &c.state.vx, &c.state.vy, &c.state.vt})
    if (a->size() != n) r.fail("per-vertex arrays differ in length");
  return c;
}

}  // namespace animpak
