// The device core compiled as C++ in double precision, inside namespace
// core_d (one per test translation unit; see core_float.hpp for float), with
// the plan's parameter blocks as the core sees them.
#pragma once
#include "aw_cpp_std.h"

namespace core_d {
#include "aw_ensemble.h"
}  // namespace core_d

#include "plan/plan_params.hpp"

namespace core_d {

// The plan's blocks, as the kernels read them (same layout: aw_param_blocks.h).
inline const aw_rparams* rp_of(const arnoldweb::Plan& p) {
  return reinterpret_cast<const aw_rparams*>(&arnoldweb::detail::params(p).reals);
}
inline const aw_iparams* ip_of(const arnoldweb::Plan& p) {
  return reinterpret_cast<const aw_iparams*>(&arnoldweb::detail::params(p).ints);
}

// The paper's model (seibert2011) has no parameters of its own: its potential,
// force and energy need no plan.
inline const aw_rparams* paper_model() {
  static const aw_rparams none{};
  return &none;
}
inline double aw_potential(double ux, double uy, double uz) { return aw_model_potential(ux, uy, uz, paper_model()); }
inline void aw_force(aw_lstate* s) { aw_force(s, paper_model()); }
inline double aw_energy(const aw_lstate* s) { return aw_energy(s, paper_model()); }

}  // namespace core_d
