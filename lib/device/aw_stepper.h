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

/* Advance by nsteps steps. On entry and on exit, (u, p) are synchronised and
 * f is the force at u. */
AW_FN void aw_segment(aw_lstate* s, aw_i64 nsteps, AW_CONSTANT aw_rparams* rp, int stages, int kick_first) {
  if (kick_first) {
    aw_kick(s, rp->kick[0]);
    for (aw_i64 n = 0; n < nsteps; ++n) {
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
