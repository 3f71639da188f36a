/* arnoldweb portable device core: initial conditions on the energy shell.
 *
 * X is uniform on the accessible part of the torus (V(X) < E). Positions
 * where the state cannot have energy E are rejected; each trajectory tries at
 * most ip->max_attempts times (the host refuses energies whose accessible
 * fraction makes failure likely) and reports failure through the returned
 * lane mask. The momentum, by kind (AW_INITIAL_*):
 *   shell:    direction uniform on the sphere, |P| = sqrt(2 (E - V(X)))
 *   cap:      direction uniform in a spherical cap, |P| as above
 *   box:      direction uniform in a longitude/latitude box, |P| as above
 *   grid:     point i of a grid of initial conditions (aw_grid.h), no draws
 *   gaussian: p_x, p_y normal (Box-Muller), drawn once per trajectory; X is drawn
 *             until p_z^2 = 2 (E - V(X)) - p_x^2 - p_y^2 > 0, p_z with a random
 *             sign. So p_x, p_y are exactly Gaussian and X is uniform on the
 *             part of the torus that this momentum can reach.
 *
 * Random draws (Philox counter = (index, attempt, draw)):
 *   draw 0: u_x, u_y   draw 1: u_z, a   draw 2: b, c   (every attempt)
 *   a, b: the direction; gaussian: (index, 0, 3): the two normals' uniforms,
 *   (index, 0, 4): the sign of p_z.
 */
#ifndef AW_INITIAL_H
#define AW_INITIAL_H

#include "aw_grid.h"
#include "aw_model.h"
#include "aw_rng.h"

/* Fills s (force not yet computed) for the lanes first .. first+AW_LANES-1;
 * returns 1 in every lane that found a state, 0 elsewhere. */
