// arnoldweb tests: an independent reference run of a plan. The device core
// (lib/device) compiled here, in the test binary, as scalar C++ (AW_LANES = 1:
// no vectors, no -march), one call per trajectory (spread over OpenMP threads,
// which share nothing but the atomic counts), in one chunk, its counts folded
// here and not by the library's reduction. The cpu backend
// runs the same source vectorised (8 lanes in double, 16 in float, GCC vector
// extensions, -march=ARNOLDWEB_CPU_ARCH) in blocks over OpenMP threads; the
// OpenCL and CUDA backends compile it for their devices. The parity contract
// (portable math: the same bits everywhere) makes every device's result equal
// to this one, bit for bit.
#pragma once

#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"

namespace awtest {

// The plan run by the scalar core: counts, flags, energy max and histogram,
// maps, frames, zoom and state records as a device's Result holds them
// (device.id "scalar core"). energy.mean is the sum in trajectory order (a
// device sums in its own order: equal only to rounding). Portable math and
// the kernel's model only (throws std::invalid_argument otherwise).
arnoldweb::Result run_scalar_core(const arnoldweb::Plan& plan);

}  // namespace awtest
