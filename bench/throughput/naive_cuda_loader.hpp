// arnoldweb bench: finds and loads libarnoldweb_naive_cuda.so (the NVIDIA
// baseline, built by nvcc where CMake finds CUDA) with dlopen.
#pragma once

#include <string>

#include "naive.hpp"

namespace arnoldweb::bench {

struct NaiveCuda {
  AwNaiveCudaRun run = nullptr;
  AwNaiveCudaMemInfo mem_info = nullptr;
  std::string path;     // where it was loaded from
  std::string problem;  // why it is not available
  explicit operator bool() const { return run != nullptr; }
};

// Looks in $ARNOLDWEB_NAIVE_CUDA, next to the running executable, then in the
// build directory; loads once per process.
const NaiveCuda& naive_cuda();

}  // namespace arnoldweb::bench
