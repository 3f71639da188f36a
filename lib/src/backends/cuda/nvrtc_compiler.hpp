// arnoldweb: compiling the CUDA ensemble kernel (kernels_cu/ensemble.cu over
// lib/device) with NVRTC from the embedded sources, with the same -D options
// the OpenCL kernels get. Needs no GPU and no driver: only libnvrtc.
// Plain C++ header (no CUDA headers), so the tests can call it.
#pragma once

#include <string>
#include <vector>

namespace arnoldweb::detail {

// What NVRTC emits for a device: a CUBIN for sm_<arch> when NVRTC knows the
// device's architecture, else PTX for compute_<arch> (the newest NVRTC knows
// below the device's), which the driver compiles when the module is loaded.
struct CudaTarget {
  int arch = 0;       // compute capability major * 10 + minor, e.g. 90
  bool cubin = true;  // false: PTX
  std::string name() const;  // "sm_90" or "compute_90"
};

// A compiled kernel image and how it was made.
struct CudaImage {
  std::string data;     // CUBIN (ELF) or NUL-terminated PTX text
  CudaTarget target;
  std::string options;  // the NVRTC options, space-separated
  std::string log;      // the compiler's log (warnings), often empty
};

// "13.0": the NVRTC this process loaded.
std::string nvrtc_version();

// Architectures NVRTC can emit CUBINs for (e.g. 75 80 86 ... 90 ... 121).
std::vector<int> nvrtc_supported_archs();

// The target for a device of compute capability `cc` (major * 10 + minor).
// Throws DeviceError naming `device` when NVRTC supports nothing that old.
CudaTarget nvrtc_target(int cc, const std::string& device);

// The NVRTC options, one per element: target, FP contract off (--fmad=false),
// no fast math (IEEE division and sqrt, no flush to zero), C++17, then the
// defines (`defines` as KernelConfig::defines() writes it, split at spaces).
std::vector<std::string> nvrtc_options(const std::string& defines, const CudaTarget& target);
// The same, space-separated (as BuildError::options() and the summary show it).
std::string nvrtc_option_line(const std::string& defines, const CudaTarget& target);

// Compiles the ensemble kernels (aw_ensemble, aw_fold) for `target`. No
// caching (kernel_cache.hpp caches). Throws BuildError with NVRTC's full log
// and the options when the source does not compile, DeviceError (call,
// status) when NVRTC itself fails. `device` labels the errors. A non-empty
// `model_source` is an expression model's header (models/aw_expression.h).
CudaImage nvrtc_compile_ensemble(const std::string& defines, const CudaTarget& target,
                                 const std::string& device, const std::string& model_source = "");

}  // namespace arnoldweb::detail
