/* arnoldweb portable device core: tangent dynamics, for the chaos indicators.
 *
 * A tangent vector w = (dX, dP) is carried through the derivative of the
 * very step the trajectory takes (aw_stepper.h), so the indicators are exact
 * for the discrete map (docs/indicators.md):
 *   kick  P += k F(X):      dP -= k Hess V(X) dX
 *   drift X += 2pi d dT/dP: dX += 2pi d A dP,  A = diag(a), aw_model_kinetic_diag
 * Units: dX is in radians (the Hamiltonian's own coordinates; the state's u is
 * in turns and 2pi d = a_i h is the drift in radians), the Hessian of V is in
 * radians (aw_model_force_hessian, from the same sin/cos as the force), dP in
 * momentum units; |w|^2 = |dX|^2 + |dP|^2.
 *
 * The state's operations are exactly aw_segment's, in the same order, and the
 * force from aw_model_force_hessian has the force's bits: a trajectory has the
 * same bits with and without indicators. Back-to-back kicks are merged for w
 * as for P (the Hessian does not change across a kick); the observers see the
 * synchronised w (dP with the step's last kick only) after every step.
 *
 * Observers, each compiled in only when asked (AW_F_FLI, AW_F_MEGNO):
 *   n2 = |w|^2 after every step. Renormalisation: where n2 > 2^64, w is
 *     multiplied by 2^-32 (exact) and 32 is added to log2w (exact), so w never
 *     overflows, in float or double, over any run length; log|w| = log2w ln 2 +
 *     log|w_stored| is what the indicators use.
 *   FLI: the largest n2 since the start, in the current scale.
 *   MEGNO (Cincotta & Simo 2000, in the discrete form of a map): after step
 *     k (t_k = k h), rho_k = log(|w_k| / |w_{k-1}|), the exact growth over
 *     the step from the ratio of the synchronised norms (issue 26: the rate
 *     h (w . w') / |w|^2 of the flow at the step's end was low by O(h));
 *     S_k = sum_j j rho_j, Y_k = 2 S_k / k, and the mean <Y>_k = (1/k) sum Y_j.
 *     The slope of Y_j against j (running mean and covariance, Welford) gives
 *     the Lyapunov exponent lambda = slope / h (Y ~ lambda t on chaotic orbits,
 *     so <Y> ~ lambda t / 2).
 */
#ifndef AW_TANGENT_H
#define AW_TANGENT_H

#include "aw_stepper.h"
#include "effects/aw_fx_common.h"

#define AW_TWO_PI_R AW_R(6.283185307179586)
#define AW_RENORM_ABOVE AW_R(18446744073709551616.0) /* 2^64 */
#define AW_RENORM_BY AW_R(2.3283064365386963e-10)    /* 2^-32 */

typedef struct {
  lreal qx, qy, qz;  /* dX, radians */
  lreal px, py, pz;  /* dP */
  lreal hess[6];     /* Hessian of V at the state's position: xx yy zz xy xz yz */
  lreal log2w;       /* whole powers of two taken out of w by renormalisation */
  lreal max_n2;      /* FLI: the largest |w|^2 so far, in the current scale */
  lreal prev_n2;     /* MEGNO: |w|^2 after the previous step, in the current scale */
  lreal s1, ysum;    /* MEGNO: sum_j j rho_j, sum_j Y_j */
  lreal mean_y, cov; /* MEGNO: running mean of Y_j and sum of (j - mean j)(Y_j - mean Y) */
  aw_i64 steps;      /* steps taken (the same in every lane) */
} aw_tangent;

/* w at the start: the scene's unit vector (rp->tangent_w0); the Hessian at the
 * state's position comes with the first force evaluation (aw_tangent_force). */
