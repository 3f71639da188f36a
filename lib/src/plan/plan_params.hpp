// arnoldweb: a plan's parameter blocks (params/kernel_params.hpp), as the
// backends read them and as tests change them.
#pragma once

#include "arnoldweb/plan.hpp"
#include "params/kernel_params.hpp"

namespace arnoldweb::detail {

// The plan's blocks.
inline const KernelParams& params(const Plan& plan) { return *plan.params; }
// A copy of the plan's blocks that can be changed (tests' hooks).
KernelParams& edit_params(Plan& plan);

}  // namespace arnoldweb::detail
