// arnoldweb expression models: the grammar of a potential (docs/models.md).
//
//   expression := term (('+' | '-') term)*
//   term       := unary (('*' | '/') unary)*
//   unary      := ('-' | '+') unary | power
//   power      := primary ('^' exponent)?          -x^2 is -(x^2); x^2^3 is refused
//   exponent   := ['-' | '+'] integer | '(' ['-' | '+'] integer ')'   |integer| <= 64
//   primary    := number | name | function '(' expression ')' | '(' expression ')'
//   function   := sin | cos | exp | sqrt
//   name       := x | y | z (radians) | pi | a parameter of the scene
//   number     := 12, 0.5, .5, 1e-3, 2.5E+2
#pragma once

#include <string>
#include <vector>

#include "physics/expression/graph.hpp"

namespace arnoldweb::detail::expression {

constexpr std::size_t kMaxLength = 4096;  // characters of a potential
constexpr int kMaxDepth = 64;             // nesting of parentheses, calls and signs
constexpr int kMaxExponent = 64;          // |n| in a^n

// Parses `text` into g (radian form, simplified as it is built) and returns
// the root. Names other than x, y, z, pi and the functions must be among
// `parameters` (parameter i becomes Param(i)). Throws ExpressionError with
// the column of the offending token.
int parse(Graph& g, const std::string& text, const std::vector<std::string>& parameters);

// Whether `name` may name a parameter (an identifier that is not x, y, z, pi
// or a function); the reason when not.
bool valid_parameter_name(const std::string& name, std::string* why);

}  // namespace arnoldweb::detail::expression
