// arnoldweb tests: the scalar reference run (scalar_core.hpp), float core.
#include <cstring>
#include <stdexcept>
#include <vector>

#include "core_float.hpp"
#include "plan/plan_params.hpp"
#include "scalar_core.hpp"
#include "scalar_core_fold.hpp"

namespace awtest {

arnoldweb::Result run_scalar_core_float(const arnoldweb::Plan& plan) {
  // float kernels read the real block converted element by element (kernel_params.hpp)
  const auto& kp = arnoldweb::detail::params(plan);
  const std::vector<unsigned char> bytes = kp.real_bytes(arnoldweb::Precision::Float);
  if (bytes.size() != sizeof(core_f::aw_rparams) || sizeof(kp.ints) != sizeof(core_f::aw_iparams))
    throw std::logic_error("run_scalar_core: the float parameter blocks do not have the core's layout");
  core_f::aw_rparams rp;
  core_f::aw_iparams ip;
  std::memcpy(&rp, bytes.data(), bytes.size());
  std::memcpy(&ip, &kp.ints, sizeof ip);
  auto item = [](auto... a) { core_f::aw_ensemble_item(a...); };
  return scalar_detail::run<float, core_f::aw_rparams, core_f::aw_iparams, core_f::aw_outputs, core_f::aw_lanes,
                            core_f::aw_config>(plan, &rp, &ip, item);
}

}  // namespace awtest
