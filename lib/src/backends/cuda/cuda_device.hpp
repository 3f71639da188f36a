// arnoldweb: finding and describing CUDA devices through the CUDA runtime
// (linked statically; it loads libcuda.so.1 itself, so a machine without the
// NVIDIA driver runs the library and simply has no cuda:N devices).
#pragma once

#include <string>

#include "arnoldweb/device.hpp"

namespace arnoldweb::detail {

// Number of CUDA devices; 0 with the reason in `problem` ("cuda: no CUDA
// driver found ...", "cuda: driver too old: ...", "cuda: no CUDA device ...").
int cuda_device_count(std::string& problem);

// DeviceInfo of CUDA device `ordinal` (id "cuda:<ordinal>"); throws DeviceError.
DeviceInfo cuda_describe(int ordinal);

// Compute capability of device `ordinal` as major * 10 + minor; throws DeviceError.
int cuda_compute_capability(int ordinal);

}  // namespace arnoldweb::detail
