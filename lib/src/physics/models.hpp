// arnoldweb: the model table. One row per built-in Hamiltonian H = T(P) + V(X)
// on the 3-torus: its name, its device header (lib/device/models/, selected by
// -DAW_MODEL=<id>), the scene keys it reads, how it fills the kernels'
// parameters, and the facts the planner needs from it (the bottom of V, the
// largest momentum at an energy, V on the host for the accessible torus).
// Adding a model: its device header, a line in lib/device/models/aw_models.h
// and a row here.
#pragma once

#include <string>
#include <vector>

#include "arnoldweb/scene.hpp"
#include "plan/kernel_params.hpp"

namespace arnoldweb::detail {

struct ModelRow {
  std::string name;     // model.kind
  int id = 0;           // AW_MODEL_* (lib/device/models/aw_models.h)
  std::string title;    // human name and source
  std::string formula;  // H, as text
  double v_min = 0;     // the bottom of V: no state below it
  // V at (u_x, u_y, u_z) in turns, on the host (the same code as the kernels)
  double (*potential)(double ux, double uy, double uz, const RealParams& rp) = nullptr;
  // the largest |p_i| on the energy shell E (for the step-size guard)
  double (*p_max)(double energy, const RealParams& rp) = nullptr;
  // its parameters into rp.model[...]
  void (*fill)(const Scene& scene, RealParams& rp) = nullptr;
};

const std::vector<ModelRow>& models();
// The model of a scene (seibert2011 until scenes name others).
const ModelRow& model_of(const Scene& scene);

// Fraction of the torus where V(X) < energy (Monte Carlo with a fixed seed).
double accessible_fraction(const ModelRow& model, const RealParams& rp, double energy);

}  // namespace arnoldweb::detail
