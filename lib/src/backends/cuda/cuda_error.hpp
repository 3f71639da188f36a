// arnoldweb: CUDA runtime status codes turned into DeviceError (call name,
// status, the runtime's own words, and what to change where that is known).
// Internal to the CUDA backend: includes the CUDA runtime header.
#pragma once

#include <cuda_runtime_api.h>

#include <string>

#include "arnoldweb/errors.hpp"

namespace arnoldweb::detail {

// "cudaErrorMemoryAllocation: out of memory"
inline std::string cuda_status_text(cudaError_t status) {
  const char* name = cudaGetErrorName(status);
  const char* text = cudaGetErrorString(status);
  return std::string(name ? name : "cudaError?") + ": " + (text ? text : "unknown error");
}

// Throws DeviceError for `call` returning `status` on `device` (an id such as
// "cuda:0"). Out-of-memory statuses say which scene keys reduce the need.
[[noreturn]] inline void throw_cuda(const std::string& device, const char* call, cudaError_t status,
                                    const std::string& context = std::string()) {
  std::string msg = cuda_status_text(status);
  if (!context.empty()) msg = context + ": " + msg;
  if (status == cudaErrorMemoryAllocation)
    msg += "; out of device memory: set ensemble.chunk smaller, or observe.velocity_map.nside "
           "smaller";
  else if (status == cudaErrorLaunchOutOfResources)
    msg += "; the kernel needs more registers or shared memory per block than the device has";
  else if (status == cudaErrorInsufficientDriver)
    msg += "; update the NVIDIA driver to one that supports CUDA " +
           std::to_string(CUDART_VERSION / 1000) + "." + std::to_string(CUDART_VERSION % 1000 / 10);
  else if (status == cudaErrorUnsupportedPtxVersion || status == cudaErrorNoKernelImageForDevice)
    msg += "; the NVIDIA driver is older than this build's NVRTC, or the device is not supported";
  else if (status == cudaErrorLaunchFailure || status == cudaErrorIllegalAddress ||
           status == cudaErrorLaunchTimeout)
    msg += "; the device context is now unusable, restart the program";
  throw DeviceError(device, call, static_cast<long>(status), msg);
}

inline void cuda_check(cudaError_t status, const std::string& device, const char* call,
                       const std::string& context = std::string()) {
  if (status != cudaSuccess) throw_cuda(device, call, status, context);
}

}  // namespace arnoldweb::detail
