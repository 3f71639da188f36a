#include "output/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/output.hpp"

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

}  // namespace

void sync_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw OutputError(path, std::string("cannot reopen to flush: ") + std::strerror(errno));
  // (messages name the temporary's final path: callers pass the final name)
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0) throw OutputError(path, std::string("cannot flush to disk: ") + std::strerror(err));
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
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
      throw OutputError(path, std::string("cannot rename into place: ") + std::strerror(errno));
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
}

}  // namespace detail

void write_text_file(const std::string& path, const std::string& text) {
  detail::write_atomically(path, [&](const std::string& tmp) {
    FILE* f = std::fopen(tmp.c_str(), "wb");
    if (!f) throw OutputError(path, std::string("cannot create: ") + std::strerror(errno));
    const std::size_t n = std::fwrite(text.data(), 1, text.size(), f);
    const int write_err = (n != text.size()) ? errno : 0;
    const int close_rc = std::fclose(f);
    if (n != text.size())
      throw OutputError(path, std::string("write failed: ") + std::strerror(write_err ? write_err : EIO));
    if (close_rc != 0) throw OutputError(path, std::string("write failed: ") + std::strerror(errno));
  });
}

}  // namespace arnoldweb
