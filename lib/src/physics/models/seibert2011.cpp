// arnoldweb model "seibert2011": the paper's Hamiltonian (lib/device/models/aw_seibert2011.h).
#include <cmath>

#include "physics/model_table.hpp"

namespace arnoldweb::detail {

AW_MODEL_ID(0);  // for good (model_descriptor.hpp)

ModelDescriptor describe_seibert2011() {
  ModelDescriptor m;
  m.title = "Seibert, Denisov, Ponomarev & Hanggi, Mapping the Arnold web with a GPU-supercomputer";
  m.formula = "H = |P|^2/2 + cos x cos y (1 + cos 2z)";
  m.notes = "none of its own: model.energy = E sets the effective perturbation eps_eff = 2/E";
  m.kinetic = [](const RealParams&) { return std::array<double, 6>{1, 1, 1, 0, 0, 0}; };
  m.v_range = [](const RealParams&) { return std::array<double, 2>{-2.0, 2.0}; };
  m.hessian_bound = [](const RealParams&) { return 8.0; };  // sum |c_k| |k|^2 of its six harmonics
  m.wave_vectors = [](const RealParams&) {
    return std::vector<std::array<int, 3>>{{1, 1, 0}, {1, -1, 0}, {1, 1, 2}, {1, 1, -2}, {1, -1, 2}, {1, -1, -2}};
  };
  // the paper's guard: h k |p|max with k = 2 (z), |p|max = sqrt(2 (E + 2))
  m.closed_frequency = [](double energy, const RealParams&) { return 2.0 * std::sqrt(2.0 * (energy + 2.0)); };
  m.effective_perturbation = [](double energy) { return 2.0 / energy; };
  m.overlay_all_resonances = true;  // its six harmonics make every resonance of the web
  return m;
}

}  // namespace arnoldweb::detail
