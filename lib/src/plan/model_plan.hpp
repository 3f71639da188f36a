// arnoldweb: the planner's part for the model: which descriptor a scene runs
// (model.kind; an expression model's row compiled from its potential), its
// parameters into the kernels' real block, the keys of other models refused,
// the accessible phase space at the scene's energy and the model's largest
// frequency for the step-size guard. Physics knows no scene: this is where a
// scene's values are handed to the model (Scene::model_values).
#pragma once

#include <string>

#include "arnoldweb/plan.hpp"
#include "params/kernel_params.hpp"
#include "physics/model_table.hpp"
#include "plan/lookups.hpp"

namespace arnoldweb::detail {

// The model of a scene (SceneError naming model.kind, or the expression's key);
// make_plan takes it from its lookups (model_found).
const ModelDescriptor& model_of(const Scene& scene);

// The model's parameters into rp.model; refuses keys of another model written
// with another value than their default, and a kinetic form that does not suit
// the initial kind.
void plan_model_values(const Scene& scene, const ModelDescriptor& model, RealParams& rp);

// The energy must leave enough phase space for the initial states (rejection
// sampling, the fraction looked up): sets plan.accessible_fraction, or SceneError naming model.energy.
void plan_accessible(const Scene& scene, const ModelDescriptor& model, const RealParams& rp, const PlanLookups& found,
                     Plan& p);

// The model's largest frequency omega at the scene's energy (radians per time
// unit) and how it was found (`basis`); where the momenta do not follow from the
// energy (bounds_momenta: energy_bounds_momenta), from the given states (null:
// those the initial kind draws).
double model_frequency(const Scene& scene, const ModelDescriptor& model, bool bounds_momenta, const KernelParams& kp,
                       int initial, const StateSet* states, std::string& basis);

// The step-size guard of the plan's step (plan.guard, warnings), or SceneError
// naming integrator.step when it is unsafe.
void plan_guard(const Scene& scene, const ModelDescriptor& model, bool bounds_momenta, const KernelParams& kp, Plan& p);
// The same at the plan's step for a frequency found before (with_step).
void guard_step(const Scene& scene, const ModelDescriptor& model, double omega, const std::string& basis, Plan& p);

}  // namespace arnoldweb::detail
