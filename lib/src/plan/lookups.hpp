// arnoldweb: what the planner asks the layers below it, asked in one place
// before it decides. Physics (the scene's model and its parameters, the method,
// the phase space the energy leaves for the initial states, whether the energy
// bounds the momenta), the output table (the bits its switches ask for, the
// sample intervals of its table keys) and the sphere (the frames of the
// directions a scene writes) answer with values; make_plan then checks and
// decides on those values alone, so that it enters each lower layer once and
// never comes back to a lookup half-way (docs/design.md, "Issue 39, measured").
// Nothing here throws for the scene: what cannot be found is kept, with its
// key, for the planner to refuse in its own order.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "arnoldweb/methods.hpp"
#include "arnoldweb/scene.hpp"
#include "arnoldweb/sphere.hpp"
#include "params/kernel_params.hpp"
#include "physics/model_table.hpp"

namespace arnoldweb::detail {

// A scene's model: its row, or the key and message of why there is none.
struct ModelLookup {
  const ModelDescriptor* model = nullptr;
  std::string key, error;
};

struct PlanLookups {
  ModelLookup model;
  RealParams reals;            // the model's parameters (rp.model) as the scene writes them
  bool bounds_momenta = true;  // energy_bounds_momenta: every a_i > 0
  const Method* method = nullptr;
  std::string method_error;  // when the method is unknown
  // The fraction of the phase space the initial states are drawn from
  // (ensemble.initial other than "grid" and "file"): of the torus where
  // V(X) < E (minus the Gaussian mean's kinetic energy) for the kinetic form
  // |P|^2/2 scaled (`accessible`), else of positions and directions from which
  // T(s n) = E - V(X) is reached.
  bool accessible = true;
  double mean_kinetic = 0;  // ensemble.initial = "gaussian": the kinetic energy of the mean momentum
  double fraction = 1;
  double enough_energy = 0;  // where the accessible fraction is too small: the smallest E that leaves enough
  std::uint32_t switch_bits = 0;                              // switch_features
  std::vector<std::pair<std::string, double>> intervals;      // sample_intervals
  TangentFrame cap, zoom, confine;                            // of the directions written
};

// Fewer accessible states than this fraction leave the rejection sampling no room.
constexpr double kMinAccessible = 0.001;

ModelLookup look_up_model(const Scene& scene);
PlanLookups look_up(const Scene& scene);

// The model found, or SceneError naming its key.
const ModelDescriptor& model_found(const Scene& scene, const ModelLookup& found);

}  // namespace arnoldweb::detail
