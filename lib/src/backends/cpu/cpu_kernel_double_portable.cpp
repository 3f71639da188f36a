// arnoldweb: cpu kernel variant "double_portable" (see cpu_kernel_body.inc).
#include "aw_cpp_std.h"  // outside the variant's namespace
#include "backends/cpu/cpu_kernel.hpp"

#define AW_LANES 8  // trajectories per vector (GCC vector extensions)
namespace arnoldweb::detail {
namespace cpu_double_portable {
#include "backends/cpu/cpu_kernel_body.inc"
}  // namespace cpu_double_portable

void cpu_chunk_double_portable(const CpuChunk& c) { cpu_double_portable::run_chunk(c); }

}  // namespace arnoldweb::detail
