/* arnoldweb portable device core: elementary functions.
 *
 * Angles are carried in turns (u = x / 2pi), so the argument reduction of
 * sin(2 pi u) and cos(2 pi u) is exact: f = 4u - rint(4u) in [-1/2, 1/2] is
 * computed without rounding, and the kernels are polynomials in f itself
 * (near-minimax fits of sin(pi f/2)/f and (cos(pi f/2) - 1)/f^2 in f^2,
 * scripts/fit_sincos.py), evaluated by Horner with explicit fma in a fixed
 * order: identical bits on every backend. Measured accuracy is in
 * docs/numerics.md (tests/device/test_math.cpp).
 *
 * aw_atan2 is scalar (used once per trajectory and window for binning); it
 * too uses only + - * / and fma, so pixel indices agree bit for bit.
 */
#ifndef AW_MATH_H
#define AW_MATH_H

#include "aw_dialect.h"


/* Quadrant bookkeeping shared by both precisions: given t = 4u + AW_ROUND_MAGIC
 * (the rounding sum that gives k = rint(4u) = t - AW_ROUND_MAGIC) and the
 * kernel values sr = sin(r), cr = cos(r), return sin and cos of k pi/2 + r.
 * q = k mod 4 is read from the low bits of t (two's complement, exact), and
 * the signs are flipped by XOR on the sign bit: integer work only, no
 * floating-point compare, select or negation (bitwise the same results as
 * comparing m = k - 4 rint(k/4) in floating point). */
#define AW_QUADRANT_SELECT_BITS(t, sr, cr, s, c)                                                   \
  do {                                                                                        \
    lbits aw_q_ = AW_AS_BITS(t);                                                              \
    lbits aw_neg_s_ = (aw_q_ & AW_BITS_C(2)) << AW_BIT1_TO_SIGN;                /* q = 2, 3 */ \
    lbits aw_neg_c_ = ((aw_q_ + AW_BITS_C(1)) & AW_BITS_C(2)) << AW_BIT1_TO_SIGN; /* q = 1, 2 */ \
    lreal aw_ss_ = AW_SELECT((sr), (cr), (aw_q_ & AW_BITS_C(1)) != AW_BITS_C(0));              \
    lreal aw_cc_ = AW_SELECT((cr), (sr), (aw_q_ & AW_BITS_C(1)) != AW_BITS_C(0));              \
    *(s) = AW_FROM_BITS(AW_AS_BITS(aw_ss_) ^ aw_neg_s_);                                      \
    *(c) = AW_FROM_BITS(AW_AS_BITS(aw_cc_) ^ aw_neg_c_);                                      \
  } while (0)

/* The same on CUDA in double (the default since 2026-11-28; -DAW_CUDA_QUADRANT32=0,
 * an NVRTC option, keeps the form above): q from the low 32-bit word of t and
 * the signs into the high word of the result, so that the test of q's low bit
 * is one 32-bit instruction instead of a 64-bit compare (two). The same
 * selections and sign flips: the same bits. */
#if defined(AW_CUDA) && !defined(AW_FLOAT) && (!defined(AW_CUDA_QUADRANT32) || AW_CUDA_QUADRANT32)
#define AW_QUADRANT_SELECT(t, sr, cr, s, c)                                                          \
  do {                                                                                               \
    const unsigned aw_q_ = (unsigned)__double2loint(t);                                              \
    const double aw_ss_ = (aw_q_ & 1u) ? (cr) : (sr);                                                \
    const double aw_cc_ = (aw_q_ & 1u) ? (sr) : (cr);                                                \
    *(s) = __hiloint2double(__double2hiint(aw_ss_) ^ (int)((aw_q_ & 2u) << 30), __double2loint(aw_ss_)); \
    *(c) = __hiloint2double(__double2hiint(aw_cc_) ^ (int)(((aw_q_ + 1u) & 2u) << 30),                 \
                            __double2loint(aw_cc_));                                                 \
  } while (0)
