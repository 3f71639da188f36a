// arnoldweb: THE MODEL TABLE: the descriptors (model_descriptor.hpp) of the
// built-in models, in the order of their ids (the paper's first), then the
// kind "expression", whose row a scene makes from its potential.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "physics/model_descriptor.hpp"

namespace arnoldweb::detail {

const std::vector<ModelDescriptor>& models();
// The descriptor of a name (nullptr if none).
const ModelDescriptor* find_model(const std::string& name);

// What an expression model is made of (model.kind = "expression"): its
// potential, its named parameters and the values of its kinetic keys.
struct ExpressionInput {
  std::string potential;
  std::vector<std::pair<std::string, double>> parameters;
};
// The row of an expression model (kept for the process, one per potential and
// parameters); ModelError naming model.potential or model.parameters when it
// cannot be compiled.
const ModelDescriptor& expression_row(const ExpressionInput& input);

// The keys model.kinetic_a and model.kinetic_b of the models that keep a and b
// in rp.model[0..5] (fourier and expression models).
ModelParameter kinetic_a_parameter();
ModelParameter kinetic_b_parameter();

// The kinetic coefficients of a model that keeps a and b in rp.model[0..5]
// (kinetic/aw_kinetic_ab.h: fourier and expression models).
std::array<double, 6> kinetic_in_slots(const RealParams& rp);

// Whether the kinetic form is |P|^2/2 (a = 1, b = 0).
bool standard_kinetic(const ModelDescriptor& model, const RealParams& rp);
// Whether every a_i > 0: then the energy bounds the momenta.
bool energy_bounds_momenta(const ModelDescriptor& model, const RealParams& rp);

// Fraction of the torus where V(X) < energy (Monte Carlo with a fixed seed).
double accessible_fraction(const ModelDescriptor& model, const RealParams& rp, double energy);
// For any kinetic form: fraction of (X uniform, direction n uniform on the
// sphere) where T(s n) = energy - V(X) has a speed s > 0 (fixed seed).
double reachable_fraction(const ModelDescriptor& model, const RealParams& rp, double energy);

}  // namespace arnoldweb::detail
