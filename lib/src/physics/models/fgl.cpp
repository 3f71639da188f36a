// arnoldweb model "fgl": Froeschle, Guzzo & Lega (lib/device/models/aw_fgl.h).
#include <cmath>

#include "physics/model_table.hpp"

namespace arnoldweb::detail {

AW_MODEL_ID(1);  // for good (model_descriptor.hpp)

ModelDescriptor describe_fgl() {
  ModelDescriptor m;
  m.title = "Froeschle, Guzzo & Lega, Graphical evolution of the Arnold web, Science 289 (2000) 2108";
  m.formula = "H = I1^2/2 + I2^2/2 + I3 + eps / (cos phi1 + cos phi2 + cos phi3 + 4)";
  m.notes = "model.epsilon = eps (their pictures: 0.001 to 0.04); angles phi = X, actions I = P";
  ModelParameter eps;
  eps.key = "model.epsilon";
  eps.type = "float";
  eps.allowed = ">= 0 and <= 1";
  eps.must = "a float from 0 to 1";
  eps.help = "the perturbation eps of H = I1^2/2 + I2^2/2 + I3 + eps / (cos phi1 + cos phi2 + cos phi3 + 4) "
             "(their pictures: 0.001 to 0.04).";
  eps.lo = 0;
  eps.hi = 1;
  eps.default_value = {0.01};
  eps.slot = 0;
  m.parameters = {eps};
  m.kinetic = [](const RealParams&) { return std::array<double, 6>{1, 1, 0, 0, 0, 1}; };
  // 1 <= D = sum cos + 4 <= 7
  m.v_range = [](const RealParams& rp) { return std::array<double, 2>{rp.model[0] / 7.0, rp.model[0]}; };
  // |V_ij| = eps |delta_ij cos phi_i / D^2 + 2 sin phi_i sin phi_j / D^3| with D >= 1:
  // the norm is at most eps (1 + 2 |sin phi|^2) <= 7 eps
  m.hessian_bound = [](const RealParams& rp) { return 7.0 * std::fabs(rp.model[0]); };
  // 1/D has every harmonic; they decay as exp(-0.795 |k|_1) (its singularity: 3 cosh y = 4):
  // the guard follows the unit ones
  m.wave_vectors = [](const RealParams&) {
    return std::vector<std::array<int, 3>>{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, -1, 0}, {1, 0, 1},
                                           {1, 0, -1}, {0, 1, 1}, {0, 1, -1}, {1, 1, 1}, {1, 1, -1}, {1, -1, 1},
                                           {1, -1, -1}};
  };
  return m;
}

}  // namespace arnoldweb::detail