#else
#define AW_QUADRANT_SELECT(t, sr, cr, s, c) AW_QUADRANT_SELECT_BITS(t, sr, cr, s, c)
#endif

/* The identity: the S() of the kernels below for scalar callers. */
#define AW_SCALAR_(x) (x)

/* The kernels of aw_sincos2pi: sin(pi f / 2) = f S(w) and cos(pi f / 2) = 1 +
 * w C(w), w = f^2, near-minimax on |f| <= 1/2 (scripts/fit_sincos.py); S(c)
 * makes the constant c a value of the caller's type (lanes broadcast it). One
 * macro for the lane and the scalar function: the same operations, the same
 * bits. */
#ifdef AW_FLOAT
#define AW_SINCOS_POLY(S, w, ps, pc)                                                      \
  do {                                                                                    \
    (ps) = AW_FMA((w), S(AW_R(-4.602149212814176e-03)), S(AW_R(7.968021764775542e-02)));   \
    (ps) = AW_FMA((w), (ps), S(AW_R(-6.459634776648118e-01)));                               \
    (ps) = AW_FMA((w), (ps), S(AW_R(1.5707963219532366)));                                   \
    (pc) = AW_FMA((w), S(AW_R(9.067398984032665e-04)), S(AW_R(-2.0861528342199967e-02)));  \
    (pc) = AW_FMA((w), (pc), S(AW_R(2.536694103571085e-01)));                                \
    (pc) = AW_FMA((w), (pc), S(AW_R(-1.2337005493742192)));                                  \
  } while (0)
#else
#define AW_SINCOS_POLY(S, w, ps, pc)                                         \
  do {                                                                       \
    (ps) = AW_FMA((w), S(5.633933781537854e-08), S(-3.59864335298231e-06));   \
    (ps) = AW_FMA((w), (ps), S(1.604411507421909e-04));                         \
    (ps) = AW_FMA((w), (ps), S(-4.681754132340976e-03));                        \
    (ps) = AW_FMA((w), (ps), S(7.969262624604301e-02));                         \
    (ps) = AW_FMA((w), (ps), S(-6.459640975062443e-01));                        \
    (ps) = AW_FMA((w), (ps), S(1.5707963267948966));                            \
    (pc) = AW_FMA((w), S(-6.329396344967424e-09), S(4.710678405505227e-07));  \
    (pc) = AW_FMA((w), (pc), S(-2.5202039028029178e-05));                       \
    (pc) = AW_FMA((w), (pc), S(9.192602745468447e-04));                         \
    (pc) = AW_FMA((w), (pc), S(-2.0863480763340773e-02));                       \
    (pc) = AW_FMA((w), (pc), S(2.536695079010478e-01));                         \
    (pc) = AW_FMA((w), (pc), S(-1.2337005501361697));                           \
  } while (0)
#endif

/* aw_sincos2pi_n(u, n, s, c): sin and cos of 2 pi n u for n a power of two
 * (n u is exact: the multiple costs nothing beyond the reduction's own
 * products); aw_sincos2pi(u, s, c) is n = 1. */
#if defined(AW_NATIVE_MATH)
/* The vendor's functions: faster on some devices, not bitwise portable. */
AW_FN void aw_sincos2pi_n(lreal u, real n, lreal* s, lreal* c) {
#if defined(AW_OPENCL)
  *s = sinpi((AW_R(2.0) * n) * u);
  *c = cospi((AW_R(2.0) * n) * u);
#elif defined(AW_CUDA) && defined(AW_FLOAT)
  sincospif((AW_R(2.0) * n) * u, s, c);
#elif defined(AW_CUDA)
  sincospi((AW_R(2.0) * n) * u, s, c);
#else
  const real twopi = AW_R(6.283185307179586) * n;
#if AW_LANES > 1
  *s = u; /* every element is overwritten below */
  *c = u;
  for (int i = 0; i < AW_LANES; ++i) {
    (*s)[i] = std::sin(twopi * u[i]);
    (*c)[i] = std::cos(twopi * u[i]);
  }
#else
  *s = std::sin(twopi * u);
  *c = std::cos(twopi * u);
#endif
#endif
}
#else