AW_FN void aw_tangent_begin(aw_tangent* t, AW_CONSTANT aw_rparams* rp) {
  t->qx = AW_LSPLAT(rp->tangent_w0[0]);
  t->qy = AW_LSPLAT(rp->tangent_w0[1]);
  t->qz = AW_LSPLAT(rp->tangent_w0[2]);
  t->px = AW_LSPLAT(rp->tangent_w0[3]);
  t->py = AW_LSPLAT(rp->tangent_w0[4]);
  t->pz = AW_LSPLAT(rp->tangent_w0[5]);
  for (int i = 0; i < 6; ++i) t->hess[i] = AW_LSPLAT(AW_R(0.0));
  t->log2w = AW_LSPLAT(AW_R(0.0));
  t->max_n2 = AW_FMA(t->pz, t->pz, AW_FMA(t->py, t->py, AW_FMA(t->px, t->px,
                     AW_FMA(t->qz, t->qz, AW_FMA(t->qy, t->qy, t->qx * t->qx)))));
  t->prev_n2 = t->max_n2;
  t->s1 = AW_LSPLAT(AW_R(0.0));
  t->ysum = AW_LSPLAT(AW_R(0.0));
  t->mean_y = AW_LSPLAT(AW_R(0.0));
  t->cov = AW_LSPLAT(AW_R(0.0));
  t->steps = 0;
}

/* The force into the state and the Hessian into t, from the same sin/cos. */
AW_FN void aw_tangent_force(aw_lstate* s, aw_tangent* t, AW_CONSTANT aw_rparams* rp) {
  aw_model_force_hessian(s, rp, t->hess);
}

/* g = Hess V . dX */
AW_FN void aw_tangent_hdx(const aw_tangent* t, lreal* gx, lreal* gy, lreal* gz) {
  *gx = AW_FMA(t->hess[4], t->qz, AW_FMA(t->hess[3], t->qy, t->hess[0] * t->qx));
  *gy = AW_FMA(t->hess[5], t->qz, AW_FMA(t->hess[1], t->qy, t->hess[3] * t->qx));
  *gz = AW_FMA(t->hess[2], t->qz, AW_FMA(t->hess[5], t->qy, t->hess[4] * t->qx));
}

AW_FN void aw_tangent_kick(aw_tangent* t, real k) {
  lreal gx, gy, gz;
  aw_tangent_hdx(t, &gx, &gy, &gz);
  lreal mk = AW_LSPLAT(-k);
  t->px = AW_FMA(mk, gx, t->px);
  t->py = AW_FMA(mk, gy, t->py);
  t->pz = AW_FMA(mk, gz, t->pz);
}

/* d: the state's drift coefficient (turns per unit of dT/dP). */
AW_FN void aw_tangent_drift(aw_tangent* t, real d, AW_CONSTANT aw_rparams* rp) {
  real a[3];
  aw_model_kinetic_diag(rp, a);
  const real dr = AW_TWO_PI_R * d; /* radians per unit of dT/dP */
  t->qx = AW_FMA(AW_LSPLAT(dr * a[0]), t->px, t->qx);
  t->qy = AW_FMA(AW_LSPLAT(dr * a[1]), t->py, t->qy);
  t->qz = AW_FMA(AW_LSPLAT(dr * a[2]), t->pz, t->qz);
}

/* After a step, with (dX, sx, sy, sz) the synchronised w: the observers, then
 * renormalisation of the stored w (whose dP may hold a merged kick already). */
