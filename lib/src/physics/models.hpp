// arnoldweb: the model table. One row per built-in Hamiltonian H = T(P) + V(X)
// on the 3-torus: its name, its device header (lib/device/models/, selected by
// -DAW_MODEL=<id>), the scene keys it reads, how it fills the kernels'
// parameters, and the facts the planner needs from it (the range of V, the
// kinetic coefficients, a bound on the Hessian of V and the wave numbers of
// its harmonics for the step-size guard, V and the initial states on the host).
// Adding a model: its device header, a line in lib/device/models/aw_models.h
// and a row here (with its header compiled for the host at the top of
// models.cpp).
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "arnoldweb/scene.hpp"
#include "plan/kernel_params.hpp"

namespace arnoldweb::detail {

// The most harmonics of the fourier model (lib/device/models/aw_fourier.h: AW_FOURIER_MAX).
constexpr int kMaxHarmonics = 32;

struct ModelRow {
  std::string name;        // model.kind
  int id = 0;              // AW_MODEL_* (lib/device/models/aw_models.h)
  std::string title;       // human name and source
  std::string formula;     // H, as text
  std::vector<std::string> keys;  // the scene keys of its parameters (besides model.energy)
  std::string parameters;  // its parameters, as text (`arnoldweb models`)
  // its parameters into rp.model[...]; throws SceneError (naming the key) for values wrong together
  std::function<void(const Scene& scene, RealParams& rp)> fill;
  // V at (u_x, u_y, u_z) in turns, on the host (the kernels' code compiled for the host, double)
  std::function<double(double ux, double uy, double uz, const RealParams& rp)> potential;
  // bounds of V over the torus: v[0] <= V <= v[1]
  std::function<std::array<double, 2>(const RealParams& rp)> v_range;
  // kinetic coefficients: T = sum a_i p_i^2 / 2 + b_i p_i; k = {a_x, a_y, a_z, b_x, b_y, b_z}
  std::function<std::array<double, 6>(const RealParams& rp)> kinetic;
  // a bound on the norm of the Hessian of V (radians^-2)
  std::function<double(const RealParams& rp)> hessian_bound;
  // the wave vectors k of its harmonics (those the step-size guard and the resonance circles follow)
  std::function<std::vector<std::array<int, 3>>(const RealParams& rp)> wave_vectors;
  // the model's own closed-form largest frequency at energy E (the paper's guard), or null
  std::function<double(double energy, const RealParams& rp)> closed_frequency;
  // one initial state (the kernels' aw_initial_state, one lane, host): u[3], p[3]; false: none found
  std::function<bool(int kind, std::uint64_t index, const RealParams& rp, const IntParams& ip, double* u,
                     double* p)>
      initial_state;
  // the speed s > 0 with T(s n) = ke along the unit direction n (false: none)
  std::function<bool(double ke, const double* n, const RealParams& rp, double& s)> speed;
  // An expression model's device header (models/aw_expression.h, compiled at run time by OpenCL
  // and CUDA in place of a built-in's); empty for the built-ins. (The fields are std::function so
  // that an expression model's row can hold its compiled potential: expression/expression_row.cpp.)
  std::string device_source;
};

const std::vector<ModelRow>& models();
// The row of a name (nullptr if none).
const ModelRow* find_model(const std::string& name);
// The model of a scene (model.kind). For "expression", a row made for the
// scene's potential (expression/expression_row.cpp; SceneError naming
// model.potential or model.parameters when it cannot be compiled).
const ModelRow& model_of(const Scene& scene);
// The row of an expression model (model.kind = "expression") for this scene.
const ModelRow& expression_row(const Scene& scene);

// The kinetic coefficients of a model that keeps a and b in rp.model[0..5]
// (models/aw_kinetic_ab.h: fourier and expression models).
std::array<double, 6> kinetic_in_slots(const RealParams& rp);

// Whether the kinetic form is |P|^2/2 (a = 1, b = 0).
bool standard_kinetic(const ModelRow& model, const RealParams& rp);
// Whether every a_i > 0: then the energy bounds the momenta.
bool energy_bounds_momenta(const ModelRow& model, const RealParams& rp);

// Fraction of the torus where V(X) < energy (Monte Carlo with a fixed seed).
double accessible_fraction(const ModelRow& model, const RealParams& rp, double energy);
// For any kinetic form: fraction of (X uniform, direction n uniform on the
// sphere) where T(s n) = energy - V(X) has a speed s > 0 (fixed seed).
double reachable_fraction(const ModelRow& model, const RealParams& rp, double energy);

}  // namespace arnoldweb::detail
