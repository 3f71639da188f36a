// arnoldweb: cpu kernel variant "double_portable" (see cpu_kernel_body.inc).
#include <Random123/philox.h>  // variant-independent types stay outside the namespace

#include <cmath>
#include <cstdint>

#include "backends/cpu/cpu_kernel.hpp"

namespace arnoldweb::detail {
namespace cpu_double_portable {
#include "backends/cpu/cpu_kernel_body.inc"
}  // namespace cpu_double_portable

void cpu_chunk_double_portable(const CpuChunk& c) { cpu_double_portable::run_chunk(c); }

}  // namespace arnoldweb::detail
