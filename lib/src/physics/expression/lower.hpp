// arnoldweb expression models: the lowered form, what the kernels compute.
//
// From the radian form (parsed and differentiated) to a graph over the
// position in turns (the kernels carry u = x / 2pi):
//  - sin(a), cos(a): the argument in turns, then SinTurns/CosTurns (the
//    portable aw_sincos2pi; sin and cos of one argument share one call).
//    When a is linear in the coordinates, a = c_x x + c_y y + c_z z + r with
//    coefficients c_i and rest r free of coordinates, the argument in turns is
//    c_x ux + c_y uy + c_z uz + r / 2pi (in that order; a coefficient 1 is no
//    multiplication, an integer coefficient times u is exact for |c| < 2^k
//    where u has 53 - k significant bits, and the reduction to a quarter turn
//    inside aw_sincos2pi is exact): cos(2z) is cos2pi(2 uz), cos(x + y) is
//    cos2pi(ux + uy). Any other argument is computed in radians and turned
//    into turns by one multiplication with 1/2pi (kInvTwoPi).
//  - a bare coordinate x (outside a linear sin/cos argument) is 2pi ux.
//  - a^n: a fixed chain of products (pow_chain.hpp).
#pragma once

#include <array>

#include "physics/expression/graph.hpp"

namespace arnoldweb::detail::expression {

// The roots in the radian form: V, its gradient and its Hessian.
struct RadianForm {
  Graph graph;
  int value = -1;
  std::array<int, 3> gradient{};
  std::array<int, 6> hessian{};  // xx, yy, zz, xy, xz, yz
};

// The roots in the lowered form: V, the force F = -grad V, the Hessian.
struct LoweredForm {
  Graph graph;
  int value = -1;
  std::array<int, 3> force{};
  std::array<int, 6> hessian{};  // xx, yy, zz, xy, xz, yz
};

LoweredForm lower(const RadianForm& radians);

}  // namespace arnoldweb::detail::expression
