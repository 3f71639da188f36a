// arnoldweb tests: the lane and scalar forms of a portable function compared
// element by element (test_math_lanes*.cpp: 8 lanes of GCC vectors).
#pragma once

#include <cstring>

namespace awtest {

template <class T>
bool same_bits(T a, T b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// 20000 x 8 inputs drawn by `draw`: the number of elements where the lane
// logarithm and the scalar one differ in their bits.
template <class Real, class Lane, class Draw>
long log_mismatches(Draw draw, Lane (*lanes)(Lane), Real (*one)(Real)) {
  long bad = 0;
  for (int i = 0; i < 20000; ++i) {
    Real x[8], y[8];
    for (int j = 0; j < 8; ++j) x[j] = draw();
    Lane v;
    std::memcpy(&v, x, sizeof v);
    const Lane r = lanes(v);
    std::memcpy(y, &r, sizeof r);
    for (int j = 0; j < 8; ++j) bad += !same_bits<Real>(y[j], one(x[j]));
  }
  return bad;
}

// The same for sin and cos of 2 pi u: lane aw_sincos2pi against the scalar
// aw_sincos2pi_1 (both results).
template <class Real, class Lane, class Draw>
long sincos_mismatches(Draw draw, void (*lanes)(Lane, Lane*, Lane*), void (*one)(Real, Real*, Real*)) {
  long bad = 0;
  for (int i = 0; i < 20000; ++i) {
    Real u[8], s[8], c[8];
    for (int j = 0; j < 8; ++j) u[j] = draw();
    Lane v, ls, lc;
    std::memcpy(&v, u, sizeof v);
    lanes(v, &ls, &lc);
    std::memcpy(s, &ls, sizeof ls);
    std::memcpy(c, &lc, sizeof lc);
    for (int j = 0; j < 8; ++j) {
      Real s1, c1;
      one(u[j], &s1, &c1);
      bad += !same_bits<Real>(s[j], s1) || !same_bits<Real>(c[j], c1);
    }
  }
  return bad;
}

}  // namespace awtest
