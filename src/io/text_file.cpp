#include "text_file.hpp"

#include <fstream>
#include <sstream>
#include <system_error>

#include "animpak/error.hpp"

namespace animpak::io_detail {

std::string read_text_file(const std::filesystem::path& file, const std::string& what_to_do, std::uintmax_t max_bytes) {
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(file, ec);
  const std::string where = file.string() + ": cannot read \"" + file.string() + "\" (resolved to " +
                            (ec ? file.string() : absolute.lexically_normal().string()) + ")";
  // A folder opens as an ifstream on Linux and then fails on the first read; refuse it up front.
  if (!std::filesystem::is_regular_file(file, ec)) throw InputError(where + "; " + what_to_do);
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (ec) throw InputError(where + "; " + what_to_do);
  if (size > max_bytes)
    throw InputError(where + ": it is " + std::to_string(size) + " bytes, more than the limit of " +
                     std::to_string(max_bytes) + "; " + what_to_do);
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in.good() && !in.eof()) throw InputError(where + "; " + what_to_do);
  return std::move(text).str();
}

}  // namespace animpak::io_detail