AW_FN void aw_sincos2pi_n(lreal u, real n, lreal* s, lreal* c) {
  /* 4 n u is exact (n a power of two), so fma(4n, u, .) rounds the same sums
   * as 4 n u + . would */
  const lreal m = AW_LSPLAT(AW_R(4.0) * n);
  lreal t = AW_FMA(m, u, AW_LSPLAT(AW_ROUND_MAGIC)); /* k = t - magic: rint(4nu) */
  lreal k = t - AW_ROUND_MAGIC;
  lreal f = AW_FMA(m, u, -k); /* 4nu - k: exact, in [-1/2, 1/2] */
  lreal w = f * f;
  /* sin(pi f / 2) = f S(w) and cos(pi f / 2) = 1 + w C(w): polynomials in
   * the exact reduced argument f itself (no rounded r = f pi/2), fitted
   * near-minimax on |f| <= 1/2 (Chebyshev, scripts/fit_sincos.py; the
   * factors of pi/2 live in the coefficients). 18 operations for both
   * instead of fdlibm's 25 on r, with the same worst case (1.5 ulp double,
   * 1.7 ulp float; docs/numerics.md); exact at multiples of a quarter turn. */
  lreal ps, pc;
  AW_SINCOS_POLY(AW_LSPLAT, w, ps, pc);
  lreal sr = f * ps;
  lreal cr = AW_FMA(w, pc, AW_LSPLAT(AW_R(1.0)));
  AW_QUADRANT_SELECT(t, sr, cr, s, c);
}
#endif /* AW_NATIVE_MATH */

AW_FN void aw_sincos2pi(lreal u, lreal* s, lreal* c) { aw_sincos2pi_n(u, AW_R(1.0), s, c); }

/* sin and cos of 2 pi u for one real u, whatever the lane width: the portable
 * kernels of aw_sincos2pi_n (the same bits as it gives without
 * AW_NATIVE_MATH), for per-trajectory scalar work such as the frequency
 * analysis (aw_naff.h). Always portable. The quadrant q = k mod 4 comes from
 * m = k - 4 rint(k / 4) in floating point (exact), the signs by negation. */
AW_FN void aw_sincos2pi_1(real u, real* s, real* c) {
  const real t = AW_FMA(AW_R(4.0), u, AW_ROUND_MAGIC);
  const real k = t - AW_ROUND_MAGIC;
  const real f = AW_FMA(AW_R(4.0), u, -k);
  const real w = f * f;
  real ps, pc;
  AW_SINCOS_POLY(AW_SCALAR_, w, ps, pc);
  const real sr = f * ps;
  const real cr = AW_FMA(w, pc, AW_R(1.0));
  const real m = k - AW_R(4.0) * AW_RINT_SMALL(AW_R(0.25) * k); /* -2, -1, 0, 1, 2 */
  if (m == AW_R(0.0)) {
    *s = sr;
    *c = cr;
  } else if (m == AW_R(1.0)) {
    *s = cr;
    *c = -sr;
  } else if (m == AW_R(2.0) || m == AW_R(-2.0)) {
    *s = -sr;
    *c = -cr;
  } else { /* m = -1: q = 3 */
    *s = -cr;
    *c = sr;
  }
}

/* ------------------------------------------------------------ log */

/* The fdlibm e_log.c kernel: log(2^k m) for m in [sqrt(1/2), sqrt(2)), k an
 * integer-valued T; S(c) makes the constant c a T (lanes broadcast it). One
 * sequence of operations for the scalar and the lane logarithm, so that they
 * give the same bits. */
