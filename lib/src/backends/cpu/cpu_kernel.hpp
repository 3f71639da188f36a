// arnoldweb: the cpu backend's kernels. The device core is compiled ahead of
// time as C++ in several variants (model x double/float x portable/native
// math, cpu_kernels.cmake), each in its own namespace; cpu_device.cpp picks
// one per plan.
#pragma once

#include <cstdint>

namespace arnoldweb::detail {

// Trajectories are processed in blocks of this many; every block reports one
// (max, sum) pair of energy errors, so the statistics do not depend on threads.
constexpr std::uint64_t kCpuBlock = 256;

struct CpuChunk {
  std::uint32_t features = 0;
  int stages = 0;
  int kick_first = 1;
  int gradient = 0;  // force-gradient kicks (aw_config::gradient)
  int initial = 0;
  std::uint64_t first = 0, end = 0;  // trajectories [first, end)
  const void* rp = nullptr;          // aw_rparams of the variant's precision
  const void* ip = nullptr;          // aw_iparams
  std::uint32_t* map = nullptr;      // the histograms' 32-bit counts
  std::uint32_t* counters = nullptr; // AW_C_COUNT
  void* initial_r = nullptr;         // reals of the variant's precision
  void* final_r = nullptr;
  std::int64_t* final_i = nullptr;
  void* indicators = nullptr;        // AW_IND_REALS reals per trajectory (chaos indicators)
  void* group_stats = nullptr;       // 2 reals of the variant's precision per block
};

using CpuKernel = void (*)(const CpuChunk&);

// The variant for (model, precision, math), or null if this build has none.
CpuKernel cpu_kernel(int model, bool single_precision, bool native_math);

}  // namespace arnoldweb::detail
