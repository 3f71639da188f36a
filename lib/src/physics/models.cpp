// arnoldweb: the model table (models.hpp).
#include "physics/models.hpp"

#include <algorithm>
#include <cmath>

#include "aw_cpp_std.h"
#include "arnoldweb/errors.hpp"
#include "arnoldweb/models.hpp"
#include "physics/expression/expression_model.hpp"

namespace arnoldweb::detail {
// The device core's models compiled for the host in double, one namespace
// each: the shared parts once, then per model its header and the initial
// states (aw_initial.h, read again in every model's namespace).
namespace host_base {
#include "aw_math.h"
#include "aw_rng.h"
#include "aw_state.h"
#include "models/aw_kinetic.h"
}  // namespace host_base
namespace host_seibert2011 {
using namespace host_base;
#include "models/aw_seibert2011.h"
#undef AW_MODEL_H
#undef AW_INITIAL_H
#undef AW_GRID_H
#include "aw_initial.h"
}  // namespace host_seibert2011
namespace host_fgl {
using namespace host_base;
#include "models/aw_fgl.h"
#undef AW_MODEL_H
#undef AW_INITIAL_H
#undef AW_GRID_H
#include "aw_initial.h"
}  // namespace host_fgl
namespace host_fourier {
using namespace host_base;
#include "models/aw_fourier.h"
#undef AW_MODEL_H
#undef AW_INITIAL_H
#undef AW_GRID_H
#include "aw_initial.h"
}  // namespace host_fourier

namespace {

constexpr double kTwoPi = 6.283185307179586476925;

const host_base::aw_rparams* core(const RealParams& rp) {
  return reinterpret_cast<const host_base::aw_rparams*>(&rp);
}
const host_base::aw_iparams* core(const IntParams& ip) {
  return reinterpret_cast<const host_base::aw_iparams*>(&ip);
}

// The host's entry points into one model's namespace.
#define AW_HOST_MODEL(ns)                                                                                    \
  double ns##_potential(double ux, double uy, double uz, const RealParams& rp) {                            \
    return ns::aw_model_potential(ux, uy, uz, core(rp));                                                     \
  }                                                                                                          \
  bool ns##_initial(int kind, std::uint64_t index, const RealParams& rp, const IntParams& ip, double* u,     \
                    double* p) {                                                                             \
    host_base::aw_lstate s{};                                                                                \
    const double ok = ns::aw_initial_state(&s, kind, index, core(rp), core(ip));                             \
    u[0] = s.ux, u[1] = s.uy, u[2] = s.uz, p[0] = s.px, p[1] = s.py, p[2] = s.pz;                            \
    return ok != 0;                                                                                          \
  }                                                                                                          \
  bool ns##_speed(double ke, const double* n, const RealParams& rp, double& speed) {                        \
    double ok = 0;                                                                                           \
    speed = ns::aw_model_speed(ke, n[0], n[1], n[2], core(rp), &ok);                                         \
    return ok != 0;                                                                                          \
  }
AW_HOST_MODEL(host_seibert2011)
AW_HOST_MODEL(host_fgl)
AW_HOST_MODEL(host_fourier)
#undef AW_HOST_MODEL

// ------------------------------------------------------------ seibert2011
ModelRow seibert2011() {
  ModelRow r;
  r.name = "seibert2011";
  r.id = 0;  // AW_MODEL_SEIBERT2011
  r.title = "Seibert, Denisov, Ponomarev & Hanggi, Mapping the Arnold web with a GPU-supercomputer";
  r.formula = "H = |P|^2/2 + cos x cos y (1 + cos 2z)";
  r.parameters = "none of its own: model.energy = E sets the effective perturbation eps_eff = 2/E";
  r.fill = [](const Scene&, RealParams&) {};
  r.potential = host_seibert2011_potential;
  r.v_range = [](const RealParams&) { return std::array<double, 2>{-2.0, 2.0}; };
  r.kinetic = [](const RealParams&) { return std::array<double, 6>{1, 1, 1, 0, 0, 0}; };
  r.hessian_bound = [](const RealParams&) { return 8.0; };  // sum |c_k| |k|^2 of its six harmonics
  r.wave_vectors = [](const RealParams&) {
    return std::vector<std::array<int, 3>>{{1, 1, 0}, {1, -1, 0}, {1, 1, 2}, {1, 1, -2}, {1, -1, 2}, {1, -1, -2}};
  };
  // the paper's guard: h k |p|max with k = 2 (z), |p|max = sqrt(2 (E + 2))
  r.closed_frequency = [](double energy, const RealParams&) { return 2.0 * std::sqrt(2.0 * (energy + 2.0)); };
  r.initial_state = host_seibert2011_initial;
  r.speed = host_seibert2011_speed;
  return r;
}

