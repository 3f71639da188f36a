/* arnoldweb portable device core: exp(x) with a fixed operation sequence.
 *
 * Used by expression models (model.kind = "expression", docs/models.md): the
 * vendors' exp differ in their last bits, this one gives the same bits on
 * every backend because it uses only + - * and explicit fma, and integer
 * work on the bit pattern:
 *   k = rint(x / ln 2)            (the rounding sum t = x/ln2 + magic, as in aw_sincos2pi)
 *   r = x - k ln2_hi - k ln2_lo   (two fma; k ln2_hi is exact: ln2_hi has trailing zeros)
 *   exp(r) = Taylor polynomial of degree 13 (double) or 7 (float) on |r| <= ln2/2,
 *            Horner with fma (truncation below 0.05 ulp)
 *   exp(x) = exp(r) 2^k, with 2^k built from k's bits (exact).
 * Accuracy is measured against expl in tests/device/test_exp.cpp.
 *
 * Range: x is clamped to [-708, 709] (double) or [-87, 88] (float), so the
 * result is never infinite, zero or subnormal: exp(1000) returns exp(709)
 * ~ 8.2e307. A NaN argument gives NaN.
 */
#ifndef AW_EXP_H
#define AW_EXP_H

#include "aw_dialect.h"

AW_FN lreal aw_exp(lreal x) {
#ifdef AW_FLOAT
  const real x_max = AW_R(88.0), x_min = AW_R(-87.0);
  const real inv_ln2 = AW_R(1.44269504088896341);
  const real ln2_hi = AW_R(6.93145752e-01), ln2_lo = AW_R(1.42860677e-06);
#define AW_EXP_BIAS AW_BITS_C(127)
#define AW_EXP_MANT 23
#else
  const real x_max = 709.0, x_min = -708.0;
  const real inv_ln2 = 1.44269504088896338700e+00;
  const real ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10;
#define AW_EXP_BIAS AW_BITS_C(1023)
#define AW_EXP_MANT 52
#endif
  lreal xc = AW_SELECT(x, AW_LSPLAT(x_max), x > x_max);
  xc = AW_SELECT(xc, AW_LSPLAT(x_min), xc < x_min);
  lreal t = AW_FMA(xc, AW_LSPLAT(inv_ln2), AW_LSPLAT(AW_ROUND_MAGIC));
  lreal k = t - AW_ROUND_MAGIC;
  lreal r = AW_FMA(-k, AW_LSPLAT(ln2_hi), xc);
  r = AW_FMA(-k, AW_LSPLAT(ln2_lo), r);
#ifdef AW_FLOAT
  lreal p = AW_FMA(r, AW_LSPLAT(AW_R(1.98412698412698413e-04)), AW_LSPLAT(AW_R(1.38888888888888889e-03)));
  p = AW_FMA(r, p, AW_LSPLAT(AW_R(8.33333333333333333e-03)));
  p = AW_FMA(r, p, AW_LSPLAT(AW_R(4.16666666666666667e-02)));
  p = AW_FMA(r, p, AW_LSPLAT(AW_R(1.66666666666666667e-01)));
  p = AW_FMA(r, p, AW_LSPLAT(AW_R(0.5)));
#else
  lreal p = AW_FMA(r, AW_LSPLAT(1.6059043836821614e-10), AW_LSPLAT(2.08767569878680990e-09));
  p = AW_FMA(r, p, AW_LSPLAT(2.50521083854417188e-08));
  p = AW_FMA(r, p, AW_LSPLAT(2.75573192239858907e-07));
  p = AW_FMA(r, p, AW_LSPLAT(2.75573192239858907e-06));
  p = AW_FMA(r, p, AW_LSPLAT(2.48015873015873016e-05));
  p = AW_FMA(r, p, AW_LSPLAT(1.98412698412698413e-04));
  p = AW_FMA(r, p, AW_LSPLAT(1.38888888888888889e-03));
  p = AW_FMA(r, p, AW_LSPLAT(8.33333333333333333e-03));
  p = AW_FMA(r, p, AW_LSPLAT(4.16666666666666667e-02));
  p = AW_FMA(r, p, AW_LSPLAT(1.66666666666666667e-01));
  p = AW_FMA(r, p, AW_LSPLAT(0.5));
#endif
  p = AW_FMA(r, p, AW_LSPLAT(AW_R(1.0)));
  p = AW_FMA(r, p, AW_LSPLAT(AW_R(1.0)));
  /* k's two's-complement bits are the low bits of t; 2^k = (k + bias) << mantissa */
  lbits scale = (AW_AS_BITS(t) - AW_ROUND_MAGIC_BITS + AW_EXP_BIAS) << AW_EXP_MANT;
#undef AW_EXP_BIAS
#undef AW_EXP_MANT
  return p * AW_FROM_BITS(scale);
}

#endif /* AW_EXP_H */