#ifdef AW_FLOAT
#define AW_LOG_LN2_HI 6.93359375e-01f
#define AW_LOG_LN2_LO -2.12194440e-04f
#else
#define AW_LOG_LN2_HI 6.93147180369123816490e-01
#define AW_LOG_LN2_LO 1.90821492927058770002e-10
#endif
#define AW_LOG_KERNEL(T, S, m, k, out)                                                                     \
  do {                                                                                                     \
    const T aw_f_ = (m) - S(AW_R(1.0));                                                                    \
    const T aw_s_ = aw_f_ / (S(AW_R(2.0)) + aw_f_);                                                        \
    const T aw_z_ = aw_s_ * aw_s_;                                                                         \
    const T aw_w_ = aw_z_ * aw_z_;                                                                         \
    const T aw_t1_ = aw_w_ * AW_FMA(aw_w_, AW_FMA(aw_w_, S(AW_R(1.531383769920937332e-01)),                \
                                                  S(AW_R(2.222219843214978396e-01))),                      \
                                    S(AW_R(3.999999999940941908e-01)));                                    \
    const T aw_t2_ = aw_z_ * AW_FMA(aw_w_, AW_FMA(aw_w_, AW_FMA(aw_w_, S(AW_R(1.479819860511658591e-01)), \
                                                                S(AW_R(1.818357216161805012e-01))),        \
                                                  S(AW_R(2.857142874366239149e-01))),                      \
                                    S(AW_R(6.666666666666735130e-01)));                                    \
    const T aw_r_ = aw_t2_ + aw_t1_;                                                                       \
    const T aw_hfsq_ = AW_R(0.5) * aw_f_ * aw_f_;                                                          \
    (out) = (k) * AW_LOG_LN2_HI - ((aw_hfsq_ - (aw_s_ * (aw_hfsq_ + aw_r_) + (k) * AW_LOG_LN2_LO)) - aw_f_); \
  } while (0)

/* Natural logarithm of a positive finite x (fdlibm e_log.c structure:
 * x = 2^k m with m in [sqrt(1/2), sqrt(2)), log(m) from s = f / (2 + f)).
 * Used for Gaussian initial states (Box-Muller) and once per trajectory by
 * the indicators. */
AW_FN real aw_log(real x) {
  int e;
  real m = AW_FREXP(x, &e); /* exact: x = m 2^e, m in [1/2, 1) */
  if (m < AW_R(0.70710678118654752440)) {
    m = AW_R(2.0) * m;
    e -= 1;
  }
  const real k = (real)e;
  real out;
  AW_LOG_KERNEL(real, AW_SCALAR_, m, k, out);
  return out;
}

/* The same logarithm per lane, for positive normal x (the exponent is read
 * from the bit pattern; subnormals, zero, infinities and NaN give garbage or
 * NaN, never a trap): bitwise aw_log of each element. Integer work on the
 * bits and the rounding sum give k without a conversion instruction. */
#ifdef AW_FLOAT
#define AW_LOG_MANT_BITS 23
#define AW_LOG_MANT_MASK AW_BITS_C(0x007FFFFF)
#define AW_LOG_ONE_BITS AW_BITS_C(0x3F800000)
#define AW_LOG_BIAS AW_R(127.0)
#else
#define AW_LOG_MANT_BITS 52
#define AW_LOG_MANT_MASK AW_BITS_C(0x000FFFFFFFFFFFFF)
#define AW_LOG_ONE_BITS AW_BITS_C(0x3FF0000000000000)
#define AW_LOG_BIAS AW_R(1023.0)
#endif
AW_FN lreal aw_log_lanes(lreal x) {
  const lbits b = AW_AS_BITS(x);
  lreal m = AW_FROM_BITS((b & AW_LOG_MANT_MASK) | AW_LOG_ONE_BITS); /* [1, 2): x = 2^(E) m */
  /* E + bias is the exponent field (x > 0: no sign bit); added to the bits of
   * the rounding constant it is read as a real exactly */
  lreal k = (AW_FROM_BITS(AW_ROUND_MAGIC_BITS + (b >> AW_LOG_MANT_BITS)) - AW_ROUND_MAGIC) - AW_LOG_BIAS;
  /* aw_log's m (in [1/2, 1)) is m / 2 here: m / 2 < sqrt(1/2) is m < sqrt(2) */
  k = AW_SELECT(k + AW_R(1.0), k, m < AW_R(1.41421356237309504880));
  m = AW_SELECT(m * AW_R(0.5), m, m < AW_R(1.41421356237309504880)); /* after k: the test reads the old m */
  lreal out;
  AW_LOG_KERNEL(lreal, AW_LSPLAT, m, k, out);
  return out;
}