// ------------------------------------------------------------ fgl
ModelRow fgl() {
  ModelRow r;
  r.name = "fgl";
  r.id = 1;  // AW_MODEL_FGL
  r.title = "Froeschle, Guzzo & Lega, Graphical evolution of the Arnold web, Science 289 (2000) 2108";
  r.formula = "H = I1^2/2 + I2^2/2 + I3 + eps / (cos phi1 + cos phi2 + cos phi3 + 4)";
  r.keys = {"model.epsilon"};
  r.parameters = "model.epsilon = eps (their pictures: 0.001 to 0.04); angles phi = X, actions I = P";
  r.fill = [](const Scene& s, RealParams& rp) { rp.model[0] = s.model_epsilon; };
  r.potential = host_fgl_potential;
  // 1 <= D = sum cos + 4 <= 7
  r.v_range = [](const RealParams& rp) { return std::array<double, 2>{rp.model[0] / 7.0, rp.model[0]}; };
  r.kinetic = [](const RealParams&) { return std::array<double, 6>{1, 1, 0, 0, 0, 1}; };
  // |V_ij| = eps |delta_ij cos phi_i / D^2 + 2 sin phi_i sin phi_j / D^3| with D >= 1:
  // the norm is at most eps (1 + 2 |sin phi|^2) <= 7 eps
  r.hessian_bound = [](const RealParams& rp) { return 7.0 * std::fabs(rp.model[0]); };
  // 1/D has every harmonic; they decay as exp(-0.795 |k|_1) (its singularity: 3 cosh y = 4):
  // the guard follows the unit ones
  r.wave_vectors = [](const RealParams&) {
    return std::vector<std::array<int, 3>>{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, -1, 0}, {1, 0, 1},
                                           {1, 0, -1}, {0, 1, 1}, {0, 1, -1}, {1, 1, 1}, {1, 1, -1}, {1, -1, 1},
                                           {1, -1, -1}};
  };
  r.initial_state = host_fgl_initial;
  r.speed = host_fgl_speed;
  return r;
}

// ------------------------------------------------------------ fourier
ModelRow fourier() {
  ModelRow r;
  r.name = "fourier";
  r.id = 2;  // AW_MODEL_FOURIER
  r.title = "A truncated Fourier potential with harmonics given in the scene";
  r.formula = "H = sum_i a_i p_i^2/2 + sum_i b_i p_i + sum_k c_k cos(k.X + phi_k)";
  r.keys = {"model.harmonics", "model.kinetic_a", "model.kinetic_b"};
  r.parameters = "model.harmonics = [[kx, ky, kz, c, phi], ...] (1 to " + std::to_string(kMaxHarmonics) +
                 ", k integers, phi in radians); model.kinetic_a = [a_x, a_y, a_z] (>= 0), "
                 "model.kinetic_b = [b_x, b_y, b_z]";
  r.fill = [](const Scene& s, RealParams& rp) {
    for (int i = 0; i < 3; ++i) {
      rp.model[i] = s.model_kinetic_a[i];
      rp.model[3 + i] = s.model_kinetic_b[i];
    }
    rp.model[6] = static_cast<double>(s.model_harmonics.size());
    for (std::size_t j = 0; j < s.model_harmonics.size(); ++j) {
      const auto& h = s.model_harmonics[j];
      double* m = &rp.model[7 + 5 * j];
      m[0] = h[0], m[1] = h[1], m[2] = h[2], m[3] = h[3];
      m[4] = h[4] / kTwoPi;  // turns
    }
  };
  r.potential = host_fourier_potential;
  r.v_range = [](const RealParams& rp) {
    double sum = 0;
    for (int j = 0; j < static_cast<int>(rp.model[6]); ++j) sum += std::fabs(rp.model[7 + 5 * j + 3]);
    return std::array<double, 2>{-sum, sum};
  };
  r.kinetic = kinetic_in_slots;
  r.hessian_bound = [](const RealParams& rp) {  // sum |c_k| |k|^2
    double sum = 0;
    for (int j = 0; j < static_cast<int>(rp.model[6]); ++j) {
      const double* m = &rp.model[7 + 5 * j];
      sum += std::fabs(m[3]) * (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    }
    return sum;
  };
  r.wave_vectors = [](const RealParams& rp) {
    std::vector<std::array<int, 3>> k;
    for (int j = 0; j < static_cast<int>(rp.model[6]); ++j) {
      const double* m = &rp.model[7 + 5 * j];
      k.push_back({static_cast<int>(m[0]), static_cast<int>(m[1]), static_cast<int>(m[2])});
    }
    return k;
  };
  r.initial_state = host_fourier_initial;
  r.speed = host_fourier_speed;
  return r;
}

// ------------------------------------------------------------ expression
// The table's row describes the kind; a scene's own row, with its compiled
// potential, is made by expression_row (expression/expression_row.cpp).
ModelRow expression() {
  ModelRow r;
  r.name = "expression";
  r.id = expression::kExpressionModelId;
  r.title = "A potential written in the scene, differentiated and compiled at run time (OpenCL, CUDA)";
  r.formula = "H = sum_i a_i p_i^2/2 + sum_i b_i p_i + V(x, y, z), V = model.potential";
  r.keys = {"model.potential", "model.parameters", "model.kinetic_a", "model.kinetic_b"};
  r.parameters = "model.potential = \"...\" (x, y, z, + - * / ^ sin cos exp sqrt pi), model.parameters = "
                 "{ name = value, ... }, model.kinetic_a, model.kinetic_b as for fourier; not on the cpu "
                 "backend (docs/models.md)";
  return r;
}

std::vector<ModelRow> build() { return {seibert2011(), fgl(), fourier(), expression()}; }

}  // namespace

