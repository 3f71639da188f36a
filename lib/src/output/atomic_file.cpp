#include "output/atomic_file.hpp"

#include <fcntl.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/output.hpp"
#include "os/regular_file.hpp"
#include "output/file_digest.hpp"

namespace arnoldweb {
namespace detail {
namespace {

std::string temporary_name(const std::string& path) {
  const std::filesystem::path p(path);
  static int counter = 0;
  const std::string name = "." + p.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                           std::to_string(counter++);
  return (p.parent_path() / name).string();
}

bool out_of_space(int err) { return err == ENOSPC || err == EDQUOT || err == EFBIG; }

std::string why_failed(const std::string& path, int err, std::size_t needed) {
  std::string why = std::strerror(err);
  if (out_of_space(err))
    why += " (" + show_bytes(static_cast<double>(needed)) + " to write, " +
           show_bytes(static_cast<double>(free_bytes(path))) + " free on that file system)";
  return why;
}

}  // namespace

std::string show_bytes(double b) {
  char buf[32];
  if (b >= 1e9) std::snprintf(buf, sizeof buf, "%.1f GB", b / 1e9);
  else if (b >= 1e6) std::snprintf(buf, sizeof buf, "%.1f MB", b / 1e6);
  else if (b >= 1e3) std::snprintf(buf, sizeof buf, "%.1f kB", b / 1e3);
  else std::snprintf(buf, sizeof buf, "%.0f bytes", b);
  return buf;
}

std::uint64_t free_bytes(const std::string& path) {
  std::filesystem::path p = path.empty() ? std::filesystem::path(".") : std::filesystem::path(path);
  std::error_code ec;
  while (!p.empty() && !std::filesystem::exists(p, ec) && p != p.parent_path()) p = p.parent_path();
  if (p.empty()) p = ".";
  struct statvfs st {};
  if (::statvfs(p.c_str(), &st) != 0) return 0;
  return static_cast<std::uint64_t>(st.f_bavail) * static_cast<std::uint64_t>(st.f_frsize);
}

void sync_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw OutputError(path, std::string("cannot reopen to flush: ") + std::strerror(errno));
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0) throw OutputError(path, std::string("cannot flush to disk: ") + std::strerror(err));
}

void write_file_atomically(const std::string& path, const std::string& bytes) {
  const std::string tmp = temporary_name(path);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) throw OutputError(path, "cannot create: " + why_failed(path, errno, bytes.size()));
  std::size_t done = 0;
  int err = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      err = n < 0 ? errno : EIO;
      break;
    }
    done += static_cast<std::size_t>(n);
  }
  if (!err && ::fsync(fd) != 0) err = errno;
  if (::close(fd) != 0 && !err) err = errno;
  if (!err && std::rename(tmp.c_str(), path.c_str()) != 0) err = errno;
  if (err) {
    ::unlink(tmp.c_str());
    throw OutputError(path, "write failed: " + why_failed(path, err, bytes.size()));
  }
  DigestLedger::record(path, digest_bytes(bytes));
}

void write_atomically(const std::string& path, const std::function<void(const std::string&)>& produce) {
  const std::string tmp = temporary_name(path);
  try {
    produce(tmp);
    try {
      sync_file(tmp);
    } catch (const OutputError& e) {
      throw OutputError(path, e.what());
    }
    const RegularFile written = read_regular_file(tmp, UINT64_MAX);  // for the digest
    if (!written.why.empty()) throw OutputError(path, "cannot read back what was written: " + written.why);
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
      throw OutputError(path, std::string("cannot rename into place: ") + std::strerror(errno));
    DigestLedger::record(path, digest_bytes(written.bytes));
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
}

}  // namespace detail

void write_text_file(const std::string& path, const std::string& text) { detail::write_file_atomically(path, text); }

}  // namespace arnoldweb
