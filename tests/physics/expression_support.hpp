// arnoldweb tests: helpers for the expression-model tests.
#pragma once

#include <string>
#include <vector>

#include "physics/expression/potential.hpp"

namespace awtest {

namespace ex = arnoldweb::detail::expression;

// The error a potential's text raises (column and message); fails the test
// case when it compiles.
struct ParseFailure {
  int column = -1;
  std::string message;
};
inline ParseFailure failure_of(const std::string& text, const std::vector<std::string>& params = {}) {
  try {
    ex::compile_potential(text, params);
  } catch (const ex::ExpressionError& e) {
    return {e.column(), e.message()};
  }
  return {};
}

// A value of the parsed text when it folds to a constant.
inline bool constant_of(const std::string& text, double* value) {
  ex::Potential p = ex::compile_potential(text, {});
  return p.radians.graph.is_const(p.radians.value, value);
}

}  // namespace awtest
