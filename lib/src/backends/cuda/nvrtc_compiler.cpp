// arnoldweb: NVRTC compilation of the CUDA ensemble kernel from the embedded
// sources (see nvrtc_compiler.hpp).
#include "backends/cuda/nvrtc_compiler.hpp"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "arnoldweb/errors.hpp"
#include "backends/cuda/nvrtc_api.hpp"
#include "backends/kernel_sources.hpp"

namespace arnoldweb::detail {
namespace {

[[noreturn]] void throw_nvrtc(const std::string& device, const char* call, nvrtcResult r) {
  throw DeviceError(device, call, static_cast<long>(r),
                    std::string("NVRTC failed: ") + nvrtc(device).GetErrorString(r));
}

void nvrtc_check(nvrtcResult r, const std::string& device, const char* call) {
  if (r != NVRTC_SUCCESS) throw_nvrtc(device, call, r);
}

// The headers NVRTC resolves #include against, kept alive for the process.
struct HeaderSet {
  std::vector<std::pair<std::string, std::string>> files = nvrtc_headers();
  std::vector<const char*> names, texts;
  HeaderSet() {
    for (const auto& [name, text] : files) {
      names.push_back(name.c_str());
      texts.push_back(text.c_str());
    }
  }
};

const HeaderSet& headers() {
  static const HeaderSet h;
  return h;
}

// nvrtcProgram, destroyed on every path.
struct Program {
  nvrtcProgram p = nullptr;
  const NvrtcApi& api;
  explicit Program(const NvrtcApi& a) : api(a) {}
  ~Program() {
    if (p) api.DestroyProgram(&p);
  }
};

std::string program_log(const NvrtcApi& api, nvrtcProgram p) {
  std::size_t n = 0;
  if (api.GetProgramLogSize(p, &n) != NVRTC_SUCCESS || n == 0) return {};
  std::string log(n, '\0');
  if (api.GetProgramLog(p, log.data()) != NVRTC_SUCCESS) return {};
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : " ") + x;
  return s;
}

}  // namespace

std::string CudaTarget::name() const {
  return (cubin ? "sm_" : "compute_") + std::to_string(arch);
}

std::string nvrtc_version() {
  const NvrtcApi* api = nvrtc_api();
  if (!api) return "none";
  int major = 0, minor = 0;
  if (api->Version(&major, &minor) != NVRTC_SUCCESS) return "unknown";
  return std::to_string(major) + "." + std::to_string(minor);
}

std::vector<int> nvrtc_supported_archs() {
  const NvrtcApi* api = nvrtc_api();
  int n = 0;
  if (!api || api->GetNumSupportedArchs(&n) != NVRTC_SUCCESS || n <= 0) return {};
  std::vector<int> archs(static_cast<std::size_t>(n));
  if (api->GetSupportedArchs(archs.data()) != NVRTC_SUCCESS) return {};
  std::sort(archs.begin(), archs.end());
  return archs;
}

CudaTarget nvrtc_target(int cc, const std::string& device) {
  nvrtc(device);  // a DeviceError saying where NVRTC was looked for, when it is not there
  const std::vector<int> archs = nvrtc_supported_archs();
  CudaTarget t;
  if (std::find(archs.begin(), archs.end(), cc) != archs.end()) {
    t.arch = cc;
    t.cubin = true;
    return t;
  }
  // Not one this NVRTC emits CUBINs for (a newer chip): PTX for the newest
  // architecture below it; the driver compiles it when the module is loaded.
  for (int a : archs)
    if (a < cc) t.arch = a;
  if (t.arch == 0) {
    std::string known;
    for (int a : archs) known += (known.empty() ? "" : " ") + std::to_string(a);
    throw DeviceError(device, "", 0,
                      "compute capability " + std::to_string(cc / 10) + "." + std::to_string(cc % 10) +
                          " is not supported by NVRTC " + nvrtc_version() +
                          " (architectures: " + (known.empty() ? "none" : known) + ")");
  }
  t.cubin = false;
  return t;
}

