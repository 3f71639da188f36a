// arnoldweb expression models: the host evaluator (evaluator.hpp).
#include "physics/expression/evaluator.hpp"

#include <algorithm>
#include <cmath>

#include "aw_cpp_std.h"

namespace arnoldweb::detail::expression {
namespace host_math {
#include "aw_exp.h"
#include "aw_math.h"
}  // namespace host_math

void Evaluator::run(int last, double ux, double uy, double uz, const std::vector<double>& params) {
  const Graph& g = form_.graph;
  v_.resize(static_cast<std::size_t>(g.size()));
  const double u[3] = {ux, uy, uz};
  for (int id = 0; id <= last; ++id) {
    const Node& n = g[id];
    auto A = [&] { return v_[static_cast<std::size_t>(n.a)]; };
    auto B = [&] { return v_[static_cast<std::size_t>(n.b)]; };
    double r = 0;
    switch (n.op) {
      case Op::Const:
        r = n.value;
        break;
      case Op::Param:
        r = params.at(static_cast<std::size_t>(n.k));
        break;
      case Op::U:
        r = u[n.k];
        break;
      case Op::Add:
        r = A() + B();
        break;
      case Op::Sub:
        r = A() - B();
        break;
      case Op::Mul:
        r = A() * B();
        break;
      case Op::Div:
        r = A() / B();
        break;
      case Op::Neg:
        r = -A();
        break;
      case Op::SinTurns:
      case Op::CosTurns: {
        double s, c;
        host_math::aw_sincos2pi(A(), &s, &c);
        r = n.op == Op::SinTurns ? s : c;
        break;
      }
      case Op::Exp:
        r = host_math::aw_exp(A());
        break;
      case Op::Sqrt:
        r = std::sqrt(A());
        break;
      default:
        throw ExpressionError(0, "internal: the host evaluator needs the lowered form");
    }
    v_[static_cast<std::size_t>(id)] = r;
  }
}

double Evaluator::potential(double ux, double uy, double uz, const std::vector<double>& params) {
  run(form_.value, ux, uy, uz, params);
  return v_[static_cast<std::size_t>(form_.value)];
}

const std::vector<double>& Evaluator::nodes(double ux, double uy, double uz, const std::vector<double>& params) {
  run(form_.graph.size() - 1, ux, uy, uz, params);
  return v_;
}

PointValues Evaluator::all(double ux, double uy, double uz, const std::vector<double>& params) {
  int last = form_.value;
  for (int f : form_.force) last = std::max(last, f);
  for (int h : form_.hessian) last = std::max(last, h);
  run(last, ux, uy, uz, params);
  PointValues p;
  p.value = v_[static_cast<std::size_t>(form_.value)];
  for (std::size_t i = 0; i < 3; ++i) p.force[i] = v_[static_cast<std::size_t>(form_.force[i])];
  for (std::size_t i = 0; i < 6; ++i) p.hessian[i] = v_[static_cast<std::size_t>(form_.hessian[i])];
  return p;
}

}  // namespace arnoldweb::detail::expression