AW_FN void aw_tangent_observe(aw_config cfg, aw_tangent* t, lreal sx, lreal sy, lreal sz) {
  t->steps += 1;
  lreal n2 = AW_FMA(sz, sz, AW_FMA(sy, sy, AW_FMA(sx, sx, AW_FMA(t->qz, t->qz, AW_FMA(t->qy, t->qy, t->qx * t->qx)))));
  if (AW_HAS(AW_F_FLI)) t->max_n2 = AW_SELECT(t->max_n2, n2, n2 > t->max_n2);
  if (AW_HAS(AW_F_MEGNO)) {
    const real k = (real)t->steps;
    /* log(|w_k| / |w_{k-1}|): both norms in the current scale */
    lreal rho = AW_R(0.5) * aw_log_lanes(n2 / t->prev_n2);
    t->s1 = AW_FMA(AW_LSPLAT(k), rho, t->s1);
    lreal y = (AW_R(2.0) * t->s1) / k;
    t->ysum = t->ysum + y;
    /* Welford: mean of j is (k + 1) / 2 after k steps */
    const real mean_j_before = AW_R(0.5) * k; /* (k - 1 + 1) / 2 */
    lreal dy = y - t->mean_y;
    t->cov = AW_FMA(AW_LSPLAT(((k - AW_R(1.0)) / k) * (k - mean_j_before)), dy, t->cov);
    t->mean_y = AW_FMA(AW_LSPLAT(AW_R(1.0) / k), dy, t->mean_y);
  }
  lreal scale = AW_SELECT(AW_LSPLAT(AW_R(1.0)), AW_LSPLAT(AW_RENORM_BY), n2 > AW_RENORM_ABOVE);
  t->qx = t->qx * scale;
  t->qy = t->qy * scale;
  t->qz = t->qz * scale;
  t->px = t->px * scale;
  t->py = t->py * scale;
  t->pz = t->pz * scale;
  t->max_n2 = t->max_n2 * (scale * scale);
  t->prev_n2 = n2 * (scale * scale);
  t->log2w = t->log2w + AW_SELECT(AW_LSPLAT(AW_R(0.0)), AW_LSPLAT(AW_R(32.0)), n2 > AW_RENORM_ABOVE);
}

/* The step's last kick k_last for the state (k_last may be the merged kick),
 * with the observers seeing w synchronised by k_sync (the step's own last
 * kick). */
AW_FN void aw_tangent_last_kick(aw_config cfg, aw_tangent* t, real k_sync, real k_last) {
  lreal gx, gy, gz;
  aw_tangent_hdx(t, &gx, &gy, &gz);
  lreal ms = AW_LSPLAT(-k_sync);
  lreal sx = AW_FMA(ms, gx, t->px), sy = AW_FMA(ms, gy, t->py), sz = AW_FMA(ms, gz, t->pz);
  lreal ml = AW_LSPLAT(-k_last);
  t->px = AW_FMA(ml, gx, t->px);
  t->py = AW_FMA(ml, gy, t->py);
  t->pz = AW_FMA(ml, gz, t->pz);
  aw_tangent_observe(cfg, t, sx, sy, sz);
}

/* aw_segment with the tangent vector: the same state operations in the same
 * order. */
AW_FN void aw_segment_tangent(aw_config cfg, aw_lstate* s, aw_tangent* t, aw_i64 nsteps, AW_CONSTANT aw_rparams* rp) {
  const int stages = cfg.stages;
  if (cfg.kick_first) {
    aw_kick(s, rp->kick[0]);
    aw_tangent_kick(t, rp->kick[0]);
    for (aw_i64 n = 0; n < nsteps; ++n) {
      for (int i = 0; i < stages - 1; ++i) {
        aw_model_drift(s, rp->drift[i], rp);
        aw_tangent_drift(t, rp->drift[i], rp);
        aw_tangent_force(s, t, rp);
        aw_kick(s, rp->kick[i + 1]);
        aw_tangent_kick(t, rp->kick[i + 1]);
      }
      aw_model_drift(s, rp->drift[stages - 1], rp);
      aw_tangent_drift(t, rp->drift[stages - 1], rp);
      aw_wrap(s);
      aw_tangent_force(s, t, rp);
      const real k_last = (n + 1 < nsteps) ? rp->kick_merged : rp->kick[stages];
      aw_kick(s, k_last);
      aw_tangent_last_kick(cfg, t, rp->kick[stages], k_last);
    }
  } else {
    for (aw_i64 n = 0; n < nsteps; ++n) {
      for (int i = 0; i < stages; ++i) {
        aw_model_drift(s, rp->drift[i], rp);
        aw_tangent_drift(t, rp->drift[i], rp);
        aw_tangent_force(s, t, rp);
        aw_kick(s, rp->kick[i + 1]);
        aw_tangent_kick(t, rp->kick[i + 1]);
      }
      aw_model_drift(s, rp->drift[stages], rp);
      aw_tangent_drift(t, rp->drift[stages], rp);
      aw_wrap(s);
      aw_tangent_observe(cfg, t, t->px, t->py, t->pz);
    }
    aw_tangent_force(s, t, rp);
  }
}

#endif /* AW_TANGENT_H */
