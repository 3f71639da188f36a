// arnoldweb tests: the potentials whose emitted code is kept in
// tests/physics/expression_golden/ and compiled into the tests.
#pragma once

#include <string>
#include <vector>

namespace awtest {

// the paper's model (seibert2011) written as an expression
inline const char* paper_potential() { return "cos(x)*cos(y)*(1 + cos(2*z))"; }

// every construct: parameters, exp, sqrt, powers, division, a non-linear argument
inline const char* mixed_potential() {
  return "a*exp(cos(x - y))*sqrt(2 + sin(z)) + b*sin(x)^3*cos(2*y + z)^2 - 1/(3 + sin(cos(x)*2))";
}
inline std::vector<std::string> mixed_parameters() { return {"a", "b"}; }
inline std::vector<double> mixed_values() { return {0.3, -1.7}; }
constexpr int kMixedParameterBase = 5;  // rp->model[5], [6]: not the first slots

}  // namespace awtest
