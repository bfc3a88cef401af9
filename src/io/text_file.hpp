// Reading a whole text file for the parsers in src/io, with one error wording for every reader.
#pragma once

#include <filesystem>
#include <string>

namespace animpak::io_detail {

/// The file's bytes. Throws InputError `<file>: cannot read "<file>" (resolved to <abs>); <what_to_do>`
/// when it is missing, unreadable, a folder, or larger than `max_bytes`.
std::string read_text_file(const std::filesystem::path& file, const std::string& what_to_do,
                           std::uintmax_t max_bytes = 64u << 20);

}  // namespace animpak::io_detail
