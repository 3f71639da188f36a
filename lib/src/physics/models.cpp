// arnoldweb: the model table (models.hpp).
#include "physics/models.hpp"

#include <cmath>

#include "aw_cpp_std.h"

namespace arnoldweb::detail {
namespace host_core {  // the device core's models, compiled for the host in double
#include "aw_rng.h"
#include "models/aw_models.h"
}  // namespace host_core

namespace {

double seibert2011_potential(double ux, double uy, double uz, const RealParams& rp) {
  return host_core::aw_model_potential(ux, uy, uz, reinterpret_cast<const host_core::aw_rparams*>(&rp));
}

std::vector<ModelRow> build() {
  std::vector<ModelRow> m;
  {
    ModelRow r;
    r.name = "seibert2011";
    r.id = 0;  // AW_MODEL_SEIBERT2011
    r.title = "Seibert, Denisov, Ponomarev & Hanggi, Mapping the Arnold web with a GPU-supercomputer";
    r.formula = "H = |P|^2/2 + cos x cos y (1 + cos 2z), eps_eff = 2/E";
    r.v_min = -2.0;
    r.potential = seibert2011_potential;
    r.p_max = [](double energy, const RealParams&) { return std::sqrt(2.0 * (energy + 2.0)); };
    r.fill = [](const Scene&, RealParams&) {};
    m.push_back(r);
  }
  return m;
}

}  // namespace

const std::vector<ModelRow>& models() {
  static const std::vector<ModelRow> rows = build();
  return rows;
}

const ModelRow& model_of(const Scene&) { return models().front(); }

double accessible_fraction(const ModelRow& model, const RealParams& rp, double energy) {
  constexpr int kSamples = 1 << 16;
  int inside = 0;
  for (int i = 0; i < kSamples; ++i) {
    double a, b, c, d;
    host_core::aw_uniform2(0x5eedULL, static_cast<std::uint64_t>(i), 0u, 0u, &a, &b);
    host_core::aw_uniform2(0x5eedULL, static_cast<std::uint64_t>(i), 0u, 1u, &c, &d);
    if (model.potential(a - 0.5, b - 0.5, c - 0.5, rp) < energy) ++inside;
  }
  return static_cast<double>(inside) / kSamples;
}

}  // namespace arnoldweb::detail
