// arnoldweb expression models: the graph's builders, which simplify as they
// build (graph.hpp). Every rule is an identity of real numbers that holds
// exactly in IEEE arithmetic for finite operands (a+b = b+a, a*1 = a,
// (-a)*b = -(a*b), ...) or folds constants; none reassociates.
//
// Constants fold with the kernels' own functions (the portable sin/cos of
// turns and exp of lib/device, compiled for the host), so a folded constant
// is the value the device would compute in double.
#include <cmath>
#include <cstring>

#include "aw_cpp_std.h"
#include "physics/expression/graph.hpp"
#include "physics/expression/pow_chain.hpp"

namespace arnoldweb::detail::expression {
namespace host_math {
#include "aw_exp.h"
#include "aw_math.h"
}  // namespace host_math

ExpressionError::ExpressionError(int column, const std::string& message)
    : std::runtime_error(column > 0 ? "column " + std::to_string(column) + ": " + message : message),
      column_(column),
      message_(message) {}

namespace {

std::uint64_t bits_of(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

double finite_or_throw(double v, const char* what) {
  if (!std::isfinite(v)) throw FoldError{std::string("the constant ") + what + " is not finite"};
  return v;
}

bool is_commutative(Op op) { return op == Op::Add || op == Op::Mul; }

}  // namespace

int Graph::intern(Node n) {
  if (is_commutative(n.op)) {
    // constants first, then by id: one node for a+b and b+a
    const bool ca = (*this)[n.a].op == Op::Const, cb = (*this)[n.b].op == Op::Const;
    if ((cb && !ca) || (ca == cb && n.b < n.a)) std::swap(n.a, n.b);
  }
  const auto key = std::make_tuple(static_cast<int>(n.op), n.a, n.b, n.k, bits_of(n.value));
  auto it = index_.find(key);
  if (it != index_.end()) return it->second;
  n.vars = 0;
  if (n.op == Op::Var || n.op == Op::U) n.vars = 1u << n.k;
  if (n.a >= 0) n.vars |= (*this)[n.a].vars;
  if (n.b >= 0) n.vars |= (*this)[n.b].vars;
  nodes_.push_back(n);
  const int id = static_cast<int>(nodes_.size()) - 1;
  index_.emplace(key, id);
  return id;
}

bool Graph::is_const(int id, double* value) const {
  const Node& n = (*this)[id];
  if (n.op != Op::Const) return false;
  if (value) *value = n.value;
  return true;
}

bool Graph::is_const_equal(int id, double v) const {
  double c;
  return is_const(id, &c) && c == v;
}

int Graph::constant(double v) {
  Node n;
  n.op = Op::Const;
  n.value = v == 0 ? 0.0 : v;  // one zero: -0 and +0 are the same constant here
  return intern(n);
}

int Graph::param(int index) {
  Node n;
  n.op = Op::Param;
  n.k = index;
  return intern(n);
}

int Graph::var(int coordinate) {
  Node n;
  n.op = Op::Var;
  n.k = coordinate;
  return intern(n);
}

int Graph::u(int coordinate) {
  Node n;
  n.op = Op::U;
  n.k = coordinate;
  return intern(n);
}

namespace {
Node binary(Op op, int a, int b) {
  Node n;
  n.op = op;
  n.a = a;
  n.b = b;
  return n;
}
Node unary(Op op, int a) {
  Node n;
  n.op = op;
  n.a = a;
  return n;
}
}  // namespace

int Graph::add(int a, int b) {
  double x, y;
  if (is_const(a, &x) && is_const(b, &y)) return constant(finite_or_throw(x + y, "sum"));
  if (is_const_equal(a, 0)) return b;
  if (is_const_equal(b, 0)) return a;
  if ((*this)[b].op == Op::Neg) return sub(a, (*this)[b].a);  // a + (-c) = a - c
  if ((*this)[a].op == Op::Neg) return sub(b, (*this)[a].a);  // (-c) + b = b - c
  return intern(binary(Op::Add, a, b));
}

int Graph::sub(int a, int b) {
  double x, y;
  if (is_const(a, &x) && is_const(b, &y)) return constant(finite_or_throw(x - y, "difference"));
  if (is_const_equal(b, 0)) return a;
  if (is_const_equal(a, 0)) return neg(b);
  if (a == b) return constant(0);
  if ((*this)[b].op == Op::Neg) return add(a, (*this)[b].a);  // a - (-c) = a + c
  return intern(binary(Op::Sub, a, b));
}

int Graph::mul(int a, int b) {
  double x, y;
  if (is_const(a, &x) && is_const(b, &y)) return constant(finite_or_throw(x * y, "product"));
  if (is_const_equal(a, 0) || is_const_equal(b, 0)) return constant(0);
  if (is_const_equal(a, 1)) return b;
  if (is_const_equal(b, 1)) return a;
  if (is_const_equal(a, -1)) return neg(b);
  if (is_const_equal(b, -1)) return neg(a);
  if ((*this)[a].op == Op::Neg) return neg(mul((*this)[a].a, b));  // (-c) b = -(c b)
  if ((*this)[b].op == Op::Neg) return neg(mul(a, (*this)[b].a));
  if (is_const(b) && !is_const(a)) std::swap(a, b);  // the constant first: 2*x
  return intern(binary(Op::Mul, a, b));
}

int Graph::div(int a, int b) {
  double x, y;
  if (is_const_equal(b, 0)) throw FoldError{"division by zero"};
  if (is_const(a, &x) && is_const(b, &y)) return constant(finite_or_throw(x / y, "quotient"));
  if (is_const_equal(a, 0)) return constant(0);
  if (is_const_equal(b, 1)) return a;
  if (is_const_equal(b, -1)) return neg(a);
  if ((*this)[a].op == Op::Neg) return neg(div((*this)[a].a, b));
  if ((*this)[b].op == Op::Neg) return neg(div(a, (*this)[b].a));
  return intern(binary(Op::Div, a, b));
}

int Graph::neg(int a) {
  double x;
  if (is_const(a, &x)) return constant(-x);
  if ((*this)[a].op == Op::Neg) return (*this)[a].a;
  return intern(unary(Op::Neg, a));
}

int Graph::pow(int a, int n) {
  double x;
  if (n == 0) return constant(1);
  if (n == 1) return a;
  if (is_const(a, &x)) {
    if (x == 0 && n < 0) throw FoldError{"division by zero (0 to a negative power)"};
    return constant(finite_or_throw(pow_chain(x, n, [](double p, double q) { return p * q; },
                                              [](double p, double q) { return p / q; }, 1.0),
                                    "power"));
  }
  if ((*this)[a].op == Op::Neg) {  // (-c)^n = +-(c^n)
    const int p = pow((*this)[a].a, n);
    return (n % 2 == 0) ? p : neg(p);
  }
  Node node = unary(Op::Pow, a);
  node.k = n;
  return intern(node);
}

int Graph::sin(int a) {
  double x;
  if (is_const(a, &x)) {
    double s, c;
    host_math::aw_sincos2pi(x * kInvTwoPi, &s, &c);
    return constant(s);
  }
  if ((*this)[a].op == Op::Neg) return neg(sin((*this)[a].a));  // sin(-c) = -sin(c)
  return intern(unary(Op::Sin, a));
}

int Graph::cos(int a) {
  double x;
  if (is_const(a, &x)) {
    double s, c;
    host_math::aw_sincos2pi(x * kInvTwoPi, &s, &c);
    return constant(c);
  }
  if ((*this)[a].op == Op::Neg) return cos((*this)[a].a);  // cos(-c) = cos(c)
  return intern(unary(Op::Cos, a));
}

int Graph::sin_turns(int a) {
  double x;
  if (is_const(a, &x)) {
    double s, c;
    host_math::aw_sincos2pi(x, &s, &c);
    return constant(s);
  }
  return intern(unary(Op::SinTurns, a));
}

int Graph::cos_turns(int a) {
  double x;
  if (is_const(a, &x)) {
    double s, c;
    host_math::aw_sincos2pi(x, &s, &c);
    return constant(c);
  }
  return intern(unary(Op::CosTurns, a));
}

int Graph::exp(int a) {
  double x;
  if (is_const(a, &x)) {
    if (!(x <= 709.0)) throw FoldError{"exp of a constant overflows (the argument is above 709)"};
    return constant(host_math::aw_exp(x));
  }
  return intern(unary(Op::Exp, a));
}

int Graph::sqrt(int a) {
  double x;
  if (is_const(a, &x)) {
    if (x < 0) throw FoldError{"square root of a negative constant"};
    return constant(std::sqrt(x));
  }
  return intern(unary(Op::Sqrt, a));
}

}  // namespace arnoldweb::detail::expression