/* ------------------------------------------------------------ scalar atan2 */

/* atan(t) for 0 <= t <= 1. */
AW_FN real aw_atan_unit(real t) {
#ifdef AW_FLOAT
  /* Cephes atanf: reduce t > tan(pi/8) by atan(t) = pi/4 + atan((t-1)/(t+1)) */
  real base = 0.0f;
  if (t > 0.41421356237309504880f) {
    t = (t - 1.0f) / (t + 1.0f);
    base = 0.78539816339744830962f;
  }
  real z = t * t;
  real p = AW_FMA(z, 8.05374449538e-2f, -1.38776856032e-1f);
  p = AW_FMA(z, p, 1.99777106478e-1f);
  p = AW_FMA(z, p, -3.33329491539e-1f);
  return base + AW_FMA(z * t, p, t);
#else
  /* fdlibm s_atan.c structure for the arguments that occur here */
  real hi = 0.0, lo = 0.0;
  int reduced = 1;
  if (t < 0.4375) {
    reduced = 0;
  } else if (t < 0.6875) {
    t = (2.0 * t - 1.0) / (2.0 + t);
    hi = 4.63647609000806093515e-01;
    lo = 2.26987774529616870924e-17;
  } else {
    t = (t - 1.0) / (t + 1.0);
    hi = 7.85398163397448278999e-01;
    lo = 3.06161699786838301793e-17;
  }
  real z = t * t;
  real w = z * z;
  real s1 = AW_FMA(w, 1.62858201153657823623e-02, 4.97687799461593236017e-02);
  s1 = AW_FMA(w, s1, 6.66107313738753120669e-02);
  s1 = AW_FMA(w, s1, 9.09088713343650656196e-02);
  s1 = AW_FMA(w, s1, 1.42857142725034663711e-01);
  s1 = AW_FMA(w, s1, 3.33333333333329318027e-01);
  s1 = z * s1;
  real s2 = AW_FMA(w, -3.65315727442169155270e-02, -5.83357013379057348645e-02);
  s2 = AW_FMA(w, s2, -7.69187620504482999495e-02);
  s2 = AW_FMA(w, s2, -1.11111104054623557880e-01);
  s2 = AW_FMA(w, s2, -1.99999999998764832476e-01);
  s2 = w * s2;
  if (!reduced) return t - t * (s1 + s2);
  return hi - ((t * (s1 + s2) - lo) - t);
#endif
}

/* atan2(y, x) in (-pi, pi]; atan2(0, 0) = 0. */
AW_FN real aw_atan2(real y, real x) {
  real ax = AW_FABS(x), ay = AW_FABS(y);
  real a;
  if (ax == AW_R(0.0) && ay == AW_R(0.0)) return AW_R(0.0);
  if (ay <= ax) {
    a = aw_atan_unit(ay / ax);
  } else {
    /* pi/2 - atan(ax/ay), with pi/2 in two parts */
#ifdef AW_FLOAT
    a = 1.5707963705062866f - (aw_atan_unit(ax / ay) + 4.371138828673793e-08f);
#else
    a = 1.5707963267948966 - (aw_atan_unit(ax / ay) - 6.123233995736766e-17);
#endif
  }
  if (x < AW_R(0.0)) {
#ifdef AW_FLOAT
    a = 3.1415927410125732f - (a + 8.742277657347586e-08f);
#else
    a = 3.141592653589793 - (a - 1.2246467991473532e-16);
#endif
  }
  return (y < AW_R(0.0)) ? -a : a;
}

#endif /* AW_MATH_H */
