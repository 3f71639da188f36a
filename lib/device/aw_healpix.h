/* arnoldweb portable device core: HEALPix pixel of a direction (RING order).
 *
 * Implements the ring-scheme formulas of Gorski et al., ApJ 622 (2005) 759,
 * with the azimuth from the portable aw_atan2, so that every backend puts a
 * direction into the same pixel. tests/device/test_math.cpp compares it with
 * Debian's HEALPix C++ library where that is installed.
 */
#ifndef AW_HEALPIX_H
#define AW_HEALPIX_H

#include "aw_math.h"

/* Pixel index in [0, 12 nside^2) of the direction (x, y, z), which must not be
 * the zero vector. */
AW_FN aw_i64 aw_vec2pix_ring(aw_i64 nside, real x, real y, real z) {
  const real inv_halfpi = AW_R(0.6366197723675814);
  real rxy = AW_SQRT(AW_FMA(y, y, x * x));
  real norm = AW_SQRT(AW_FMA(z, z, AW_FMA(y, y, x * x)));
  real cz = z / norm;            /* cos(theta) */
  real za = AW_FABS(cz);
  real phi = aw_atan2(y, x);
  real tt = phi * inv_halfpi;    /* in [-2, 2] */
  if (tt < AW_R(0.0)) tt += AW_R(4.0);
  if (tt >= AW_R(4.0)) tt -= AW_R(4.0);
  const real n = (real)nside;
  if (za <= AW_R(2.0) / AW_R(3.0)) {
    /* equatorial belt */
    aw_i64 nl4 = 4 * nside;
    real t1 = n * (AW_R(0.5) + tt);
    real t2 = n * (cz * AW_R(0.75));
    aw_i64 jp = (aw_i64)(t1 - t2); /* ascending edge line */
    aw_i64 jm = (aw_i64)(t1 + t2); /* descending edge line */
    aw_i64 ir = nside + 1 + jp - jm; /* ring from z = 2/3, in 1 .. 2 nside + 1 */
    aw_i64 kshift = 1 - (ir & 1);
    aw_i64 ip = ((jp + jm - nside + kshift + 1 + 2 * nl4) / 2) % nl4;
    return 2 * nside * (nside - 1) + (ir - 1) * nl4 + ip;
  }
  /* polar caps: sqrt(3 (1 - za)) written with sin(theta) for accuracy */
  real tp = tt - (real)((aw_i64)tt);
  real sth = rxy / norm;
  real tmp = n * (sth / AW_SQRT((AW_R(1.0) + za) / AW_R(3.0)));
  aw_i64 jp = (aw_i64)(tp * tmp);
  aw_i64 jm = (aw_i64)((AW_R(1.0) - tp) * tmp);
  aw_i64 ir = jp + jm + 1;           /* ring from the nearest pole */
  aw_i64 ip = (aw_i64)(tt * (real)ir); /* in 0 .. 4 ir - 1 */
  if (ip >= 4 * ir) ip = 4 * ir - 1;
  return (cz > AW_R(0.0)) ? 2 * ir * (ir - 1) + ip : 12 * nside * nside - 2 * ir * (ir + 1) + ip;
}

#endif /* AW_HEALPIX_H */
