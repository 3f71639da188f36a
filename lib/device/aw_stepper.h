/* arnoldweb portable device core: the generic symplectic composition stepper.
 *
 * One stepper for every method: a method is a table of drift coefficients
 * a_i and kick coefficients b_i (rp->drift[i] = a_i h / 2pi in turns per unit
 * of dT/dP, rp->kick[i] = b_i h), `stages` force evaluations a step.
 *
 * kick-first methods (KDK, b_0 != 0):   K b0  D a0  K b1 ... D a_{s-1}  K b_s
 *   Back-to-back steps merge K b_s with the next K b0 into one kick
 *   (rp->kick_merged = (b_s + b_0) h), so a step costs s evaluations, and the
 *   force at the end of a segment is cached in the state.
 * drift-first methods (DKD):            D a0  K b1  D a1 ... K b_s  D a_s
 * force-gradient methods (kick-first, cfg.gradient): kick i also adds
 *   g_i h^3 grad(sum_k a_k F_k^2)   (rp->gradient[i] = g_i h^3, a_k = d^2T/dP_k^2),
 *   the flow of the modified potential b_i V - g_i h^2 |grad V|^2_T, from the
 *   force's own sin/cos (aw_model_force_hessian); merged across steps as b is.
 *
 * The drift is the model's (u += d dT/dP); after the last drift of every step
 * the angles are wrapped back to [-1/2, 1/2] turns and the integer winding
 * counts take the whole turns: exact, so averaged velocities are exact over
 * any run length.
 */
#ifndef AW_STEPPER_H
#define AW_STEPPER_H

#include "aw_model.h"

AW_FN void aw_kick(aw_lstate* s, real k) {
  lreal kk = AW_LSPLAT(k);
  s->px = AW_FMA(kk, s->fx, s->px);
  s->py = AW_FMA(kk, s->fy, s->py);
  s->pz = AW_FMA(kk, s->fz, s->pz);
}

/* Whole turns move from u into the winding counts; u - rint(u) is exact. The
 * integer turns are read from the bits of the rounding sum (no conversion). */
AW_FN void aw_wrap(aw_lstate* s) {
  lreal tx = s->ux + AW_ROUND_MAGIC;
  lreal ty = s->uy + AW_ROUND_MAGIC;
  lreal tz = s->uz + AW_ROUND_MAGIC;
  s->ux = s->ux - (tx - AW_ROUND_MAGIC);
  s->uy = s->uy - (ty - AW_ROUND_MAGIC);
  s->uz = s->uz - (tz - AW_ROUND_MAGIC);
  s->wx += AW_MAGIC_TO_INT(tx);
  s->wy += AW_MAGIC_TO_INT(ty);
  s->wz += AW_MAGIC_TO_INT(tz);
}

/* F at s->u into s->f, and g = grad(sum_k a_k F_k^2) = -2 Hess(V) A F there
 * (radians), from the same sin/cos. */
AW_FN void aw_force_gradient(aw_lstate* s, AW_CONSTANT aw_rparams* rp, lreal* g) {
  lreal hess[6]; /* xx yy zz xy xz yz */
  real a[3];
  aw_model_force_hessian(s, rp, hess);
  aw_model_kinetic_diag(rp, a);
  lreal ax = a[0] * s->fx, ay = a[1] * s->fy, az = a[2] * s->fz;
  g[0] = AW_R(-2.0) * AW_FMA(hess[4], az, AW_FMA(hess[3], ay, hess[0] * ax));
  g[1] = AW_R(-2.0) * AW_FMA(hess[5], az, AW_FMA(hess[1], ay, hess[3] * ax));
  g[2] = AW_R(-2.0) * AW_FMA(hess[2], az, AW_FMA(hess[5], ay, hess[4] * ax));
}

/* P += k F + c g (F = s->f, g from aw_force_gradient at the same point). */
AW_FN void aw_gradient_kick(aw_lstate* s, real k, real c, const lreal* g) {
  lreal kk = AW_LSPLAT(k), cc = AW_LSPLAT(c);
  s->px = AW_FMA(cc, g[0], AW_FMA(kk, s->fx, s->px));
  s->py = AW_FMA(cc, g[1], AW_FMA(kk, s->fy, s->py));
  s->pz = AW_FMA(cc, g[2], AW_FMA(kk, s->fz, s->pz));
}

/* The kick of a force-gradient method at s->u: P += k F + c g. A kick without
 * a gradient term (c = 0: most kicks of SBAB_nC, SABA_nC and Chin 4A) forms no
 * Hessian: P += k F, the value P + k F + 0 g has (F is written by one
 * function of the model for both). The branch is the same for every
 * trajectory. */
AW_FN void aw_force_gradient_kick(aw_lstate* s, AW_CONSTANT aw_rparams* rp, real k, real c) {
  if (c != AW_R(0.0)) {
    lreal g[3];
    aw_force_gradient(s, rp, g);
    aw_gradient_kick(s, k, c, g);
  } else {
    aw_force(s, rp);
    aw_kick(s, k);
  }
}

/* The kick-first stepper of force-gradient methods. The force (and gradient)
 * at the start of a segment is computed again (the state caches F only; F's
 * bits are the same). */
AW_FN void aw_segment_gradient(aw_lstate* s, aw_i64 nsteps, AW_CONSTANT aw_rparams* rp, int stages) {
  aw_force_gradient_kick(s, rp, rp->kick[0], rp->gradient[0]);
  for (aw_i64 n = 0; n < nsteps; ++n) {
    AW_UNROLL_STAGES
    for (int i = 0; i < stages - 1; ++i) {
      aw_model_drift(s, rp->drift[i], rp);
      aw_force_gradient_kick(s, rp, rp->kick[i + 1], rp->gradient[i + 1]);
    }
    aw_model_drift(s, rp->drift[stages - 1], rp);
    aw_wrap(s);
    if (n + 1 < nsteps)
      aw_force_gradient_kick(s, rp, rp->kick_merged, rp->gradient_merged);
    else
      aw_force_gradient_kick(s, rp, rp->kick[stages], rp->gradient[stages]);
  }
}

/* Advance by nsteps steps. On entry and on exit, (u, p) are synchronised and
 * f is the force at u. */
AW_FN void aw_segment(aw_lstate* s, aw_i64 nsteps, AW_CONSTANT aw_rparams* rp, int stages, int kick_first,
                      int gradient) {
  if (gradient) {
    aw_segment_gradient(s, nsteps, rp, stages);
  } else if (kick_first) {
    aw_kick(s, rp->kick[0]);
    for (aw_i64 n = 0; n < nsteps; ++n) {
      AW_UNROLL_STAGES
      for (int i = 0; i < stages - 1; ++i) {
        aw_model_drift(s, rp->drift[i], rp);
        aw_force(s, rp);
        aw_kick(s, rp->kick[i + 1]);
      }
      aw_model_drift(s, rp->drift[stages - 1], rp);
      aw_wrap(s);
      aw_force(s, rp);
      aw_kick(s, (n + 1 < nsteps) ? rp->kick_merged : rp->kick[stages]);
    }
  } else {
    for (aw_i64 n = 0; n < nsteps; ++n) {
      AW_UNROLL_STAGES
      for (int i = 0; i < stages; ++i) {
        aw_model_drift(s, rp->drift[i], rp);
        aw_force(s, rp);
        aw_kick(s, rp->kick[i + 1]);
      }
      aw_model_drift(s, rp->drift[stages], rp);
      aw_wrap(s);
    }
    aw_force(s, rp);
  }
}

#endif /* AW_STEPPER_H */
