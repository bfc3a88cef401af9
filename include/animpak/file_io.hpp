// Files as a database writes them (docs/cli.md, "What survives"): every write goes to a temporary
// name beside its file, is checked (each write, the flush to disk, the close) and only then renamed into
// place, so a full disk, a killed run or a read-only folder never leaves half a file where a whole one
// was. Reads inside an output folder open only regular files and follow no link: a FIFO, a device or a
// link planted in a copied folder is refused before a byte of it is read.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace animpak {

/// The bytes of `file`, which must be a regular file of at most `max_bytes`. Opened without blocking
/// (a FIFO never hangs) and, with `follow_links` false, without following a link at its last component.
/// Throws InputError `<file>: <why>; <what_to_do>` (missing, a link, not a regular file, too large,
/// unreadable).
std::string read_regular_file(const std::filesystem::path& file, const std::string& what_to_do,
                              std::uintmax_t max_bytes, bool follow_links = false);

/// Writes `bytes` to `file`: into `file` + ".partial" beside it, every write checked, flushed to disk
/// (fsync), closed, then renamed over `file` (its folder must exist). On any failure the temporary
/// file is removed, `file` is left as it was, and InputError names `file` and the cause ("No space left
/// on device", "Permission denied").
void write_file_atomically(const std::filesystem::path& file, std::string_view bytes);

/// Flushes a file another writer (a library, ffmpeg) wrote to disk and checks that it is a regular,
/// non-empty file; InputError names it and the cause otherwise.
void sync_written_file(const std::filesystem::path& file);

/// Flushes a folder's entries (its renames) to disk; errors are ignored (some file systems refuse it).
void sync_folder(const std::filesystem::path& dir);

/// Refuses `dir` / `relative` when any part of `relative` below `dir` is a symbolic link, without opening
/// anything: a copied output folder is data, never a way out of it (`dir` itself may be a link the user
/// made). Parts that do not exist yet are allowed. InputError names the link and `what_to_do`.
void refuse_links_below(const std::filesystem::path& dir, const std::filesystem::path& relative,
                        const std::string& what_to_do);

/// An InputError message for a failed file operation: `<file>: <doing>: <the system's reason>; <advice>`,
/// the advice chosen by the cause (free disk space, check permissions).
std::string file_error(const std::filesystem::path& file, const std::string& doing, int error_number);

}  // namespace animpak
