// animation.lottie: the Lottie document in a dotLottie container, a zip holding manifest.json and
// animations/animation.json, deflated with zlib (docs/animation-formats.md, "dotLottie").
#include <zlib.h>

#include <cstdint>
#include <fstream>
#include <sstream>

#include "animpak/error.hpp"
#include "animpak/file_io.hpp"
#include "animpak/version.hpp"
#include "frame_writers.hpp"

namespace animpak::frame_writers {
namespace {

struct ZipEntry {
  std::string name, data;
};

void put16(std::string& out, std::uint32_t v) { out += char(v & 0xff), out += char((v >> 8) & 0xff); }
void put32(std::string& out, std::uint32_t v) { put16(out, v & 0xffff), put16(out, v >> 16); }

// Raw deflate (no zlib header), as a zip entry of method 8 holds it.
std::string deflated(const std::string& data, const std::filesystem::path& file) {
  z_stream z{};
  if (deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, -15, 9, Z_DEFAULT_STRATEGY) != Z_OK)
    throw InputError(file.string() + ": zlib could not start deflating");
  std::string out(deflateBound(&z, uLong(data.size())), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  z.avail_in = uInt(data.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = uInt(out.size());
  const int status = deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  if (status != Z_STREAM_END) throw InputError(file.string() + ": zlib could not deflate the document");
  return out;
}

// A zip of deflated entries, every one dated 1980-01-01 00:00 so that the same animation gives the same file.
std::string zip(const std::vector<ZipEntry>& entries, const std::filesystem::path& file) {
  std::string body, directory;
  for (const ZipEntry& e : entries) {
    const std::string packed = deflated(e.data, file);
    const auto crc = std::uint32_t(crc32(0, reinterpret_cast<const Bytef*>(e.data.data()), uInt(e.data.size())));
    std::string common;  // version needed, flags, method, time, date, CRC, sizes, name length
    put16(common, 20), put16(common, 0), put16(common, 8), put16(common, 0), put16(common, 0x21);
    put32(common, crc), put32(common, std::uint32_t(packed.size())), put32(common, std::uint32_t(e.data.size()));
    put16(common, std::uint32_t(e.name.size()));
    put32(directory, 0x02014b50), put16(directory, 20), directory += common;
    // No extra field or comment, disk 0, no internal or external attributes.
    put16(directory, 0), put16(directory, 0), put16(directory, 0), put16(directory, 0);
    put32(directory, 0), put32(directory, std::uint32_t(body.size())), directory += e.name;
    put32(body, 0x04034b50), body += common, put16(body, 0), body += e.name, body += packed;
  }
  std::string end;
  put32(end, 0x06054b50), put16(end, 0), put16(end, 0), put16(end, std::uint32_t(entries.size()));
  put16(end, std::uint32_t(entries.size())), put32(end, std::uint32_t(directory.size()));
  put32(end, std::uint32_t(body.size())), put16(end, 0);
  return body + directory + end;
}

}  // namespace

void write_dotlottie(const World& world, const SimState& state, const FrameOutput& out,
                     const std::vector<std::string>& ids, const std::filesystem::path& file) {
  std::ostringstream document;
  write_lottie(world, state, out, ids, document, file);
  const std::string manifest = "{\"version\":\"1\",\"generator\":\"animpak " + std::string(animpak_version) +
                               "\",\"author\":\"animpak\",\"revision\":1,\"activeAnimationId\":\"animation\","
                               "\"animations\":[{\"id\":\"animation\",\"loop\":true,\"autoplay\":true,\"speed\":1,"
                               "\"direction\":1,\"playMode\":\"normal\"}]}\n";
  const std::string bytes = zip({{"manifest.json", manifest}, {"animations/animation.json", document.str()}}, file);
  write_file_atomically(file, bytes);
}

}  // namespace animpak::frame_writers
