// arnoldweb: the cpu backend's kernels. The device core is compiled four times
// as C++ (double/float x portable/native math), each copy in its own
// namespace; cpu_backend.cpp picks one per plan.
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
  std::uint64_t first = 0, end = 0;  // trajectories [first, end)
  const void* rp = nullptr;          // AW_P_COUNT reals of the variant's precision
  const std::int64_t* ip = nullptr;  // AW_I_COUNT
  std::uint32_t* map = nullptr;      // 12 nside^2 counts
  std::uint32_t* counters = nullptr; // AW_C_COUNT
  void* initial_r = nullptr;         // reals of the variant's precision
  void* final_r = nullptr;
  std::int64_t* final_i = nullptr;
  double* group_stats = nullptr;     // 2 per block
};

using CpuKernel = void (*)(const CpuChunk&);

void cpu_chunk_double_portable(const CpuChunk& c);
void cpu_chunk_double_native(const CpuChunk& c);
void cpu_chunk_float_portable(const CpuChunk& c);
void cpu_chunk_float_native(const CpuChunk& c);

}  // namespace arnoldweb::detail
