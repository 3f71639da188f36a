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
    {  // operands in named steps, left first: the node order (and so the emitted
       // code) must not depend on the compiler's order of evaluating arguments
      const int da = d(n.a, i), db = d(n.b, i);
      r = g_.add(da, db);
      break;
    }
    case Op::Sub:
    {
      const int da = d(n.a, i), db = d(n.b, i);
      r = g_.sub(da, db);
      break;
    }
    case Op::Neg:
      r = g_.neg(d(n.a, i));
      break;
    case Op::Mul:
    {
      const int da = d(n.a, i);
      const int left = g_.mul(da, n.b);
      const int db = d(n.b, i);
      const int right = g_.mul(n.a, db);
      r = g_.add(left, right);
      break;
    }
    case Op::Div: {
      const int da = d(n.a, i), db = d(n.b, i);
      const int left = g_.div(da, n.b);
      const int num = g_.mul(n.a, db);
      const int den = g_.mul(n.b, n.b);
      const int right = g_.div(num, den);
      r = g_.sub(left, right);
      break;
    }
    case Op::Pow:
    {
      const int k = g_.constant(n.k);
      const int power = g_.pow(n.a, n.k - 1);
      const int outer = g_.mul(k, power);
      const int da = d(n.a, i);
      r = g_.mul(outer, da);
      break;
    }
    case Op::Sin:
    {
      const int c = g_.cos(n.a);
      const int da = d(n.a, i);
      r = g_.mul(c, da);
      break;
    }
    case Op::Cos:
    {
      const int sn = g_.sin(n.a);
      const int da = d(n.a, i);
      r = g_.neg(g_.mul(sn, da));
      break;
    }
    case Op::Exp:
      r = g_.mul(id, d(n.a, i));
      break;
    case Op::Sqrt:
    {
      const int da = d(n.a, i);
      const int two = g_.constant(2);
      r = g_.div(da, g_.mul(two, id));
      break;
    }
    default:
      throw ExpressionError(0, "internal: cannot differentiate the lowered form");
  }
  memo_.emplace(key, r);
  return r;
}

}  // namespace arnoldweb::detail::expression
