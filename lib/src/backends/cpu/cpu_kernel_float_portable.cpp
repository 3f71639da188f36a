// arnoldweb: cpu kernel variant "float_portable" (see cpu_kernel_body.inc).
#include <Random123/philox.h>  // variant-independent types stay outside the namespace

#include <cmath>
#include <cstdint>

#include "backends/cpu/cpu_kernel.hpp"

#define AW_FLOAT 1
namespace arnoldweb::detail {
namespace cpu_float_portable {
#include "backends/cpu/cpu_kernel_body.inc"
}  // namespace cpu_float_portable

void cpu_chunk_float_portable(const CpuChunk& c) { cpu_float_portable::run_chunk(c); }

}  // namespace arnoldweb::detail
