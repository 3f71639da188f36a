// arnoldweb tests: the scalar reference run (scalar_core.hpp), double core
// and the choice of precision.
#include "scalar_core.hpp"

#include <stdexcept>

#include "core_double.hpp"
#include "scalar_core_fold.hpp"

namespace awtest {

arnoldweb::Result run_scalar_core_float(const arnoldweb::Plan& plan);  // scalar_core_float.cpp

arnoldweb::Result run_scalar_core(const arnoldweb::Plan& plan) {
  if (plan.kernel.math != arnoldweb::MathMode::Portable)
    throw std::invalid_argument("run_scalar_core: portable math only (native math differs between backends)");
  if (plan.kernel.model != AW_MODEL_SEIBERT2011)
    throw std::invalid_argument("run_scalar_core: the test binary holds the seibert2011 model only");
  if (plan.kernel.precision == arnoldweb::Precision::Float) return run_scalar_core_float(plan);
  auto item = [](auto... a) { core_d::aw_ensemble_item(a...); };
  return scalar_detail::run<double, core_d::aw_rparams, core_d::aw_iparams, core_d::aw_outputs, core_d::aw_lanes,
                            core_d::aw_config>(plan, core_d::rp_of(plan), core_d::ip_of(plan), item);
}

}  // namespace awtest
