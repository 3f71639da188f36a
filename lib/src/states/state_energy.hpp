// arnoldweb: the energies of given states under a model (the planner's check
// of ensemble.initial = "file" and of Python's initial=): each state's
// H = T(P) + V(X) into states.energy and their range; a StateError for the
// first state (status 0) whose energy is not finite or far from `energy`
// (kStateEnergyTolerance, states.hpp). Physics and states only: the planner
// hands in the scene's model and its parameters.
#pragma once

#include "arnoldweb/states.hpp"
#include "physics/model_descriptor.hpp"

namespace arnoldweb::detail {

void check_state_energies(StateSet& states, const ModelDescriptor& model, const RealParams& rp, double energy);

// H = T(P) + V(X) of one state: u in turns, the kinetic coefficients k of model.kinetic(rp).
inline double state_energy(const ModelDescriptor& model, const RealParams& rp, const std::array<double, 6>& k,
                           const double* u, const double* p) {
  double t = 0;  // T = sum a_i p_i^2 / 2 + b_i p_i
  for (int c = 0; c < 3; ++c) t += k[c] * p[c] * p[c] / 2 + k[3 + c] * p[c];
  return t + model.potential(u[0], u[1], u[2], rp);
}

}  // namespace arnoldweb::detail
