// arnoldweb expression models: the model-table row of a scene's potential
// (model_table.hpp, expression_row). The row holds the compiled potential: V
// and its force on the host come from the host evaluator (the bits of a double
// kernel), the kinetic half and the initial states from the device headers
// compiled for the host, as for the built-ins (host_model.cpp.in).
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>

#include "arnoldweb/errors.hpp"
#include "aw_cpp_std.h"
#include "physics/expression/expression_model.hpp"
#include "physics/expression/parser.hpp"
#include "physics/model_table.hpp"

namespace arnoldweb::detail {
namespace host_expression {
#include "aw_math.h"
#include "aw_rng.h"
#include "aw_state.h"
#include "kinetic/aw_expression_kinetic.h"

// The potential and force of the model being evaluated on this thread (set
// around each call by the row's functions below; the device code of the
// initial states calls them by these names).
thread_local const expression::ExpressionModel* current = nullptr;

AW_FN lreal aw_model_potential(lreal ux, lreal uy, lreal uz, AW_CONSTANT aw_rparams*) {
  return current->value(ux, uy, uz);
}
AW_FN void aw_model_force(aw_lstate* s, AW_CONSTANT aw_rparams*) {
  expression::Evaluator ev(current->potential->lowered);
  const expression::PointValues v = ev.all(s->ux, s->uy, s->uz, current->parameter_values);
  s->fx = v.force[0];
  s->fy = v.force[1];
  s->fz = v.force[2];
}
#define AW_MODELS_H /* the model is the one above, not one of models/aw_models.h */
#include "aw_initial.h"
#undef AW_MODELS_H
}  // namespace host_expression

namespace {

const host_expression::aw_rparams* core(const RealParams& rp) {
  return reinterpret_cast<const host_expression::aw_rparams*>(&rp);
}
const host_expression::aw_iparams* core(const IntParams& ip) {
  return reinterpret_cast<const host_expression::aw_iparams*>(&ip);
}

// Largest Frobenius norm of the Hessian of V on a 24^3 grid, with 10% margin
// (an estimate for the step-size guard, not a bound).
double sampled_hessian_bound(const expression::ExpressionModel& m) {
  expression::Evaluator ev(m.potential->lowered);
  constexpr int kN = 24;
  double worst = 0;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j)
      for (int k = 0; k < kN; ++k) {
        const auto v = ev.all(i / double(kN) - 0.5, j / double(kN) - 0.5, k / double(kN) - 0.5, m.parameter_values);
        const auto& h = v.hessian;
        const double f2 = h[0] * h[0] + h[1] * h[1] + h[2] * h[2] + 2 * (h[3] * h[3] + h[4] * h[4] + h[5] * h[5]);
        worst = std::max(worst, std::sqrt(f2));
      }
  return 1.1 * worst;
}

std::unique_ptr<ModelDescriptor> make_row(const ExpressionInput& in) {
  if (in.potential.empty())
    throw ModelError("model.kind",
                     "model.kind = \"expression\" needs model.potential, the potential V(x, y, z) as a string, e.g. "
                     "potential = \"cos(x)*cos(y)*(1 + cos(2*z))\" (docs/models.md)");
  const int slots = AW_MAX_MODEL_PARAMS - expression::kFirstParameter;
  if (static_cast<int>(in.parameters.size()) > slots)
    throw ModelError("model.parameters", std::to_string(in.parameters.size()) +
                                             " parameters; an expression model holds at most " + std::to_string(slots));
  for (const auto& [name, value] : in.parameters) {
    std::string why;
    if (!expression::valid_parameter_name(name, &why)) throw ModelError("model.parameters", why);
  }
  auto model = std::make_shared<expression::ExpressionModel>();
  try {
    *model = expression::make_expression_model(in.potential, in.parameters);
  } catch (const expression::ExpressionError& e) {
    throw ModelError("model.potential", e.what());
  }
  const ModelDescriptor& kind = *find_model("expression");
  auto r = std::make_unique<ModelDescriptor>(kind);
  r->device_source = model->device_header;
  r->fill_more = [model](RealParams& rp) { expression::fill_parameter_slots(*model, rp.model, AW_MAX_MODEL_PARAMS); };
  r->potential = [model](double ux, double uy, double uz, const RealParams&) { return model->value(ux, uy, uz); };
  // sampled on a 48^3 grid, widened by 1% of the span (an estimate: the extremes may lie between points)
  std::array<double, 2> range = model->sampled_range();
  const double pad = 0.01 * (range[1] - range[0]);
  range = {range[0] - pad, range[1] + pad};
  r->v_range = [range](const RealParams&) { return range; };
  const double hessian = sampled_hessian_bound(*model);
  r->hessian_bound = [hessian](const RealParams&) { return hessian; };
  const auto waves = expression::wave_vectors(*model);
  r->wave_vectors = [waves](const RealParams&) { return waves; };
  r->initial_state = [model](int kind, std::uint64_t index, const RealParams& rp, const IntParams& ip, double* u,
                             double* p) {
    host_expression::current = model.get();
    host_expression::aw_lstate s{};
    const double ok = host_expression::aw_initial_state(&s, kind, index, core(rp), core(ip));
    host_expression::current = nullptr;
    u[0] = s.ux, u[1] = s.uy, u[2] = s.uz, p[0] = s.px, p[1] = s.py, p[2] = s.pz;
    return ok != 0;
  };
  r->speed = [](double ke, const double* n, const RealParams& rp, double& speed) {
    double ok = 0;
    speed = host_expression::aw_model_speed(ke, n[0], n[1], n[2], core(rp), &ok);
    return ok != 0;
  };
  return r;
}

}  // namespace

const ModelDescriptor& expression_row(const ExpressionInput& in) {
  // one row per potential and parameters, kept for the process (a handful per run)
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<ModelDescriptor>> rows;
  std::string key = in.potential;
  for (const auto& [name, value] : in.parameters) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%a", value);
    key += '\n' + name + '=' + buf;
  }
  std::lock_guard<std::mutex> lock(mutex);
  auto it = rows.find(key);
  if (it == rows.end()) it = rows.emplace(key, make_row(in)).first;
  return *it->second;
}

}  // namespace arnoldweb::detail