std::vector<std::string> nvrtc_options(const std::string& defines, const CudaTarget& target) {
  // Bitwise parity with the cpu and OpenCL backends: no FP contraction, IEEE
  // division and square root, denormals kept. Warning 161 is "unrecognized
  // #pragma" (the OpenCL pragmas the portable headers carry).
  std::vector<std::string> o = {"--gpu-architecture=" + target.name(),
                                "--fmad=false",
                                "--prec-div=true",
                                "--prec-sqrt=true",
                                "--ftz=false",
                                "-default-device",
                                "-std=c++17",
                                "-diag-suppress=161"};
  std::istringstream in(defines);
  std::string word;
  while (in >> word) o.push_back(word);
  // Tuning hook (bench/NOTES.md): extra NVRTC options, e.g.
  // ARNOLDWEB_NVRTC_OPTIONS=-DAW_CUDA_MIN_BLOCKS=6. Part of the cache key.
  if (const char* extra = std::getenv("ARNOLDWEB_NVRTC_OPTIONS")) {
    std::istringstream ex(extra);
    while (ex >> word) o.push_back(word);
  }
  return o;
}

std::string nvrtc_option_line(const std::string& defines, const CudaTarget& target) {
  return join(nvrtc_options(defines, target));
}

CudaImage nvrtc_compile_ensemble(const std::string& defines, const CudaTarget& target,
                                 const std::string& device, const std::string& model_source) {
  const std::vector<std::string> opts = nvrtc_options(defines, target);
  std::vector<const char*> argv;
  for (const auto& o : opts) argv.push_back(o.c_str());
  CudaImage img;
  img.target = target;
  img.options = join(opts);

  static const std::string source(embedded_file("ensemble.cu"));
  const HeaderSet* set = &headers();
  HeaderSet with_model;  // the embedded headers and an expression model's
  if (!model_source.empty()) {
    with_model.files.emplace_back(expression_model_header(), model_source);
    with_model.names.clear();
    with_model.texts.clear();
    for (const auto& [name, text] : with_model.files) {
      with_model.names.push_back(name.c_str());
      with_model.texts.push_back(text.c_str());
    }
    set = &with_model;
  }
  const HeaderSet& h = *set;
  const NvrtcApi& api = nvrtc(device);
  Program prog(api);
  nvrtc_check(api.CreateProgram(&prog.p, source.c_str(), "ensemble.cu",
                                 static_cast<int>(h.names.size()), h.texts.data(), h.names.data()),
              device, "nvrtcCreateProgram");
  const nvrtcResult r = api.CompileProgram(prog.p, static_cast<int>(argv.size()), argv.data());
  img.log = program_log(api, prog.p);
  if (r != NVRTC_SUCCESS) {
    std::string log = std::string(api.GetErrorString(r)) + " (NVRTC " + nvrtc_version() + ")\n" +
                      (img.log.empty() ? "(empty compiler log)" : img.log);
    throw BuildError(device, img.options, log);
  }
  std::size_t n = 0;
  if (target.cubin) {
    nvrtc_check(api.GetCUBINSize(prog.p, &n), device, "nvrtcGetCUBINSize");
    img.data.assign(n, '\0');
    if (n) nvrtc_check(api.GetCUBIN(prog.p, img.data.data()), device, "nvrtcGetCUBIN");
  } else {
    nvrtc_check(api.GetPTXSize(prog.p, &n), device, "nvrtcGetPTXSize");
    img.data.assign(n, '\0');  // n counts the terminating NUL
    if (n) nvrtc_check(api.GetPTX(prog.p, img.data.data()), device, "nvrtcGetPTX");
  }
  if (img.data.empty())
    throw BuildError(device, img.options, "NVRTC reported success but produced an empty image\n" + img.log);
  return img;
}

}  // namespace arnoldweb::detail
