// arnoldweb expression models: the expression graph.
//
// A potential V(x, y, z), its derivatives and the form the kernels compute
// are nodes of one graph (a DAG). Nodes are interned: building a node that
// already exists returns the existing one, so every common subexpression is
// computed once (sin and cos of one argument share one aw_sincos2pi call in
// the emitted code). The builders simplify as they go (simplify.cpp): they
// fold constants and apply exact identities (x*1, x+0, 0*x, -(-x), ...), and
// put the operands of + and * in a canonical order (a+b and b+a round the
// same in IEEE arithmetic). They never reassociate: (a+b)+c stays as written.
//
// Two vocabularies share the Op enum:
//  - the radian form, as parsed and differentiated: Var (x, y, z in radians),
//    Pow, Sin, Cos;
//  - the lowered form, which the host evaluator and the emitter compute
//    (lower.cpp): U (the position in turns, u = x / 2pi), SinTurns/CosTurns
//    (sin and cos of 2 pi t, the device's aw_sincos2pi), no Pow (fixed chains
//    of products).
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace arnoldweb::detail::expression {

// An error in a potential. column: 1-based position in the text, 0 when the
// error is not about one place (periodicity, size).
class ExpressionError : public std::runtime_error {
 public:
  ExpressionError(int column, const std::string& message);
  int column() const noexcept { return column_; }
  const std::string& message() const noexcept { return message_; }

 private:
  int column_;
  std::string message_;
};

enum class Op : std::uint8_t {
  Const,     // value
  Param,     // k: index into the parameters
  Var,       // k: 0 x, 1 y, 2 z (radians)
  U,         // k: 0 ux, 1 uy, 2 uz (turns; lowered form)
  Add,
  Sub,
  Mul,
  Div,
  Neg,
  Pow,       // a^k, k an integer (radian form)
  Sin,       // radian form
  Cos,       // radian form
  SinTurns,  // sin(2 pi a) (lowered form)
  CosTurns,  // cos(2 pi a) (lowered form)
  Exp,
  Sqrt,
};

struct Node {
  Op op = Op::Const;
  int a = -1, b = -1;  // operands (node ids), -1 when absent
  int k = 0;           // variable, parameter index or exponent
  double value = 0;    // Const
  unsigned vars = 0;   // bit i: depends on coordinate i
};

// 1 / (2 pi) and 2 pi, rounded to double: the one multiplication that turns
// a non-linear argument in radians into turns, and a bare coordinate into radians.
constexpr double kInvTwoPi = 0.15915494309189535;
constexpr double kTwoPi = 6.283185307179586;

// Thrown by the builders when a constant folds to something not finite or a
// division by zero; the parser turns it into an ExpressionError with a column.
struct FoldError {
  std::string message;
};

class Graph {
 public:
  // Leaves.
  int constant(double v);
  int param(int index);
  int var(int coordinate);
  int u(int coordinate);
  // Operations, simplified (simplify.cpp).
  int add(int a, int b);
  int sub(int a, int b);
  int mul(int a, int b);
  int div(int a, int b);
  int neg(int a);
  int pow(int a, int n);
  int sin(int a);
  int cos(int a);
  int sin_turns(int a);
  int cos_turns(int a);
  int exp(int a);
  int sqrt(int a);

  const Node& operator[](int id) const { return nodes_.at(static_cast<std::size_t>(id)); }
  int size() const { return static_cast<int>(nodes_.size()); }
  bool is_const(int id, double* value = nullptr) const;
  bool is_const_equal(int id, double v) const;

 private:
  int intern(Node n);
  std::vector<Node> nodes_;
  std::map<std::tuple<int, int, int, int, std::uint64_t>, int> index_;
};

// Infix text of a node (radian or lowered form), with the fewest parentheses
// that keep the tree: for the simplifier's tests and the emitted comments.
std::string to_text(const Graph& g, int id, const std::vector<std::string>& parameter_names);
// The shortest decimal text that reads back as exactly v (17 digits at most).
std::string number_text(double v);

}  // namespace arnoldweb::detail::expression
