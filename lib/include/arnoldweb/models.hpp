// arnoldweb: the built-in models (Hamiltonians H = T(P) + V(X) on the 3-torus),
// as `arnoldweb models` lists them (docs/models.md). A scene picks one with
// model.kind.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace arnoldweb {

struct Scene;

struct ModelInfo {
  std::string name;        // model.kind
  std::string title;       // human name and source
  std::string formula;     // H, as text
  std::string parameters;  // its parameters and their keys, as text
  std::vector<std::string> keys;  // its scene keys besides model.energy
};

std::vector<ModelInfo> model_list();

// A scene's model (model.kind, its parameters, model.energy) evaluated on the
// host in double precision by the kernels' own code (the model's device header
// compiled for the host, or an expression model's compiled potential), for
// building and checking states (Python's aw.potential, aw.energy,
// aw.shell_momenta). Positions are in turns (x / 2 pi), any value: each is
// wrapped to [-1/2, 1/2] as initial states are (states.hpp).
class SceneModel {
 public:
  // SceneError as the planner reports it (model.kind, a key of another model, ...).
  explicit SceneModel(const Scene& scene);
  ~SceneModel();
  SceneModel(SceneModel&&) noexcept;
  double energy() const;  // model.energy
  double potential(const double* u) const;  // V(X)
  // H = T(P) + V(X): the energy check_states gives a state
  double hamiltonian(const double* u, const double* p) const;
  // The momentum on the shell H = model.energy along the unit direction n,
  // made as the kernels make initial states (P = s n with T(s n) = E - V(X));
  // false (and p unchanged) where there is none.
  bool shell_momentum(const double* u, const double* n, double* p) const;

 private:
  struct Model;
  std::unique_ptr<Model> m_;
};

}  // namespace arnoldweb
