// arnoldweb expression models: the host evaluator. Computes the lowered form
// (lower.hpp) node by node in double, in the order of the node ids, with the
// kernels' own sin/cos of turns and exp (lib/device, compiled for the host):
// the same operations in the same order as the emitted code, so it gives the
// bits a double kernel gives (tests/physics/test_expression_emit.cpp).
#pragma once

#include <array>
#include <vector>

#include "physics/expression/lower.hpp"

namespace arnoldweb::detail::expression {

struct PointValues {
  double value = 0;
  std::array<double, 3> force{};
  std::array<double, 6> hessian{};
};

class Evaluator {
 public:
  explicit Evaluator(const LoweredForm& form) : form_(form) {}
  // at (ux, uy, uz) in turns, with the parameters' values in order
  double potential(double ux, double uy, double uz, const std::vector<double>& params);
  PointValues all(double ux, double uy, double uz, const std::vector<double>& params);
  // every node's value (node ids index it)
  const std::vector<double>& nodes(double ux, double uy, double uz, const std::vector<double>& params);

 private:
  void run(int last, double ux, double uy, double uz, const std::vector<double>& params);
  const LoweredForm& form_;
  std::vector<double> v_;
};

}  // namespace arnoldweb::detail::expression
