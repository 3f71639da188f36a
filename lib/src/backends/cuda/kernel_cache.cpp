// arnoldweb: in-memory and on-disk caches of CUDA kernel images (see
// kernel_cache.hpp).
#include "backends/cuda/kernel_cache.hpp"

#include <xxhash.h>

#include <filesystem>
#include <map>
#include <mutex>

#include "backends/kernel_disk_cache.hpp"
#include "backends/kernel_sources.hpp"

namespace fs = std::filesystem;

namespace arnoldweb::detail {
namespace {

// Cache files: magic, then the XXH64 of the image, then the image (kernel_disk_cache.hpp).
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
  return kernel_cache_file_name(fp, target.cubin ? ".cubin" : ".ptx");
}

}  // namespace

std::string cuda_cache_dir() { return kernel_cache_dir("cuda"); }

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
      if (read_cache_file(file.string(), kMagic, payload)) {
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
  if (!file.empty()) write_cache_file(file.string(), kMagic, img->data);
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
