// arnoldweb expression models: infix text of a graph node (graph.hpp).
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "physics/expression/graph.hpp"

namespace arnoldweb::detail::expression {

std::string number_text(double v) {
  char buf[40];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

namespace {

// binding strength: + - 1, * / 2, unary minus 3, ^ 4, atoms and calls 5
int precedence(const Node& n) {
  switch (n.op) {
    case Op::Add:
    case Op::Sub:
      return 1;
    case Op::Mul:
    case Op::Div:
      return 2;
    case Op::Neg:
      return 3;
    case Op::Pow:
      return 4;
    case Op::Const:
      return n.value < 0 ? 3 : 5;
    default:
      return 5;
  }
}

const char* function_name(Op op) {
  switch (op) {
    case Op::Sin:
      return "sin";
    case Op::Cos:
      return "cos";
    case Op::SinTurns:
      return "sin2pi";
    case Op::CosTurns:
      return "cos2pi";
    case Op::Exp:
      return "exp";
    default:
      return "sqrt";
  }
}

std::string text(const Graph& g, int id, const std::vector<std::string>& names);

std::string wrapped(const Graph& g, int id, const std::vector<std::string>& names, bool paren) {
  return paren ? "(" + text(g, id, names) + ")" : text(g, id, names);
}

std::string text(const Graph& g, int id, const std::vector<std::string>& names) {
  const Node& n = g[id];
  static const char* const vars[] = {"x", "y", "z"};
  static const char* const us[] = {"ux", "uy", "uz"};
  const int p = precedence(n);
  switch (n.op) {
    case Op::Const:
      return number_text(n.value);
    case Op::Param:
      return n.k < static_cast<int>(names.size()) ? names[static_cast<std::size_t>(n.k)]
                                                  : "p" + std::to_string(n.k);
    case Op::Var:
      return vars[n.k];
    case Op::U:
      return us[n.k];
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div: {
      const char* sym = n.op == Op::Add ? " + " : n.op == Op::Sub ? " - " : n.op == Op::Mul ? "*" : "/";
      const bool left_paren = precedence(g[n.a]) < p;
      const bool right_paren = precedence(g[n.b]) <= p;  // the tree as built: never regrouped
      return wrapped(g, n.a, names, left_paren) + sym + wrapped(g, n.b, names, right_paren);
    }
    case Op::Neg:
      return "-" + wrapped(g, n.a, names, precedence(g[n.a]) <= p);
    case Op::Pow:
      return wrapped(g, n.a, names, precedence(g[n.a]) <= p) + "^" + std::to_string(n.k);
    default:
      return std::string(function_name(n.op)) + "(" + text(g, n.a, names) + ")";
  }
}

}  // namespace

std::string to_text(const Graph& g, int id, const std::vector<std::string>& parameter_names) {
  return text(g, id, parameter_names);
}

}  // namespace arnoldweb::detail::expression