const std::vector<ModelRow>& models() {
  static const std::vector<ModelRow> rows = build();
  return rows;
}

const ModelRow* find_model(const std::string& name) {
  for (const ModelRow& m : models())
    if (m.name == name) return &m;
  return nullptr;
}

const ModelRow& model_of(const Scene& scene) {
  if (scene.model_kind == "expression") return expression_row(scene);
  const ModelRow* m = find_model(scene.model_kind);
  if (!m) throw SceneError(scene.file, 0, 0, "model.kind", "unknown model \"" + scene.model_kind + "\"");
  return *m;
}

std::array<double, 6> kinetic_in_slots(const RealParams& rp) {
  return {rp.model[0], rp.model[1], rp.model[2], rp.model[3], rp.model[4], rp.model[5]};
}

bool standard_kinetic(const ModelRow& model, const RealParams& rp) {
  const auto k = model.kinetic(rp);
  return k == std::array<double, 6>{1, 1, 1, 0, 0, 0};
}

bool energy_bounds_momenta(const ModelRow& model, const RealParams& rp) {
  const auto k = model.kinetic(rp);
  return k[0] > 0 && k[1] > 0 && k[2] > 0;
}

double accessible_fraction(const ModelRow& model, const RealParams& rp, double energy) {
  constexpr int kSamples = 1 << 16;
  int inside = 0;
  for (int i = 0; i < kSamples; ++i) {
    double a, b, c, d;
    host_base::aw_uniform2(0x5eedULL, static_cast<std::uint64_t>(i), 0u, 0u, &a, &b);
    host_base::aw_uniform2(0x5eedULL, static_cast<std::uint64_t>(i), 0u, 1u, &c, &d);
    if (model.potential(a - 0.5, b - 0.5, c - 0.5, rp) < energy) ++inside;
  }
  return static_cast<double>(inside) / kSamples;
}

double reachable_fraction(const ModelRow& model, const RealParams& rp, double energy) {
  constexpr int kSamples = 1 << 16;
  int reached = 0;
  for (int i = 0; i < kSamples; ++i) {
    double a, b, c, d, e, f;
    host_base::aw_uniform2(0x5eedULL, static_cast<std::uint64_t>(i), 0u, 0u, &a, &b);
    host_base::aw_uniform2(0x5eedULL, static_cast<std::uint64_t>(i), 0u, 1u, &c, &d);
    host_base::aw_uniform2(0x5eedULL, static_cast<std::uint64_t>(i), 0u, 2u, &e, &f);
    const double ct = 2.0 * d - 1.0, st = std::sqrt((1.0 - ct) * (1.0 + ct));
    const double n[3] = {st * std::cos(kTwoPi * e), st * std::sin(kTwoPi * e), ct};
    double s = 0;
    if (model.speed(energy - model.potential(a - 0.5, b - 0.5, c - 0.5, rp), n, rp, s)) ++reached;
  }
  return static_cast<double>(reached) / kSamples;
}

}  // namespace arnoldweb::detail

namespace arnoldweb {

std::vector<ModelInfo> model_list() {
  std::vector<ModelInfo> out;
  for (const detail::ModelRow& m : detail::models()) out.push_back({m.name, m.title, m.formula, m.parameters, m.keys});
  return out;
}

}  // namespace arnoldweb
