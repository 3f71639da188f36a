#include "naive_cuda_loader.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <vector>

namespace arnoldweb::bench {
namespace {

std::string exe_dir() {
  std::vector<char> buf(4096);
  const ssize_t n = readlink("/proc/self/exe", buf.data(), buf.size() - 1);
  if (n <= 0) return ".";
  std::string p(buf.data(), static_cast<std::size_t>(n));
  const auto slash = p.rfind('/');
  return slash == std::string::npos ? "." : p.substr(0, slash);
}

NaiveCuda load() {
  NaiveCuda nc;
  std::vector<std::string> candidates;
  if (const char* env = std::getenv("ARNOLDWEB_NAIVE_CUDA")) candidates.push_back(env);
  candidates.push_back(exe_dir() + "/libarnoldweb_naive_cuda.so");
#ifdef ARNOLDWEB_BINARY_DIR
  candidates.push_back(std::string(ARNOLDWEB_BINARY_DIR) + "/libarnoldweb_naive_cuda.so");
#endif
  std::string why;
  for (const auto& c : candidates) {
    if (access(c.c_str(), R_OK) != 0) continue;
    void* h = dlopen(c.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!h) {
      why += std::string(" ") + dlerror();
      continue;
    }
    nc.run = reinterpret_cast<AwNaiveCudaRun>(dlsym(h, "aw_naive_cuda_run"));
    nc.mem_info = reinterpret_cast<AwNaiveCudaMemInfo>(dlsym(h, "aw_naive_cuda_mem_info"));
    if (nc.run) {
      nc.path = c;
      return nc;
    }
    why += " " + c + " lacks aw_naive_cuda_run;";
  }
  nc.problem = "naive CUDA baseline not available (libarnoldweb_naive_cuda.so is built where CMake finds "
               "nvcc);" + why;
  return nc;
}

}  // namespace

const NaiveCuda& naive_cuda() {
  static const NaiveCuda nc = load();
  return nc;
}

}  // namespace arnoldweb::bench
