// Error of a computed value against a long-double reference, in units in the
// last place of the computed type.
#pragma once
#include <cmath>
#include <limits>

namespace awtest {

template <class T>
double ulp_error(T computed, long double reference) {
  const T r = static_cast<T>(reference);
  // ulp of the reference's magnitude in T (at zero: the smallest normal's ulp)
  T mag = std::fabs(r);
  if (mag < std::numeric_limits<T>::min()) mag = std::numeric_limits<T>::min();
  const T ulp = std::nextafter(mag, std::numeric_limits<T>::infinity()) - mag;
  return static_cast<double>(std::fabs(static_cast<long double>(computed) - reference) / ulp);
}

// sin and cos of 2 pi u with the reduction done exactly: u - k/2 is exact in
// long double for a double or float u, so the reference keeps its relative
// accuracy near the zeros of sin and cos.
inline void sincos2pi_reference(long double u, long double* s, long double* c) {
  const long double twopi = 6.283185307179586476925286766559005768L;
  const long double k = std::rint(4 * u);  // quarter turns
  const long double r = twopi * (u - k / 4);
  const int q = static_cast<int>(std::fmod(std::fmod(k, 4.0L) + 4.0L, 4.0L));
  const long double sr = sinl(r), cr = cosl(r);
  *s = q == 0 ? sr : q == 1 ? cr : q == 2 ? -sr : -cr;
  *c = q == 0 ? cr : q == 1 ? -sr : q == 2 ? -cr : sr;
}

}  // namespace awtest
