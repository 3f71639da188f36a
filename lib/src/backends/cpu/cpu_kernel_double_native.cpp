// arnoldweb: cpu kernel variant "double_native" (see cpu_kernel_body.inc).
#include "aw_cpp_std.h"  // outside the variant's namespace
#include "backends/cpu/cpu_kernel.hpp"

#define AW_NATIVE_MATH 1
#define AW_LANES 8  // trajectories per vector (GCC vector extensions)
namespace arnoldweb::detail {
namespace cpu_double_native {
#include "backends/cpu/cpu_kernel_body.inc"
}  // namespace cpu_double_native

void cpu_chunk_double_native(const CpuChunk& c) { cpu_double_native::run_chunk(c); }

}  // namespace arnoldweb::detail
