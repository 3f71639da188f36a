// arnoldweb: where NVRTC is looked for at run time (nvrtc_api.hpp opens it).
// Plain C++ header (no CUDA headers), so the tests can call it.
#pragma once

#include <string>
#include <vector>

namespace arnoldweb::detail {

// The files tried, in order: $ARNOLDWEB_NVRTC alone when set; else
// libnvrtc.so.13 and libnvrtc.so.12 through the dynamic loader
// (LD_LIBRARY_PATH, ld.so.cache), then in the pip packages nvidia-cuda-nvrtc
// beside this library (site-packages/nvidia/cu13/lib, nvidia/cuda_nvrtc/lib),
// $CUDA_HOME/lib64, $CUDA_PATH/lib64 and /usr/local/cuda/lib64.
std::vector<std::string> nvrtc_candidates();

// Opens the first of `candidates` that is an NVRTC with every function the
// CUDA backend calls, and closes it again: "" when one is, else why not
// (naming what was tried).
std::string nvrtc_check_candidates(const std::vector<std::string>& candidates);

// The NVRTC this process uses (opened once, on first use): its path, or ""
// with `problem` set when none was found.
std::string nvrtc_library(std::string* problem = nullptr);

}  // namespace arnoldweb::detail
