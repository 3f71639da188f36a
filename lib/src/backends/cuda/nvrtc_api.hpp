// arnoldweb: NVRTC found at run time. The library does not link libnvrtc: it
// opens it with dlopen when a CUDA kernel is first compiled (or a CUDA device
// is listed), so a library or wheel built with the CUDA backend loads and
// runs on machines without the CUDA toolkit, and its CUDA devices appear
// where a driver and NVRTC are present. The types and signatures are nvrtc.h's.
#pragma once

#include <nvrtc.h>

#include <string>

#include "backends/cuda/nvrtc_loader.hpp"

namespace arnoldweb::detail {

// The NVRTC functions the CUDA backend calls.
struct NvrtcApi {
  decltype(&nvrtcGetErrorString) GetErrorString = nullptr;
  decltype(&nvrtcVersion) Version = nullptr;
  decltype(&nvrtcGetNumSupportedArchs) GetNumSupportedArchs = nullptr;
  decltype(&nvrtcGetSupportedArchs) GetSupportedArchs = nullptr;
  decltype(&nvrtcCreateProgram) CreateProgram = nullptr;
  decltype(&nvrtcDestroyProgram) DestroyProgram = nullptr;
  decltype(&nvrtcCompileProgram) CompileProgram = nullptr;
  decltype(&nvrtcGetProgramLogSize) GetProgramLogSize = nullptr;
  decltype(&nvrtcGetProgramLog) GetProgramLog = nullptr;
  decltype(&nvrtcGetCUBINSize) GetCUBINSize = nullptr;
  decltype(&nvrtcGetCUBIN) GetCUBIN = nullptr;
  decltype(&nvrtcGetPTXSize) GetPTXSize = nullptr;
  decltype(&nvrtcGetPTX) GetPTX = nullptr;
  std::string path;  // the file that was loaded
};

// NVRTC, loaded on first use (once per process) from nvrtc_candidates(), or
// null when none was found; then `problem` (when given) says what was tried.
const NvrtcApi* nvrtc_api(std::string* problem = nullptr);

// The same, or a DeviceError naming `device` and what was tried.
const NvrtcApi& nvrtc(const std::string& device);

}  // namespace arnoldweb::detail
