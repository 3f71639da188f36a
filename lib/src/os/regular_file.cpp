// arnoldweb: reading a plain file without blocking (regular_file.hpp).
#include "os/regular_file.hpp"

#include <fcntl.h>
#include <linux/magic.h>
#include <sys/stat.h>
#include <sys/vfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace arnoldweb::detail {
namespace {

// Closes the descriptor on every path out.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

// The kernel's pseudo file systems: their "files" are interfaces.
bool pseudo_file_system(int fd) {
  struct statfs fs {};
  if (::fstatfs(fd, &fs) != 0) return false;
  switch (static_cast<unsigned long>(fs.f_type)) {
    case PROC_SUPER_MAGIC:
    case SYSFS_MAGIC:
    case DEBUGFS_MAGIC:
    case TRACEFS_MAGIC:
    case SECURITYFS_MAGIC:
    case CGROUP_SUPER_MAGIC:
    case CGROUP2_SUPER_MAGIC:
    case BPF_FS_MAGIC:
      return true;
    default:
      return false;
  }
}

const char* not_regular(mode_t mode) {
  if (S_ISDIR(mode)) return "it is a directory";
  if (S_ISFIFO(mode)) return "it is a pipe (FIFO), not a file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "it is a device, not a file";
  if (S_ISSOCK(mode)) return "it is a socket, not a file";
  return "it is not a regular file";
}

RegularFile failed(int err, std::string why) {
  RegularFile f;
  f.error = err;
  f.why = std::move(why);
  return f;
}

// Opens `path` without blocking and checks that it is a plain file: its
// descriptor and size, or why not.
RegularFile open_plain(const std::string& path, Fd& f) {
  if (path.empty()) return failed(ENOENT, "no file name given");
  if (path.find('\0') != std::string::npos) return failed(EINVAL, "the name holds a NUL character");
  f.fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (f.fd < 0) return failed(errno, std::strerror(errno));
  struct stat st {};
  if (::fstat(f.fd, &st) != 0) return failed(errno, std::strerror(errno));
  if (!S_ISREG(st.st_mode)) return failed(0, not_regular(st.st_mode));
  if (pseudo_file_system(f.fd)) return failed(0, "it is a file of the kernel (/proc, /sys), not a file with contents");
  RegularFile out;
  out.size = static_cast<std::uint64_t>(st.st_size);
  return out;
}

}  // namespace

OpenPlainFile::OpenPlainFile(const std::string& path) : path_(path) {
  Fd f{-1};
  const RegularFile r = open_plain(path, f);
  why_ = r.why;
  error_ = r.error;
  size_ = r.size;
  if (why_.empty()) std::swap(fd_, f.fd);
}

OpenPlainFile::~OpenPlainFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::string OpenPlainFile::name() const {
  const std::string self = "/proc/self/fd/" + std::to_string(fd_);
  struct stat a {}, b {};
  // the same file through /proc (mounted nearly everywhere), else its path
  if (fd_ >= 0 && ::fstat(fd_, &a) == 0 && ::stat(self.c_str(), &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino)
    return self;
  return path_;
}

RegularFile read_regular_file(const std::string& path, std::uint64_t max_bytes) {
  Fd f{-1};
  RegularFile out = open_plain(path, f);
  if (!out.why.empty()) return out;
  if (out.size > max_bytes) {
    out.why = "it is " + std::to_string(out.size) + " bytes; at most " + std::to_string(max_bytes) + " bytes are read";
    return out;
  }
  out.bytes.reserve(static_cast<std::size_t>(out.size));
  char buf[1 << 16];
  while (true) {
    const ssize_t n = ::read(f.fd, buf, sizeof buf);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      out.error = errno;
      out.why = errno == EAGAIN ? "reading it would block (not a plain file)" : std::strerror(errno);
      out.bytes.clear();
      return out;
    }
    out.bytes.append(buf, static_cast<std::size_t>(n));
    if (out.bytes.size() > max_bytes) {  // it grew while being read
      out.bytes.clear();
      out.why = "it is larger than " + std::to_string(max_bytes) + " bytes";
      return out;
    }
  }
  return out;
}

}  // namespace arnoldweb::detail
