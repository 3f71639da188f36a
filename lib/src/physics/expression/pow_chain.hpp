// arnoldweb expression models: an integer power as a fixed chain of products
// (square and multiply from the leading bit: a^3 = (a a) a, a^4 = (a a)(a a),
// a^5 = ((a a)(a a)) a; a^-n = 1 / a^n). The lowering (lower.cpp) builds these
// nodes and constant folding computes the same chain, so folding never
// changes a value.
#pragma once

namespace arnoldweb::detail::expression {

template <class T, class Mul, class Div>
T pow_chain(T a, int n, Mul mul, Div div, T one) {
  if (n == 0) return one;
  const unsigned m = static_cast<unsigned>(n < 0 ? -n : n);
  int top = 31;
  while (!((m >> top) & 1u)) --top;
  T r = a;
  for (int bit = top - 1; bit >= 0; --bit) {
    r = mul(r, r);
    if ((m >> bit) & 1u) r = mul(r, a);
  }
  return n < 0 ? div(one, r) : r;
}

}  // namespace arnoldweb::detail::expression
