#include "animpak/checkpoint.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "animpak/error.hpp"
#include "animpak/file_io.hpp"
#include "animpak/sha256.hpp"

namespace animpak {
namespace {

constexpr char magic[8] = {'A', 'N', 'I', 'M', 'P', 'A', 'K', 'S'};
constexpr std::uint64_t max_array = std::uint64_t{1} << 32;
// The largest state file read: 8 arrays of at most max_array floats would be 128 GiB; a scene within the
// element and vertex limits (docs/cli.md, "Limits") writes far less than this.
constexpr std::uintmax_t max_state_bytes = std::uintmax_t{16} << 30;
constexpr std::size_t digest_size = 64;  // SHA-256 as hex digits
// Positions, velocities and rest lengths of a world normalised to the unit square stay far inside this;
// a larger value is a damaged or made-up state, not a packing.
constexpr float max_magnitude = 1e6f;

const char* const stop_reasons[] = {"running",        "gap",         "stalled",   "unsettled", "growth",
                                    "max_iterations", "interrupted", "non_finite"};

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

// A state is resumed and rendered as it stands, so a value no packing can hold is refused here, naming
// it, instead of stepping or drawing it (a NaN resumed as if it were a packing).
void check_values(const Checkpoint& c, const Reader& r) {
  const SimState& s = c.state;
  if (c.level_slices < 0 || c.level_slices == 1 || c.level_slices > 1000)
    r.fail("its level (" + std::to_string(c.level_slices) + " slices) is not one animpak writes");
  if (std::find(std::begin(stop_reasons), std::end(stop_reasons), c.stop_reason) == std::end(stop_reasons))
    r.fail("its stop reason \"" + c.stop_reason.substr(0, 40) + "\" is not one animpak writes");
  for (const std::uint64_t since : {s.settling_since, s.secondary_since, s.mark_iteration})
    if (since > s.iteration) r.fail("an iteration mark lies after its iteration count");
  for (const double m : {s.mark_growth, s.mark_growth_1, s.mark_growth_2, s.mark_growth_3})
    if (!std::isfinite(m) || m < 0.0) r.fail("a growth mark is not a finite, non-negative number");
  const std::pair<const std::vector<float>*, const char*> arrays[] = {{&s.x, "x"},
                                                                      {&s.y, "y"},
                                                                      {&s.t, "t"},
                                                                      {&s.vx, "vx"},
                                                                      {&s.vy, "vy"},
                                                                      {&s.vt, "vt"},
                                                                      {&s.spring_rest, "spring rest length"},
                                                                      {&s.growth, "growth"}};
  for (const auto& [values, name] : arrays)
    for (std::size_t i = 0; i < values->size(); ++i)
      if (!(std::fabs((*values)[i]) <= max_magnitude))  // false for NaN too
        r.fail(std::string("its ") + name + " value " + std::to_string(i) + " is " + std::to_string((*values)[i]) +
               ", not a finite number of a packing");
  for (const float g : s.growth)
    if (!(g > 0.0f)) r.fail("a growth value is not positive");
  for (const float rest : s.spring_rest)
    if (rest < 0.0f) r.fail("a spring rest length is negative");
}

}  // namespace

void write_checkpoint(const std::filesystem::path& file, const Checkpoint& c, const std::filesystem::path& home) {
  Writer w;
  w.bytes().append(magic, sizeof magic);
  w.put<std::uint32_t>(checkpoint_version);
  w.put_string(c.scene_text);
  // The scene's path relative to the state's own folder, so the folder and its scene can move
  // together (e.g. a checkout carried to a GPU machine); absolute when they share no root.
  const std::filesystem::path base =
      (home.empty() ? std::filesystem::absolute(file).parent_path() : std::filesystem::absolute(home));
  const std::filesystem::path relative = c.scene_file.is_absolute() ? c.scene_file.lexically_relative(base) : "";
  w.put_string((relative.empty() ? c.scene_file : relative).generic_string());
  w.put<std::uint64_t>(c.seed);
  w.put_string(c.stop_reason);
  w.put<std::int32_t>(c.level_slices);
  w.put<std::uint64_t>(c.state.iteration);
  w.put<std::uint64_t>(c.state.settling_since);
  w.put<std::uint64_t>(c.state.secondary_since);
  w.put<std::uint64_t>(c.state.mark_iteration);
  w.put<double>(c.state.mark_growth);
  for (const double m : {c.state.mark_growth_1, c.state.mark_growth_2, c.state.mark_growth_3}) w.put<double>(m);
  for (const auto* a : {&c.state.x, &c.state.y, &c.state.t, &c.state.vx, &c.state.vy, &c.state.vt, &c.state.spring_rest,
                        &c.state.growth})
    w.put_array(*a);
  w.bytes() += sha256_hex(w.bytes());
  write_file_atomically(file, w.bytes());
}

Checkpoint read_checkpoint(const std::filesystem::path& file, const std::filesystem::path& home) {
  const std::string bytes = read_regular_file(
      file, "cannot read the state file; give the folder `animpak pack --out` wrote", max_state_bytes);
  const std::string name = file.string();
  // A file cut inside or right after the header still starts like a state file: it is truncated,
  // not foreign.
  if (std::memcmp(bytes.data(), magic, std::min(bytes.size(), sizeof magic)) != 0 || bytes.empty())
    throw InputError(name + ": not an animpak state file (wrong magic bytes)");
  if (bytes.size() < sizeof magic + 4)
    throw InputError(name + ": ends early (truncated); the state file is damaged, pack the scene again");
  std::uint32_t version;
  std::memcpy(&version, bytes.data() + sizeof magic, sizeof version);
  // Versions 2 to 4 ended in a 64-bit FNV checksum, which anyone can recompute for a state changed on
  // purpose; versions 5 and 6 end in a SHA-256 of everything before it, and its values are checked below.
  // Version 6 adds the level (level_slices); a version 5 state is at the scene's own slices.
  if (version >= 2 && version < 5)
    throw InputError(name + ": state format version " + std::to_string(version) +
                     " (animpak 0.15 and before), whose checksum cannot tell a changed state from a packed one; "
                     "pack the scene again with this version (the animpak that wrote it still renders it)");
  if (version < 2 || version > checkpoint_version)
    throw InputError(name + ": state format version " + std::to_string(version) + ", this animpak reads version " +
                     std::to_string(checkpoint_version) + "; pack the scene again with this version");
  if (bytes.size() < sizeof magic + 4 + digest_size)
    throw InputError(name + ": ends early (truncated); the state file is damaged, pack the scene again");
  const std::size_t body = bytes.size() - digest_size;
  Reader r(bytes, body, name);
  if (sha256_hex(std::string_view(bytes).substr(0, body)) != bytes.substr(body))
    r.fail("checksum mismatch (truncated or modified)");

  Checkpoint c;
  c.scene_text = r.get_string();
  c.scene_file = r.get_string();
  if (c.scene_file.is_relative())
    c.scene_file = ((home.empty() ? std::filesystem::absolute(file).parent_path() : std::filesystem::absolute(home)) /
                    c.scene_file)
                       .lexically_normal();
  c.seed = r.get<std::uint64_t>();
  c.stop_reason = r.get_string();
  if (version >= 6) c.level_slices = r.get<std::int32_t>();
  c.state.iteration = r.get<std::uint64_t>();
  c.state.settling_since = r.get<std::uint64_t>();
  c.state.secondary_since = r.get<std::uint64_t>();
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
  check_values(c, r);
  return c;
}

}  // namespace animpak
