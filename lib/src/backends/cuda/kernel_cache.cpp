// arnoldweb: in-memory and on-disk caches of CUDA kernel images (see
// kernel_cache.hpp).
#include "backends/cuda/kernel_cache.hpp"

#include <unistd.h>
#include <xxhash.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

#include "backends/kernel_sources.hpp"

namespace fs = std::filesystem;

namespace arnoldweb::detail {
namespace {

// File layout: magic, then the XXH64 of the payload (8 bytes, little end
// first), then the payload (the image).
constexpr char kMagic[8] = {'A', 'W', 'C', 'U', 'D', 'A', '0', '1'};

std::mutex cache_mutex;
std::map<std::string, std::shared_ptr<const CudaImage>>& memory_cache() {
  static std::map<std::string, std::shared_ptr<const CudaImage>> m;
  return m;
}

std::string key_of(const std::string& defines, const CudaTarget& target, const std::string& model_source) {
  std::string k;
  for (const auto& o : nvrtc_options(defines, target)) k += o + '\n';
  if (!model_source.empty()) k += "expression model\n" + model_source;  // hashed into the file name
  return k;
}

// Hash of every embedded source NVRTC sees, computed once.
XXH128_hash_t sources_hash() {
  static const XXH128_hash_t h = [] {
    XXH3_state_t* st = XXH3_createState();
    XXH3_128bits_reset(st);
    for (const auto& [name, text] : nvrtc_headers()) {
      XXH3_128bits_update(st, name.data(), name.size() + 1);
      const std::uint64_t n = text.size();
      XXH3_128bits_update(st, &n, sizeof n);
      XXH3_128bits_update(st, text.data(), text.size());
    }
    const std::string_view main = embedded_file("ensemble.cu");
    XXH3_128bits_update(st, main.data(), main.size());
    XXH128_hash_t r = XXH3_128bits_digest(st);
    XXH3_freeState(st);
    return r;
  }();
  return h;
}

std::string file_name(const std::string& key, const CudaTarget& target) {
  const XXH128_hash_t src = sources_hash();
  std::string fp = "arnoldweb cuda image v1\nnvrtc " + nvrtc_version() + "\n" + key;
  fp.append(reinterpret_cast<const char*>(&src.low64), 8);
  fp.append(reinterpret_cast<const char*>(&src.high64), 8);
  const XXH128_hash_t h = XXH3_128bits(fp.data(), fp.size());
  char hex[33];
  std::snprintf(hex, sizeof hex, "%016llx%016llx", static_cast<unsigned long long>(h.high64),
                static_cast<unsigned long long>(h.low64));
  return std::string(hex) + (target.cubin ? ".cubin" : ".ptx");
}

std::string le64(std::uint64_t v) {
  std::string s(8, '\0');
  for (int i = 0; i < 8; ++i) s[i] = static_cast<char>((v >> (8 * i)) & 0xff);
  return s;
}

bool read_disk(const fs::path& file, std::string& payload) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return false;
  std::ostringstream buf;
  buf << in.rdbuf();
  const std::string all = buf.str();
  if (all.size() <= 16 || std::memcmp(all.data(), kMagic, 8) != 0) return false;
  payload = all.substr(16);
  return all.compare(8, 8, le64(XXH64(payload.data(), payload.size(), 0))) == 0;
}

void write_disk(const fs::path& file, const std::string& payload) {
  try {
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    if (ec) return;
    static std::atomic<unsigned> serial{0};
    const fs::path tmp = file.string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                         std::to_string(serial++);
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      if (!out) return;
      out.write(kMagic, 8);
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

}  // namespace

std::string cuda_cache_dir() {
  const char* env = std::getenv("ARNOLDWEB_CACHE_DIR");
  if (env) {
    if (!*env || std::strcmp(env, "off") == 0 || std::strcmp(env, "0") == 0) return {};
    return (fs::path(env) / "cuda").string();
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return (fs::path(xdg) / "arnoldweb" / "cuda").string();
  if (const char* home = std::getenv("HOME"); home && *home)
    return (fs::path(home) / ".cache" / "arnoldweb" / "cuda").string();
  return {};
}

CachedImage cuda_ensemble_image(const std::string& defines, const CudaTarget& target,
                                const std::string& device, const std::string& model_source) {
  std::lock_guard<std::mutex> lock(cache_mutex);
  const std::string key = key_of(defines, target, model_source);
  auto& mem = memory_cache();
  if (auto it = mem.find(key); it != mem.end()) return {it->second, "memory"};

  const std::string dir = cuda_cache_dir();
  fs::path file;
  if (!dir.empty()) {
    try {
      file = fs::path(dir) / file_name(key, target);
      std::string payload;
      if (read_disk(file, payload)) {
        auto img = std::make_shared<CudaImage>();
        img->data = std::move(payload);
        img->target = target;
        img->options = nvrtc_option_line(defines, target);
        mem[key] = img;
        return {img, "disk"};
      }
    } catch (...) {
      file.clear();  // unreadable cache: compile
    }
  }

  auto img = std::make_shared<const CudaImage>(nvrtc_compile_ensemble(defines, target, device, model_source));
  mem[key] = img;
  if (!file.empty()) write_disk(file, img->data);
  return {img, "compiled"};
}

void cuda_clear_memory_cache() {
  std::lock_guard<std::mutex> lock(cache_mutex);
  memory_cache().clear();
}

void cuda_forget_image(const std::string& defines, const CudaTarget& target, const std::string& model_source) {
  std::lock_guard<std::mutex> lock(cache_mutex);
  const std::string key = key_of(defines, target, model_source);
  memory_cache().erase(key);
  const std::string dir = cuda_cache_dir();
  if (dir.empty()) return;
  try {
    std::error_code ec;
    fs::remove(fs::path(dir) / file_name(key, target), ec);
  } catch (...) {
  }
}

}  // namespace arnoldweb::detail
