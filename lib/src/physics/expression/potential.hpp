// arnoldweb expression models: a potential written by the user, from text to
// what the host and the kernels compute (docs/models.md, "Expression models").
//
//   text --parse--> radian form V --differentiate--> grad V, Hessian
//        --lower--> the form over turns --> host evaluator / emitted device code
#pragma once

#include <string>
#include <vector>

#include "physics/expression/emitter.hpp"
#include "physics/expression/evaluator.hpp"
#include "physics/expression/lower.hpp"

namespace arnoldweb::detail::expression {

constexpr int kMaxNodes = 20000;  // operations of V, its gradient and Hessian together

struct Potential {
  std::string text;
  std::vector<std::string> parameters;
  RadianForm radians;
  LoweredForm lowered;
};

// Parses, differentiates twice and lowers. Throws ExpressionError (with the
// column for errors in the text).
Potential compile_potential(const std::string& text, const std::vector<std::string>& parameters);

// Refuses a potential that is not 2pi-periodic in each coordinate, or whose
// value or force is not finite, on a fixed grid of points (dyadic in turns,
// so u + 1 is exact): throws ExpressionError naming the coordinate and the
// point. The tolerance is relative to the largest |V| seen.
void check_periodic(const Potential& p, const std::vector<double>& parameter_values);

}  // namespace arnoldweb::detail::expression
