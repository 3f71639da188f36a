// arnoldweb: a model's device code compiled for the host, in double precision
// (generated per model from host_model.cpp.in): the same operations as the
// kernels', for the planner (accessible phase space, the step-size guard's
// velocity estimates) and for checking states read from files.
#pragma once

#include <cstdint>

#include "params/kernel_params.hpp"

namespace arnoldweb::detail {

struct HostModel {
  // V at (u_x, u_y, u_z) in turns
  double (*potential)(double ux, double uy, double uz, const RealParams& rp) = nullptr;
  // one initial state (the kernels' aw_initial_state, one lane): u[3] in turns, p[3]; false: none found
  bool (*initial_state)(int kind, std::uint64_t index, const RealParams& rp, const IntParams& ip, double* u,
                        double* p) = nullptr;
  // the speed s > 0 with T(s n) = ke along the unit direction n (false: none)
  bool (*speed)(double ke, const double* n, const RealParams& rp, double& s) = nullptr;
  // T(p)
  double (*kinetic)(const double* p, const RealParams& rp) = nullptr;
  // F = -grad V at u (turns), per radian; with the Hessian of V (xx, yy, zz, xy, xz, yz)
  void (*force)(const double* u, const RealParams& rp, double* f) = nullptr;
  void (*force_hessian)(const double* u, const RealParams& rp, double* f, double* hessian) = nullptr;
  // the diagonal of d^2T/dP^2
  void (*kinetic_diag)(const RealParams& rp, double* a) = nullptr;
};

}  // namespace arnoldweb::detail
