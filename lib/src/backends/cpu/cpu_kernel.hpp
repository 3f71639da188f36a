// arnoldweb: the cpu backend's kernels. The device core is compiled ahead of
// time as C++ in several variants (model x double/float x portable/native
// math, cpu_kernels.cmake), each in its own namespace; cpu_device.cpp picks
// one per plan.
#pragma once

#include <cstdint>

#include "aw_params.h"

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
  std::uint64_t first = 0, end = 0;       // trajectories [first, end)
  std::int64_t seg_first = 0, seg_end = 0;  // over the segments [seg_first, seg_end) of their schedule
  bool frequencies = false;  // the frequency analysis of the trajectories instead (aw_freq_analyse)
  // the kernel's buffers in host memory, indexed by AW_BUF_* (aw_params.h:
  // AW_BUFFERS); reals in the variant's precision; null where the plan needs none
  void* buffers[AW_BUF_COUNT] = {};
};

using CpuKernel = void (*)(const CpuChunk&);

// The variant for (model, precision, math), or null if this build has none.
CpuKernel cpu_kernel(int model, bool single_precision, bool native_math);

}  // namespace arnoldweb::detail
