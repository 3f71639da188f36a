// arnoldweb expression models: the lowered form (lower.hpp).
#include "physics/expression/lower.hpp"

#include <map>
#include <optional>

#include "physics/expression/pow_chain.hpp"

namespace arnoldweb::detail::expression {
namespace {

class Lowering {
 public:
  Lowering(const Graph& from, Graph& to) : from_(from), to_(to) {}

  int lower(int id) {
    if (auto it = memo_.find(id); it != memo_.end()) return it->second;
    const Node& n = from_[id];
    int r = 0;
    switch (n.op) {
      case Op::Const:
        r = to_.constant(n.value);
        break;
      case Op::Param:
        r = to_.param(n.k);
        break;
      case Op::Var:
      {  // operands in named steps, left first: the node order (and so the
         // emitted code) must not depend on the compiler's argument order
        const int two_pi = to_.constant(kTwoPi);
        r = to_.mul(two_pi, to_.u(n.k));
        break;
      }
      case Op::Add: {
        const int a = lower(n.a), b = lower(n.b);
        r = to_.add(a, b);
        break;
      }
      case Op::Sub: {
        const int a = lower(n.a), b = lower(n.b);
        r = to_.sub(a, b);
        break;
      }
      case Op::Mul: {
        const int a = lower(n.a), b = lower(n.b);
        r = to_.mul(a, b);
        break;
      }
      case Op::Div: {
        const int a = lower(n.a), b = lower(n.b);
        r = to_.div(a, b);
        break;
      }
      case Op::Neg:
        r = to_.neg(lower(n.a));
        break;
      case Op::Pow: {
        const int a = lower(n.a);
        r = pow_chain(
            a, n.k, [this](int p, int q) { return to_.mul(p, q); }, [this](int p, int q) { return to_.div(p, q); },
            to_.constant(1));
        break;
      }
      case Op::Sin:
        r = to_.sin_turns(turns(n.a));
        break;
      case Op::Cos:
        r = to_.cos_turns(turns(n.a));
        break;
      case Op::Exp:
        r = to_.exp(lower(n.a));
        break;
      case Op::Sqrt:
        r = to_.sqrt(lower(n.a));
        break;
      default:
        throw ExpressionError(0, "internal: the expression is already lowered");
    }
    memo_.emplace(id, r);
    return r;
  }

 private:
  // a = sum_i coef[i] x_i + rest, every part free of coordinates (nodes of to_; -1: absent)
  struct Linear {
    std::array<int, 3> coef{-1, -1, -1};
    int rest = -1;
  };

  int plus(int a, int b) { return a < 0 ? b : b < 0 ? a : to_.add(a, b); }
  int minus(int a, int b) { return b < 0 ? a : a < 0 ? to_.neg(b) : to_.sub(a, b); }

  std::optional<Linear> linear(int id) {
    const Node& n = from_[id];
    Linear l;
    if (n.vars == 0) {
      l.rest = lower(id);
      return l;
    }
    switch (n.op) {
      case Op::Var:
        l.coef[static_cast<std::size_t>(n.k)] = to_.constant(1);
        return l;
      case Op::Add:
      case Op::Sub: {
        auto a = linear(n.a), b = linear(n.b);
        if (!a || !b) return std::nullopt;
        for (std::size_t i = 0; i < 3; ++i)
          l.coef[i] = n.op == Op::Add ? plus(a->coef[i], b->coef[i]) : minus(a->coef[i], b->coef[i]);
        l.rest = n.op == Op::Add ? plus(a->rest, b->rest) : minus(a->rest, b->rest);
        return l;
      }
      case Op::Neg: {
        auto a = linear(n.a);
        if (!a) return std::nullopt;
        for (std::size_t i = 0; i < 3; ++i) l.coef[i] = a->coef[i] < 0 ? -1 : to_.neg(a->coef[i]);
        l.rest = a->rest < 0 ? -1 : to_.neg(a->rest);
        return l;
      }
      case Op::Mul:
      case Op::Div: {
        const bool a_free = from_[n.a].vars == 0, b_free = from_[n.b].vars == 0;
        if (n.op == Op::Div && !b_free) return std::nullopt;
        if (!a_free && !b_free) return std::nullopt;
        const int factor = lower(a_free ? n.a : n.b);
        auto inner = linear(a_free ? n.b : n.a);
        if (!inner) return std::nullopt;
        auto scale = [&](int c) {
          if (c < 0) return -1;
          return n.op == Op::Mul ? to_.mul(factor, c) : to_.div(c, factor);
        };
        for (std::size_t i = 0; i < 3; ++i) l.coef[i] = scale(inner->coef[i]);
        l.rest = scale(inner->rest);
        return l;
      }
      default:
        return std::nullopt;
    }
  }

  // the argument of sin/cos in turns
  int turns(int arg) {
    if (auto l = linear(arg)) {
      int t = -1;
      for (std::size_t i = 0; i < 3; ++i)
        if (l->coef[i] >= 0) t = plus(t, to_.mul(l->coef[i], to_.u(static_cast<int>(i))));
      if (l->rest >= 0) {
        const int inv_two_pi = to_.constant(kInvTwoPi);
        t = plus(t, to_.mul(inv_two_pi, l->rest));
      }
      return t < 0 ? to_.constant(0) : t;
    }
    const int inv_two_pi = to_.constant(kInvTwoPi);
    return to_.mul(inv_two_pi, lower(arg));
  }

  const Graph& from_;
  Graph& to_;
  std::map<int, int> memo_;
};

}  // namespace

LoweredForm lower(const RadianForm& radians) {
  LoweredForm out;
  Lowering l(radians.graph, out.graph);
  try {
    out.value = l.lower(radians.value);
    for (std::size_t i = 0; i < 3; ++i) out.force[i] = out.graph.neg(l.lower(radians.gradient[i]));
    for (std::size_t i = 0; i < 6; ++i) out.hessian[i] = l.lower(radians.hessian[i]);
  } catch (const FoldError& e) {
    throw ExpressionError(0, e.message);
  }
  return out;
}

}  // namespace arnoldweb::detail::expression
