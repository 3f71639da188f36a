// arnoldweb: NVRTC opened with dlopen (see nvrtc_api.hpp).
#include "backends/cuda/nvrtc_api.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <vector>

#include "arnoldweb/errors.hpp"
#include "os/shared_object.hpp"

namespace arnoldweb::detail {
namespace {

constexpr const char* kSonames[] = {"libnvrtc.so.13", "libnvrtc.so.12"};

}  // namespace

std::vector<std::string> nvrtc_candidates() {
  if (const char* forced = std::getenv("ARNOLDWEB_NVRTC"); forced && *forced) return {forced};
  std::vector<std::string> c(std::begin(kSonames), std::end(kSonames));
  std::vector<std::string> dirs;
  if (const std::string own = this_library_dir(); !own.empty()) {
    dirs.push_back(own + "/../nvidia/cu13/lib");
    dirs.push_back(own + "/../nvidia/cuda_nvrtc/lib");
  }
  for (const char* var : {"CUDA_HOME", "CUDA_PATH"})
    if (const char* root = std::getenv(var); root && *root) dirs.push_back(std::string(root) + "/lib64");
  dirs.push_back("/usr/local/cuda/lib64");
  for (const auto& d : dirs)
    for (const char* so : kSonames) c.push_back(d + "/" + so);
  return c;
}

namespace {

template <class F>
bool bind(void* lib, const char* name, F& f) {
  f = reinterpret_cast<F>(dlsym(lib, name));
  return f != nullptr;
}

struct Loaded {
  NvrtcApi api;
  bool ok = false;
  std::string problem;
};

// Opens the first usable candidate; `keep`: leave it open (else close it).
Loaded load(const std::vector<std::string>& candidates, bool keep) {
  Loaded r;
  std::string tried;
  for (const std::string& name : candidates) {
    void* lib = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
      tried += (tried.empty() ? "" : ", ") + name;
      continue;
    }
    NvrtcApi& a = r.api;
    const bool all = bind(lib, "nvrtcGetErrorString", a.GetErrorString) && bind(lib, "nvrtcVersion", a.Version) &&
                     bind(lib, "nvrtcGetNumSupportedArchs", a.GetNumSupportedArchs) &&
                     bind(lib, "nvrtcGetSupportedArchs", a.GetSupportedArchs) &&
                     bind(lib, "nvrtcCreateProgram", a.CreateProgram) &&
                     bind(lib, "nvrtcDestroyProgram", a.DestroyProgram) &&
                     bind(lib, "nvrtcCompileProgram", a.CompileProgram) &&
                     bind(lib, "nvrtcGetProgramLogSize", a.GetProgramLogSize) &&
                     bind(lib, "nvrtcGetProgramLog", a.GetProgramLog) &&
                     bind(lib, "nvrtcGetCUBINSize", a.GetCUBINSize) && bind(lib, "nvrtcGetCUBIN", a.GetCUBIN) &&
                     bind(lib, "nvrtcGetPTXSize", a.GetPTXSize) && bind(lib, "nvrtcGetPTX", a.GetPTX);
    if (!all) {
      tried += (tried.empty() ? "" : ", ") + name + " (lacks a function the CUDA backend calls)";
      dlclose(lib);
      r.api = NvrtcApi{};
      continue;
    }
    a.path = name;
    r.ok = true;
    if (!keep) dlclose(lib);  // else kept open for the life of the process
    return r;
  }
  r.problem = "NVRTC (the CUDA runtime compiler) was not found: tried " + tried +
              "; install the CUDA toolkit or `pip install nvidia-cuda-nvrtc`, or set ARNOLDWEB_NVRTC to "
              "the path of libnvrtc.so";
  return r;
}

}  // namespace

std::string nvrtc_check_candidates(const std::vector<std::string>& candidates) {
  return load(candidates, false).problem;
}

std::string nvrtc_library(std::string* problem) {
  const NvrtcApi* api = nvrtc_api(problem);
  return api ? api->path : std::string();
}

const NvrtcApi* nvrtc_api(std::string* problem) {
  static const Loaded loaded = load(nvrtc_candidates(), true);
  if (!loaded.ok && problem) *problem = loaded.problem;
  return loaded.ok ? &loaded.api : nullptr;
}

const NvrtcApi& nvrtc(const std::string& device) {
  std::string problem;
  if (const NvrtcApi* a = nvrtc_api(&problem)) return *a;
  throw DeviceError(device, "dlopen", 0, problem);
}

}  // namespace arnoldweb::detail
