// arnoldweb: cpu kernel variant "float_portable" (see cpu_kernel_body.inc).
#include "aw_cpp_std.h"  // outside the variant's namespace
#include "backends/cpu/cpu_kernel.hpp"

#define AW_FLOAT 1
#define AW_LANES 16  // trajectories per vector (GCC vector extensions)
namespace arnoldweb::detail {
namespace cpu_float_portable {
#include "backends/cpu/cpu_kernel_body.inc"
}  // namespace cpu_float_portable

void cpu_chunk_float_portable(const CpuChunk& c) { cpu_float_portable::run_chunk(c); }

}  // namespace arnoldweb::detail
