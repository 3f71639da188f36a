// arnoldweb expression models: symbolic differentiation (radian form).
#pragma once

#include <map>
#include <utility>

#include "physics/expression/graph.hpp"

namespace arnoldweb::detail::expression {

// d(node)/d(coordinate) as a node of the same graph, built with the
// simplifying builders. Remembers what it has derived, so the derivatives of
// a gradient (the Hessian) reuse the gradient's nodes.
class Differentiator {
 public:
  explicit Differentiator(Graph& g) : g_(g) {}
  int d(int node, int coordinate);

 private:
  Graph& g_;
  std::map<std::pair<int, int>, int> memo_;
};

}  // namespace arnoldweb::detail::expression
