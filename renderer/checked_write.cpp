#include "renderer/checked_write.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace raylab {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& step, int error) {
  throw WriteError("cannot write " + path + ": " + (step.empty() ? "" : step + ": ") + std::strerror(error));
}

// 0, or the errno of the write that failed; short writes are continued (a full disk answers the next one).
int writeAll(int fd, std::string_view bytes) {
  const char* p = bytes.data();
  size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return errno;
    if (n == 0) return EIO;
    p += n;
    left -= static_cast<size_t>(n);
  }
  return 0;
}

// The file a path names: a symbolic link's target (so the link survives the rename), else the path itself.
std::string resolvedTarget(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return path;
  char* real = ::realpath(path.c_str(), nullptr);
  if (!real) return path;  // a dangling link: replaced by the file
  std::string target = real;
  std::free(real);
  return target;
}

// A device or FIFO takes the bytes as they come: nothing to rename, nothing to fsync. `named` is what the
// messages call it.
void writeInPlace(const std::string& target, const std::string& named, std::string_view bytes) {
  const int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) fail(named, "", errno);
  int error = writeAll(fd, bytes);
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) fail(named, "", error);
}

// What a new file gets from open(..., 0666): mkstemp makes 0600, which would hide results from other users.
mode_t newFileMode() {
  const mode_t mask = ::umask(0);  // umask can only be read by setting it
  ::umask(mask);
  return 0666 & ~mask;
}

}  // namespace

void writeFileChecked(const std::string& path, std::string_view bytes) {
  const std::string target = resolvedTarget(path);
  const std::string named = target == path ? path : path + " (a link to " + target + ")";  // what was asked for
  struct stat st {};
  const bool exists = ::stat(target.c_str(), &st) == 0;
  if (exists && !S_ISREG(st.st_mode)) return writeInPlace(target, named, bytes);

  std::filesystem::path folder = std::filesystem::path(target).parent_path();
  if (folder.empty()) folder = ".";
  // Hidden and named after the final file, so one left by a crash says what it was.
  std::string pattern = (folder / ("." + std::filesystem::path(target).filename().string() + ".XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) fail(named, "cannot create a temporary file in " + folder.string(), errno);
  const std::string temp = name.data();

  int error = ::fchmod(fd, exists ? (st.st_mode & 07777) : newFileMode()) == 0 ? 0 : errno;
  std::string step = error != 0 ? "chmod" : "";
  if (error == 0) error = writeAll(fd, bytes);
  if (error == 0 && ::fsync(fd) != 0) error = errno, step = "fsync";
  if (::close(fd) != 0 && error == 0) error = errno, step = "close";
  if (error == 0 && ::rename(temp.c_str(), target.c_str()) != 0) error = errno, step = "rename";
  if (error != 0) {
    ::unlink(temp.c_str());
    fail(named, step, error);
  }
  // The rename is durable once the folder is: best effort, not every file system syncs folders.
  const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

AppendFile::AppendFile(const std::string& path, Start start) : path_(path) {
  const int flags = O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | (start == Start::Empty ? O_TRUNC : 0);
  fd_ = ::open(path.c_str(), flags, 0666);
  if (fd_ < 0) fail(path, "", errno);
}

AppendFile::~AppendFile() {
  if (fd_ >= 0) ::close(fd_);
}

void AppendFile::append(std::string_view bytes, bool durable) {
  if (fd_ < 0) throw WriteError("cannot write " + path_ + ": already closed");
  struct stat st {};
  const bool regular = ::fstat(fd_, &st) == 0 && S_ISREG(st.st_mode);
  int error = writeAll(fd_, bytes);
  if (error == 0 && durable && regular && ::fsync(fd_) != 0) error = errno;
  if (error == 0) return;
  // Cut a half-written record off, so the file still ends on a whole one (best effort: the write failed).
  if (regular) {
    [[maybe_unused]] const int ignored = ::ftruncate(fd_, st.st_size);
  }
  fail(path_, "", error);
}

void AppendFile::close() {
  if (fd_ < 0) return;
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail(path_, "close", errno);
}

}  // namespace raylab
