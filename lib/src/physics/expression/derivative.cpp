// arnoldweb expression models: symbolic differentiation (derivative.hpp).
// The rules, with a' = da/dx_i:
//   (a + b)' = a' + b'        (a - b)' = a' - b'      (-a)' = -a'
//   (a b)'   = a' b + a b'    (a / b)' = a'/b - (a b')/(b b)
//   (a^n)'   = (n a^(n-1)) a'
//   sin(a)'  = cos(a) a'      cos(a)'  = -(sin(a) a')
//   exp(a)'  = exp(a) a'      sqrt(a)' = a' / (2 sqrt(a))
// The builders drop the zero and unit factors (a variable-free b gives
// a'/b), so the result of a sum of products of sines and cosines is again a
// sum of products of the same sines and cosines.
#include "physics/expression/derivative.hpp"

namespace arnoldweb::detail::expression {

int Differentiator::d(int id, int i) {
  const Node n = g_[id];
  if (!(n.vars & (1u << i))) return g_.constant(0);
  const auto key = std::make_pair(id, i);
  if (auto it = memo_.find(key); it != memo_.end()) return it->second;
  int r = 0;
  switch (n.op) {
    case Op::Var:
      r = g_.constant(1);  // only x_i itself reaches here
      break;
    case Op::Add:
      r = g_.add(d(n.a, i), d(n.b, i));
      break;
    case Op::Sub:
      r = g_.sub(d(n.a, i), d(n.b, i));
      break;
    case Op::Neg:
      r = g_.neg(d(n.a, i));
      break;
    case Op::Mul:
      r = g_.add(g_.mul(d(n.a, i), n.b), g_.mul(n.a, d(n.b, i)));
      break;
    case Op::Div: {
      const int da = d(n.a, i), db = d(n.b, i);
      r = g_.sub(g_.div(da, n.b), g_.div(g_.mul(n.a, db), g_.mul(n.b, n.b)));
      break;
    }
    case Op::Pow:
      r = g_.mul(g_.mul(g_.constant(n.k), g_.pow(n.a, n.k - 1)), d(n.a, i));
      break;
    case Op::Sin:
      r = g_.mul(g_.cos(n.a), d(n.a, i));
      break;
    case Op::Cos:
      r = g_.neg(g_.mul(g_.sin(n.a), d(n.a, i)));
      break;
    case Op::Exp:
      r = g_.mul(id, d(n.a, i));
      break;
    case Op::Sqrt:
      r = g_.div(d(n.a, i), g_.mul(g_.constant(2), id));
      break;
    default:
      throw ExpressionError(0, "internal: cannot differentiate the lowered form");
  }
  memo_.emplace(key, r);
  return r;
}

}  // namespace arnoldweb::detail::expression
