// arnoldweb expression models: a potential from the scene, made into what the
// plan hands to the kernels: the device header that replaces a built-in's
// (models/aw_expression.h, AW_MODEL 1000), the parameter slots, and V on the
// host (the host evaluator) for the planner's checks.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "physics/expression/potential.hpp"

namespace arnoldweb::detail::expression {

// AW_MODEL of an expression model (lib/device/models/aw_models.h).
constexpr int kExpressionModelId = 1000;
// rp->model index of the potential's first parameter (AW_EXPRESSION_FIRST_PARAMETER
// in lib/device/models/aw_expression_kinetic.h); a and b of T come first.
constexpr int kFirstParameter = 6;

struct ExpressionModel {
  std::shared_ptr<const Potential> potential;
  std::vector<double> parameter_values;  // in the order of potential->parameters
  std::string device_header;             // the whole model, for OpenCL and CUDA
  // V at (ux, uy, uz) in turns on the host (the same bits as a double kernel)
  double value(double ux, double uy, double uz) const;
  // bounds of V over the torus, from the periodicity check's grid and a
  // finer one (an estimate: the true minimum may be slightly lower)
  std::array<double, 2> sampled_range() const;
};

// Compiles `text` with the named parameters, checks periodicity and
// finiteness, emits the device header. Throws ExpressionError.
ExpressionModel make_expression_model(const std::string& text,
                                      const std::vector<std::pair<std::string, double>>& parameters);

// The wave vectors k of the sin/cos arguments that are linear in the
// coordinates (k.X + c), found numerically, rounded to integers (one sign of
// each; non-linear arguments are left out): for the step-size guard and the
// resonance circles.
std::vector<std::array<int, 3>> wave_vectors(const ExpressionModel& m);

// Writes T's coefficients (a, b) and the parameters into rp.model (`model`
// points at AW_MAX_MODEL_PARAMS reals). Throws ExpressionError when the
// parameters do not fit.
void fill_model_slots(const ExpressionModel& m, const std::array<double, 3>& a, const std::array<double, 3>& b,
                      double* model, int slots);

}  // namespace arnoldweb::detail::expression