AW_FN lreal aw_initial_state(aw_lstate* s, int kind, aw_u64 first, AW_CONSTANT aw_rparams* rp,
                             AW_CONSTANT aw_iparams* ip) {
  if (kind == AW_INITIAL_GRID) return aw_grid_state(s, first, rp, ip);
  const aw_u64 seed = (aw_u64)ip->seed;
  const int max_attempts = (int)ip->max_attempts;
  const real energy = rp->energy;
  real r0[AW_LANES], r1[AW_LANES], r2[AW_LANES], r3[AW_LANES], r4[AW_LANES], r5[AW_LANES];
  lreal accepted = AW_LSPLAT(AW_R(0.0));
  lreal gx = AW_LSPLAT(AW_R(0.0)), gy = AW_LSPLAT(AW_R(0.0)), gsign = AW_LSPLAT(AW_R(1.0));
  if (kind == AW_INITIAL_GAUSSIAN) {
    /* the momentum's Gaussian part, once per trajectory (Box-Muller) */
    for (int j = 0; j < AW_LANES; ++j) {
      aw_uniform2(seed, first + (aw_u64)j, 0u, 3u, &r0[j], &r1[j]);
      aw_uniform2(seed, first + (aw_u64)j, 0u, 4u, &r2[j], &r3[j]);
      r0[j] = AW_SQRT(AW_R(-2.0) * aw_log(AW_R(1.0) - r0[j])); /* 1 - U in (0, 1] */
    }
    lreal radius = AW_LOAD_LANES(r0), sb, cb;
    aw_sincos2pi(AW_LOAD_LANES(r1), &sb, &cb);
    gx = AW_FMA(AW_LSPLAT(rp->gaussian.sigma_x) * radius, cb, AW_LSPLAT(rp->gaussian.mean_x));
    gy = AW_FMA(AW_LSPLAT(rp->gaussian.sigma_y) * radius, sb, AW_LSPLAT(rp->gaussian.mean_y));
    gsign = AW_SELECT(AW_LSPLAT(AW_R(1.0)), AW_LSPLAT(AW_R(-1.0)), AW_LOAD_LANES(r2) < AW_R(0.5));
  }
  s->ux = s->uy = s->uz = AW_LSPLAT(AW_R(0.0));
  s->px = s->py = s->pz = AW_LSPLAT(AW_R(0.0));
  s->wx = s->wy = s->wz = AW_ISPLAT(0);
  for (int attempt = 0; attempt < max_attempts; ++attempt) {
    for (int j = 0; j < AW_LANES; ++j) {
      aw_u64 index = first + (aw_u64)j;
      aw_uniform2(seed, index, (aw_u32)attempt, 0u, &r0[j], &r1[j]);
      aw_uniform2(seed, index, (aw_u32)attempt, 1u, &r2[j], &r3[j]);
      aw_uniform2(seed, index, (aw_u32)attempt, 2u, &r4[j], &r5[j]);
    }
    lreal ux = AW_LOAD_LANES(r0) - AW_R(0.5);
    lreal uy = AW_LOAD_LANES(r1) - AW_R(0.5);
    lreal uz = AW_LOAD_LANES(r2) - AW_R(0.5);
    lreal ke = energy - aw_model_potential(ux, uy, uz, rp); /* kinetic energy left */
    lreal a = AW_LOAD_LANES(r3), b = AW_LOAD_LANES(r4);
    lreal px, py, pz, ok;
    if (kind == AW_INITIAL_GAUSSIAN) {
      px = gx;
      py = gy;
      lreal pz2 = AW_R(2.0) * ke - AW_FMA(py, py, px * px);
      pz = gsign * AW_SQRT(AW_SELECT(AW_LSPLAT(AW_R(0.0)), pz2, pz2 > AW_R(0.0)));
      ok = AW_SELECT(AW_LSPLAT(AW_R(0.0)), AW_LSPLAT(AW_R(1.0)), pz2 > AW_R(0.0));
    } else {
      /* a unit direction (dx, dy, dz) */
      lreal dx, dy, dz;
      if (kind == AW_INITIAL_BOX) {
        lreal sl = AW_FMA(a, AW_LSPLAT(rp->box.sin_lat_width), AW_LSPLAT(rp->box.sin_lat0)); /* sin(latitude) */
        lreal cl = AW_SQRT((AW_R(1.0) - sl) * (AW_R(1.0) + sl));
        lreal slon, clon;
        aw_sincos2pi(AW_FMA(b, AW_LSPLAT(rp->box.lon_width), AW_LSPLAT(rp->box.lon0)), &slon, &clon);
        dx = cl * clon;
        dy = cl * slon;
        dz = sl;
      } else {
        /* shell: the whole sphere; cap: cos(theta) in [cos(radius), 1] about c */
        lreal ct = (kind == AW_INITIAL_CAP) ? AW_R(1.0) - a * (AW_R(1.0) - rp->cap.cos_radius)
                                            : AW_R(2.0) * a - AW_R(1.0);
        lreal st = AW_SQRT((AW_R(1.0) - ct) * (AW_R(1.0) + ct));
        lreal sphi, cphi;
        aw_sincos2pi(b, &sphi, &cphi);
        if (kind == AW_INITIAL_CAP) {
          lreal t1 = st * cphi, t2 = st * sphi;
          AW_CONSTANT aw_cap* q = &rp->cap;
          dx = AW_FMA(ct, AW_LSPLAT(q->c[0]), AW_FMA(t1, AW_LSPLAT(q->e1[0]), t2 * q->e2[0]));
          dy = AW_FMA(ct, AW_LSPLAT(q->c[1]), AW_FMA(t1, AW_LSPLAT(q->e1[1]), t2 * q->e2[1]));
          dz = AW_FMA(ct, AW_LSPLAT(q->c[2]), AW_FMA(t1, AW_LSPLAT(q->e1[2]), t2 * q->e2[2]));
        } else {
          dx = st * cphi;
          dy = st * sphi;
          dz = ct;
        }
      }
      lreal pm = aw_model_speed(ke, dx, dy, dz, rp, &ok);
      px = pm * dx;
      py = pm * dy;
      pz = pm * dz;
    }
    /* take the candidate where it is valid and nothing was taken yet */
#define AW_TAKE_ (ok != AW_R(0.0)) & (accepted == AW_R(0.0))
    s->ux = AW_SELECT(s->ux, ux, AW_TAKE_);
    s->uy = AW_SELECT(s->uy, uy, AW_TAKE_);
    s->uz = AW_SELECT(s->uz, uz, AW_TAKE_);
    s->px = AW_SELECT(s->px, px, AW_TAKE_);
    s->py = AW_SELECT(s->py, py, AW_TAKE_);
    s->pz = AW_SELECT(s->pz, pz, AW_TAKE_);
    accepted = AW_SELECT(accepted, AW_LSPLAT(AW_R(1.0)), AW_TAKE_);
#undef AW_TAKE_
    if (AW_ALL(accepted != AW_R(0.0))) break;
  }
  return accepted;
}

#endif /* AW_INITIAL_H */
