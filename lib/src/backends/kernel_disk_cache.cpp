// arnoldweb: the disk cache of kernels compiled at run time (kernel_disk_cache.hpp).
#include "backends/kernel_disk_cache.hpp"

#include <unistd.h>
#include <xxhash.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace arnoldweb::detail {
namespace {

std::string le64(std::uint64_t v) {
  std::string s(8, '\0');
  for (int i = 0; i < 8; ++i) s[i] = static_cast<char>((v >> (8 * i)) & 0xff);
  return s;
}

}  // namespace

std::string kernel_cache_dir(const std::string& kind) {
  const char* env = std::getenv("ARNOLDWEB_CACHE_DIR");
  if (env) {
    if (!*env || std::strcmp(env, "off") == 0 || std::strcmp(env, "0") == 0) return {};
    return (fs::path(env) / kind).string();
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return (fs::path(xdg) / "arnoldweb" / kind).string();
  if (const char* home = std::getenv("HOME"); home && *home)
    return (fs::path(home) / ".cache" / "arnoldweb" / kind).string();
  return {};
}

std::string kernel_cache_file_name(const std::string& fingerprint, const std::string& extension) {
  const XXH128_hash_t h = XXH3_128bits(fingerprint.data(), fingerprint.size());
  char hex[33];
  std::snprintf(hex, sizeof hex, "%016llx%016llx", static_cast<unsigned long long>(h.high64),
                static_cast<unsigned long long>(h.low64));
  return std::string(hex) + extension;
}

bool read_cache_file(const std::string& path, const char (&magic)[8], std::string& payload) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream buf;
  buf << in.rdbuf();
  const std::string all = buf.str();
  if (all.size() <= 16 || std::memcmp(all.data(), magic, 8) != 0) return false;
  payload = all.substr(16);
  return all.compare(8, 8, le64(XXH64(payload.data(), payload.size(), 0))) == 0;
}

void write_cache_file(const std::string& path, const char (&magic)[8], const std::string& payload) {
  try {
    const fs::path file(path);
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    if (ec) return;
    static std::atomic<unsigned> serial{0};
    const fs::path tmp = file.string() + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(serial++);
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      if (!out) return;
      out.write(magic, 8);
      const std::string sum = le64(XXH64(payload.data(), payload.size(), 0));
      out.write(sum.data(), 8);
      out.write(payload.data(), static_cast<std::streamsize>(payload.size()));
      out.close();
      if (!out) {
        fs::remove(tmp, ec);
        return;
      }
    }
    fs::rename(tmp, file, ec);
    if (ec) fs::remove(tmp, ec);
  } catch (...) {
    // a cache that cannot be written is no error
  }
}

}  // namespace arnoldweb::detail
