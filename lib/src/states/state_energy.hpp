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

}  // namespace arnoldweb::detail
