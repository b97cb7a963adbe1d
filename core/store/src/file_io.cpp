#include "file_io.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

namespace strahler::store::detail {
namespace {

using base::ErrorCode;

base::Error ioError(std::string_view what, const std::string& path, int error) {
  return base::makeError(ErrorCode::kIoError,
                         std::string(what) + " '" + path + "': " + std::strerror(error));
}

/// Closes a descriptor on scope exit unless released.
class FileDescriptor {
public:
  explicit FileDescriptor(int fd) noexcept : fd_(fd) {}
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  ~FileDescriptor() {
    if (fd_ >= 0)
      ::close(fd_);
  }
  int get() const noexcept { return fd_; }
  /// Closes now; returns 0 or the errno of close().
  int close() noexcept {
    const int result = ::close(fd_);
    fd_ = -1;
    return result == 0 ? 0 : errno;
  }

private:
  int fd_;
};

/// Writes all of `bytes`, retrying on EINTR and short writes; 0 or errno.
int writeAll(int fd, std::string_view bytes) noexcept {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
      return n < 0 ? errno : EIO;
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return 0;
}

/// Opens a fresh temporary file beside `path`; its name is stored in *tempPath.
int openTempFile(const std::string& path, std::string* tempPath) {
  static std::atomic<std::uint64_t> counter{0};
  for (int attempt = 0; attempt < 100; ++attempt) {
    *tempPath =
        path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter.fetch_add(1));
    const int fd = ::open(tempPath->c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd >= 0 || errno != EEXIST)
      return fd;
  }
  errno = EEXIST;
  return -1;
}

/// Writes, fsyncs and closes the temp file; 0 or errno.
int fillTempFile(FileDescriptor& fd, std::string_view bytes) {
  if (const int error = writeAll(fd.get(), bytes))
    return error;
  if (::fsync(fd.get()) != 0)
    return errno;
  return fd.close();
}

/// fsync of the directory holding `path`, so that the rename survives a crash.
int syncParentDirectory(const std::string& path) {
  std::string dir = std::filesystem::path(path).parent_path().string();
  if (dir.empty())
    dir = ".";
  FileDescriptor fd(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (fd.get() < 0)
    return errno;
  // Some file systems cannot sync a directory; the rename is still done.
  if (::fsync(fd.get()) != 0 && errno != EINVAL)
    return errno;
  return 0;
}

/// The writer's PID of a temporary file named "<target>.tmp.<pid>.<n>" with `target` ending
/// in `suffix`, or 0 when `name` is not such a file.
pid_t tempFileOwner(std::string_view name, std::string_view suffix) {
  const std::size_t dot = name.rfind('.');
  if (dot == std::string_view::npos || dot + 1 == name.size() ||
      name.find_first_not_of("0123456789", dot + 1) != std::string_view::npos)
    return 0;
  const std::size_t pidDot = name.rfind('.', dot - 1);
  if (pidDot == std::string_view::npos || pidDot + 1 == dot || dot - pidDot > 10 ||
      name.substr(pidDot + 1, dot - pidDot - 1).find_first_not_of("0123456789") !=
          std::string_view::npos)
    return 0;
  const std::string_view target = name.substr(0, pidDot);
  constexpr std::string_view kTmp = ".tmp";
  if (target.size() < kTmp.size() + suffix.size() + 1 ||
      target.substr(target.size() - kTmp.size()) != kTmp ||
      target.substr(target.size() - kTmp.size() - suffix.size(), suffix.size()) != suffix)
    return 0;
  return static_cast<pid_t>(std::stol(std::string(name.substr(pidDot + 1, dot - pidDot - 1))));
}

/// False only when no process `pid` exists (EPERM means one exists, owned by someone else).
bool processAlive(pid_t pid) {
  return ::kill(pid, 0) == 0 || errno != ESRCH;
}

} // namespace

std::size_t removeStaleTempFiles(const std::string& dir, std::string_view suffix,
                                 std::chrono::seconds maxAge) {
  namespace fs = std::filesystem;
  std::error_code error;
  fs::directory_iterator it(dir.empty() ? "." : dir, error);
  std::size_t removed = 0;
  const auto now = fs::file_time_type::clock::now();
  for (; !error && it != fs::directory_iterator(); it.increment(error)) {
    const std::string name = it->path().filename().string();
    const pid_t owner = tempFileOwner(name, suffix);
    std::error_code typeError;
    if (owner <= 0 || !it->is_regular_file(typeError))
      continue;
    const bool ownerGone = owner != ::getpid() && !processAlive(owner);
    std::error_code timeError;
    const auto written = fs::last_write_time(it->path(), timeError);
    const bool old = !timeError && now - written > maxAge;
    if ((ownerGone || old) && ::unlink(it->path().c_str()) == 0)
      ++removed;
  }
  return removed;
}

base::Status writeFileAtomically(const std::string& path, std::string_view bytes) {
  std::string tempPath;
  FileDescriptor fd(openTempFile(path, &tempPath));
  if (fd.get() < 0)
    return ioError("cannot create a temporary file for", path, errno);
  if (const int error = fillTempFile(fd, bytes)) {
    ::unlink(tempPath.c_str());
    return ioError("cannot write a temporary file for", path, error);
  }
  if (::rename(tempPath.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(tempPath.c_str());
    return ioError("cannot rename the temporary file over", path, error);
  }
  if (const int error = syncParentDirectory(path))
    return ioError("cannot sync the directory of", path, error);
  return base::Ok{};
}

base::Result<std::string> readWholeFile(const std::string& path, std::uint64_t maxBytes) {
  FileDescriptor fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (fd.get() < 0) {
    if (errno == ENOENT)
      return base::makeError(ErrorCode::kNotFound, "no file '" + path + "'");
    return ioError("cannot open", path, errno);
  }
  struct stat info {};
  if (::fstat(fd.get(), &info) != 0)
    return ioError("cannot stat", path, errno);
  if (!S_ISREG(info.st_mode))
    return base::makeError(ErrorCode::kIoError, "'" + path + "' is not a regular file");
  const auto size = static_cast<std::uint64_t>(info.st_size);
  if (size > maxBytes)
    return base::makeError(ErrorCode::kCorrupt, "'" + path + "' is " + std::to_string(size) +
                                                    " bytes, more than the limit of " +
                                                    std::to_string(maxBytes));
  std::string bytes(static_cast<std::size_t>(size), '\0');
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(fd.get(), bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR)
      continue;
    if (n < 0)
      return ioError("cannot read", path, errno);
    if (n == 0)
      break; // The file shrank while we read it: what we have is what it holds.
    done += static_cast<std::size_t>(n);
  }
  bytes.resize(done);
  return bytes;
}

} // namespace strahler::store::detail
