// arnoldweb tests: the lane and scalar forms of a portable function compared
// element by element (test_math_lanes*.cpp).
#pragma once

#include <cstring>

namespace awtest {

template <class T>
bool same_bits(T a, T b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// 20000 x 8 inputs drawn by `draw`, through the lane function `lanes` (8
// Real in, 8 out: the caller loads them into its lane vector, so that no
// vector crosses a call) and the scalar `one` per element; the number of
// elements whose bits differ.
template <class Real, class Draw, class Lanes, class One>
long lane_mismatches(Draw draw, Lanes lanes, One one) {
  long bad = 0;
  for (int i = 0; i < 20000; ++i) {
    Real x[8], y[8];
    for (int j = 0; j < 8; ++j) x[j] = draw();
    lanes(x, y);
    for (int j = 0; j < 8; ++j) bad += !same_bits<Real>(y[j], one(x[j]));
  }
  return bad;
}

}  // namespace awtest
