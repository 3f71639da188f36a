/* arnoldweb portable device core: grids of initial conditions
 * (ensemble.initial = "grid"). Trajectory i is point i of the grid; every
 * point has the same position X0 (rp->grid_position, turns). By kind
 * (ip->grid_kind, AW_GRID_*):
 *   healpix: the momentum direction is the centre of HEALPix pixel i (RING
 *            order, nside = ip->grid_n[0]), |P| from the energy at X0;
 *   lonlat:  the direction is the centre of cell (i mod n_lon, i div n_lon)
 *            of an n_lon x n_lat grid over a longitude/latitude box (uniform
 *            in longitude and latitude), |P| from the energy at X0;
 *   plane:   momentum grid_axes[0] and grid_axes[1] at the centre of cell
 *            (i mod n1, i div n1) of an n1 x n2 grid over their ranges, the
 *            momentum grid_axes[2] fixed (rp->grid_fixed).
 * Cell centres: lo + (j + 1/2) width / n. Integer work and + - * / sqrt and
 * the portable sin/cos only: the same initial states on every backend.
 */
#ifndef AW_GRID_H
#define AW_GRID_H

#include "aw_model.h"

/* Integer square root: the largest r with r^2 <= v. */
AW_FN aw_i64 aw_isqrt(aw_i64 v) {
  aw_i64 r = (aw_i64)AW_SQRT((real)v);
  while (r > 0 && r * r > v) --r;
  while ((r + 1) * (r + 1) <= v) ++r;
  return r;
}

/* The centre of HEALPix pixel p (RING order): z = cos(theta) and the azimuth
 * in turns (Gorski et al. 2005, pix2ang_ring). */
AW_FN void aw_pix2zphi_ring(aw_i64 nside, aw_i64 p, real* z, real* phi_turns) {
  const aw_i64 npix = 12 * nside * nside;
  const aw_i64 ncap = 2 * nside * (nside - 1);
  const real n3 = AW_R(3.0) * (real)nside * (real)nside;
  if (p < ncap) { /* north polar cap */
    const aw_i64 ring = (1 + aw_isqrt(1 + 2 * p)) / 2;
    const aw_i64 iphi = p + 1 - 2 * ring * (ring - 1);
    *z = AW_R(1.0) - (real)(ring * ring) / n3;
    *phi_turns = ((real)iphi - AW_R(0.5)) / (real)(4 * ring);
  } else if (p < npix - ncap) { /* equatorial belt */
    const aw_i64 q = p - ncap;
    aw_i64 col;
    const aw_i64 ring = aw_divrem(q, 4 * nside, &col) + nside;
    const aw_i64 iphi = col + 1;
    const real shift = ((ring + nside) & 1) ? AW_R(1.0) : AW_R(0.5);
    *z = (real)(2 * (2 * nside - ring)) / (AW_R(3.0) * (real)nside);
    *phi_turns = ((real)iphi - shift) / (real)(4 * nside);
  } else { /* south polar cap */
    const aw_i64 q = npix - p;
    const aw_i64 ring = (1 + aw_isqrt(2 * q - 1)) / 2;
    const aw_i64 iphi = 4 * ring + 1 - (q - 2 * ring * (ring - 1));
    *z = (real)(ring * ring) / n3 - AW_R(1.0);
    *phi_turns = ((real)iphi - AW_R(0.5)) / (real)(4 * ring);
  }
}

/* Fills s (force not yet computed) with grid points first .. first +
 * AW_LANES - 1; returns 1 in every lane whose point has a state (healpix,
 * lonlat: E > V(X0)), 0 elsewhere. */
AW_FN lreal aw_grid_state(aw_lstate* s, aw_u64 first, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip) {
  const int kind = (int)ip->grid_kind;
  const aw_i64 n0 = ip->grid_n[0], n1 = ip->grid_n[1];
  real a[AW_LANES], b[AW_LANES];
  for (int j = 0; j < AW_LANES; ++j) {
    const aw_i64 i = (aw_i64)(first + (aw_u64)j);
    if (kind == AW_GRID_HEALPIX) {
      const aw_i64 npix = 12 * n0 * n0;
      aw_pix2zphi_ring(n0, i < npix ? i : npix - 1, &a[j], &b[j]); /* a = z, b = azimuth */
    } else {
      aw_i64 col;
      const aw_i64 r = aw_divrem(i, n0, &col), row = r < n1 ? r : n1 - 1;
      a[j] = AW_FMA(((real)col + AW_R(0.5)) / (real)n0, rp->grid_width[0], rp->grid_lo[0]);
      b[j] = AW_FMA(((real)row + AW_R(0.5)) / (real)n1, rp->grid_width[1], rp->grid_lo[1]);
    }
  }
  s->ux = AW_LSPLAT(rp->grid_position[0]);
  s->uy = AW_LSPLAT(rp->grid_position[1]);
  s->uz = AW_LSPLAT(rp->grid_position[2]);
  s->wx = s->wy = s->wz = AW_ISPLAT(0);
  if (kind == AW_GRID_PLANE) {
    lreal m[3];
    m[0] = m[1] = m[2] = AW_LSPLAT(rp->grid_fixed);
    m[ip->grid_axes[0]] = AW_LOAD_LANES(a);
    m[ip->grid_axes[1]] = AW_LOAD_LANES(b);
    s->px = m[0];
    s->py = m[1];
    s->pz = m[2];
    return AW_LSPLAT(AW_R(1.0));
  }
  lreal dx, dy, dz;
  if (kind == AW_GRID_HEALPIX) {
    lreal z = AW_LOAD_LANES(a), sp, cp;
    lreal st = AW_SQRT((AW_R(1.0) - z) * (AW_R(1.0) + z));
    aw_sincos2pi(AW_LOAD_LANES(b), &sp, &cp);
    dx = st * cp;
    dy = st * sp;
    dz = z;
  } else { /* lonlat: a = longitude, b = latitude, turns */
    lreal slon, clon, slat, clat;
    aw_sincos2pi(AW_LOAD_LANES(a), &slon, &clon);
    aw_sincos2pi(AW_LOAD_LANES(b), &slat, &clat);
    dx = clat * clon;
    dy = clat * slon;
    dz = slat;
  }
  lreal ke = AW_LSPLAT(rp->energy) - aw_model_potential(s->ux, s->uy, s->uz, rp);
  lreal ok;
  lreal pm = aw_model_speed(ke, dx, dy, dz, rp, &ok);
  s->px = pm * dx;
  s->py = pm * dy;
  s->pz = pm * dz;
  return ok;
}

#endif /* AW_GRID_H */
