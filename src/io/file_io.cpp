#include "animpak/file_io.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "animpak/error.hpp"

namespace animpak {
namespace fs = std::filesystem;
namespace {

// Closes on every path out, so a refused or failed file never leaks its descriptor.
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }
  /// Closes now and reports close's own error (NFS and some full disks report a failed write only here).
  int close() {
    const int result = ::close(fd_);
    fd_ = -1;
    return result == 0 ? 0 : errno;
  }

 private:
  int fd_;
};

}  // namespace

std::string file_error(const fs::path& file, const std::string& doing, int error_number) {
  std::string advice;
  switch (error_number) {
    case ENOSPC:
    case EDQUOT:
    case EFBIG:
      advice = "free disk space (or raise the file size limit) and run the command again";
      break;
    case EACCES:
    case EPERM:
    case EROFS:
      advice = "the folder is not writable by you: choose another --out, or change its permissions";
      break;
    case EISDIR:
    case ENOTDIR:
      advice = "a folder stands where the file should be, or a file where a folder should be: move it away";
      break;
    default:
      advice = "check the folder and free disk space";
  }
  return file.string() + ": " + doing + ": " + std::strerror(error_number) + "; " + advice;
}

std::string read_regular_file(const fs::path& file, const std::string& what_to_do, std::uintmax_t max_bytes,
                              bool follow_links) {
  const int flags = O_RDONLY | O_NONBLOCK | O_CLOEXEC | (follow_links ? 0 : O_NOFOLLOW);
  Descriptor fd(::open(file.c_str(), flags));
  if (fd.get() < 0) {
    const int error = errno;
    if (error == ELOOP)
      throw InputError(file.string() + ": is a symbolic link, which animpak does not follow inside an output folder; " +
                       what_to_do);
    throw InputError(file.string() + ": cannot read it (" + std::strerror(error) + "); " + what_to_do);
  }
  struct stat info {};
  if (::fstat(fd.get(), &info) != 0 || !S_ISREG(info.st_mode))
    throw InputError(file.string() + ": not a regular file (a folder, FIFO or device); " + what_to_do);
  if (static_cast<std::uintmax_t>(info.st_size) > max_bytes)
    throw InputError(file.string() + ": it is " + std::to_string(info.st_size) + " bytes, more than the limit of " +
                     std::to_string(max_bytes) + "; " + what_to_do);
  // O_NONBLOCK only kept the open from waiting on a FIFO; a regular file reads the same either way.
  std::string bytes(static_cast<std::size_t>(info.st_size), '\0');
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(fd.get(), bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(file.string() + ": cannot read it (" + std::strerror(errno) + "); " + what_to_do);
    if (n == 0) break;  // shrank while read: what is there
    done += static_cast<std::size_t>(n);
  }
  bytes.resize(done);
  return bytes;
}

void write_file_atomically(const fs::path& file, std::string_view bytes) {
  fs::path temporary = file;
  temporary += ".partial";
  // O_NOFOLLOW: a link planted at the temporary name is not written through; it is replaced.
  ::unlink(temporary.c_str());
  Descriptor fd(::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644));
  if (fd.get() < 0) throw InputError(file_error(file, "cannot write it", errno));
  const auto fail = [&](int error) {
    ::unlink(temporary.c_str());
    throw InputError(file_error(file, "cannot write it", error));
  };
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd.get(), bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(errno);
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd.get()) != 0) fail(errno);
  if (const int error = fd.close()) fail(error);
  if (::rename(temporary.c_str(), file.c_str()) != 0) fail(errno);
}

void sync_written_file(const fs::path& file) {
  Descriptor fd(::open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC));
  if (fd.get() < 0) throw InputError(file_error(file, "cannot check what was written", errno));
  struct stat info {};
  if (::fstat(fd.get(), &info) != 0 || !S_ISREG(info.st_mode) || info.st_size == 0)
    throw InputError(file.string() +
                     ": was written empty or not as a file; free disk space and check the folder, then run the "
                     "command again");
  if (::fsync(fd.get()) != 0) throw InputError(file_error(file, "cannot flush it to disk", errno));
}

void sync_folder(const fs::path& dir) {
  Descriptor fd(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (fd.get() >= 0) ::fsync(fd.get());
}

void refuse_links_below(const fs::path& dir, const fs::path& relative, const std::string& what_to_do) {
  fs::path at = dir;
  std::error_code ec;
  const auto check = [&](const fs::path& p) {
    if (fs::is_symlink(fs::symlink_status(p, ec)))
      throw InputError(p.string() + ": is a symbolic link, which animpak does not follow inside an output folder; " +
                       what_to_do);
  };
  for (const fs::path& part : relative) {
    at /= part;
    check(at);
  }
}

}  // namespace animpak
