/* arnoldweb effects "fli", "megno", "lyapunov": chaos indicators from the
 * tangent vector (aw_tangent.h), which the trajectory's life integrates in
 * place of the plain step when any of them is asked for (AW_F_TANGENT).
 * After the run, every trajectory's record (AW_IND_REALS reals, aw_params.h):
 *   FLI       max_t log|w(t)|            (|w(0)| = 1, so FLI >= 0)
 *   MEGNO     <Y>(t) = (1/k) sum_j Y_j   (-> 2 on regular orbits)
 *   lambda_Y  slope of Y_j against t_j (Y ~ lambda t, <Y> ~ lambda t / 2), 1/T
 *   lambda    log|w(t)| / t, 1/T
 * t = k h in T. Indicators not asked for, and flagged trajectories, are NaN.
 * Logarithms are taken here only (once per trajectory, scalar, per lane). */
/* What the host reads too (plain macros, gathered by the generated
 * effects/aw_effect_declarations.h that aw_params.h includes). */
#ifndef AW_FX_INDICATORS_DECLARATIONS
#define AW_FX_INDICATORS_DECLARATIONS
/* the tangent vector through the derivative of the same step, and its
 * observers, each only when asked (docs/indicators.md) */
#define AW_F_TANGENT 0x400u   /* tangent dynamics (any indicator sets it) */
#define AW_F_FLI 0x800u       /* fast Lyapunov indicator: max_t log |w| */
#define AW_F_MEGNO 0x1000u    /* mean MEGNO <Y> and the Lyapunov exponent from its slope */
#define AW_F_LYAPUNOV 0x2000u /* finite-time maximal Lyapunov exponent log |w(t)| / t */
#define AW_OUT_INDICATORS 2   /* AW_IND_REALS reals */
/* The chaos indicators of a trajectory (NaN for a flagged one): FLI, mean
 * MEGNO <Y>, the Lyapunov exponent from MEGNO's slope (1/T), the finite-time
 * Lyapunov exponent (1/T). */
#define AW_IND_REALS 4
#define AW_IND_FLI 0
#define AW_IND_MEGNO 1
#define AW_IND_MEGNO_LYAPUNOV 2
#define AW_IND_LYAPUNOV 3
#define AW_FX_INDICATORS_RPARAMS                                          \
  real tangent_w0[6]; /* initial tangent vector (dX in radians, dP), unit norm */ \
  real tangent_step;  /* h in T: indicator times and exponents are in T */
#endif

#if !defined(AW_EFFECT_DECLARATIONS_ONLY) && !defined(AW_FX_INDICATORS_H)
#define AW_FX_INDICATORS_H

#include "aw_tangent.h"

AW_EFFECT_ORDER(50)

/* log x for x > 0 finite, NaN otherwise. */
AW_FN real aw_log_or_nan(real x) { return (x > AW_R(0.0) && x - x == AW_R(0.0)) ? aw_log(x) : aw_nan_real(); }

/* Lane j's indicators into out[0 .. AW_IND_REALS - 1]. */
AW_FN void aw_store_indicators(aw_config cfg, AW_GLOBAL real* out, const aw_tangent* t, int j, int ok,
                               AW_CONSTANT aw_rparams* rp) {
  real l2[AW_LANES], mx[AW_LANES], ys[AW_LANES], cv[AW_LANES];
  real qx[AW_LANES], qy[AW_LANES], qz[AW_LANES], px[AW_LANES], py[AW_LANES], pz[AW_LANES];
  AW_STORE_LANES(t->log2w, l2);
  AW_STORE_LANES(t->max_n2, mx);
  AW_STORE_LANES(t->ysum, ys);
  AW_STORE_LANES(t->cov, cv);
  AW_STORE_LANES(t->qx, qx);
  AW_STORE_LANES(t->qy, qy);
  AW_STORE_LANES(t->qz, qz);
  AW_STORE_LANES(t->px, px);
  AW_STORE_LANES(t->py, py);
  AW_STORE_LANES(t->pz, pz);
  const real ln2 = AW_R(0.6931471805599453);
  const real k = (real)t->steps;
  const real h = rp->tangent_step;
  real fli = aw_nan_real(), megno = aw_nan_real(), lam_y = aw_nan_real(), lam = aw_nan_real();
  if (ok && t->steps > 0) {
    if (AW_HAS(AW_F_FLI)) fli = AW_FMA(l2[j], ln2, AW_R(0.5) * aw_log_or_nan(mx[j]));
    if (AW_HAS(AW_F_MEGNO)) {
      megno = ys[j] / k;
      /* sum over j = 1..k of (j - (k + 1)/2)^2 = k (k^2 - 1) / 12 */
      const real var = (k * (k * k - AW_R(1.0))) / AW_R(12.0);
      lam_y = (t->steps > 1) ? (cv[j] / var) / h : aw_nan_real(); /* Y ~ lambda t */
    }
    if (AW_HAS(AW_F_LYAPUNOV)) {
      real n2 = AW_FMA(pz[j], pz[j], AW_FMA(py[j], py[j], AW_FMA(px[j], px[j],
                       AW_FMA(qz[j], qz[j], AW_FMA(qy[j], qy[j], qx[j] * qx[j])))));
      lam = AW_FMA(l2[j], ln2, AW_R(0.5) * aw_log_or_nan(n2)) / (k * h);
    }
  }
  out[AW_IND_FLI] = fli;
  out[AW_IND_MEGNO] = megno;
  out[AW_IND_MEGNO_LYAPUNOV] = lam_y;
  out[AW_IND_LYAPUNOV] = lam;
}

typedef struct {
  aw_tangent tangent; /* the tangent vector and its observers */
} aw_fx_indicators_state;

/* A few stores, whatever the bits: every field is defined for the cpu
 * backend's run-time bits (and saved by a time slice). */
AW_FN void aw_fx_indicators_begin(aw_config cfg, aw_fx_indicators_state* me, aw_fx_core* fx, aw_lstate* s,
                                  aw_lanes l, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip,
                                  aw_outputs out) {
  aw_tangent_begin(&me->tangent, rp);
}

/* The force at the initial state with the Hessian: 1 where this effect took it. */
AW_FN int aw_fx_indicators_first_force(aw_config cfg, aw_fx_indicators_state* me, aw_fx_core* fx, aw_lstate* s,
                                       AW_CONSTANT aw_rparams* rp) {
  if (!AW_HAS(AW_F_TANGENT)) return 0;
  aw_tangent_force(s, &me->tangent, rp);
  return 1;
}

/* One segment of the steps carrying the tangent vector, in place of the
 * plain stepper: 1 where this effect took them. */
AW_FN int aw_fx_indicators_steps(aw_config cfg, aw_fx_indicators_state* me, aw_fx_core* fx, aw_lstate* s,
                                 aw_i64 nsteps, AW_CONSTANT aw_rparams* rp) {
  if (!AW_HAS(AW_F_TANGENT)) return 0;
  aw_segment_tangent(cfg, s, &me->tangent, nsteps, rp);
  return 1;
}

AW_FN void aw_fx_indicators_finish(aw_config cfg, aw_fx_indicators_state* me, aw_fx_core* fx, aw_lstate* s,
                                   aw_lanes l, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip,
                                   aw_outputs out) {
  if (!AW_HAS(AW_F_TANGENT)) return;
  for (int j = 0; j < AW_LANES; ++j) {
    if (!AW_LANE_ACTIVE(l, j)) continue;
    const int st = fx->status[j];
    aw_store_indicators(cfg, aw_record_r(out, ip, AW_OUT_INDICATORS, AW_LANE_RECORD(l, j)), &me->tangent, j,
                        st == AW_STATUS_OK || st == AW_STATUS_LEFT_REGION, rp);
  }
}

/* The tangent vector and its observers, in their order in the carry record
 * (AW_CARRY_TANGENT + 0 .. 12); the steps in its last integer. The Hessian
 * comes again with the first force. */
#define AW_TANGENT_CARRIED(t)                                                                          \
  {&(t)->qx, &(t)->qy, &(t)->qz, &(t)->px, &(t)->py, &(t)->pz, &(t)->log2w, &(t)->max_n2, &(t)->s1, \
   &(t)->ysum, &(t)->mean_y, &(t)->cov, &(t)->prev_n2}

AW_FN void aw_fx_indicators_carry_save(aw_config cfg, aw_fx_indicators_state* me, aw_fx_core* fx, aw_outputs out,
                                       AW_CONSTANT aw_iparams* ip, aw_lanes l) {
  lreal* const f[13] = AW_TANGENT_CARRIED(&me->tangent);
  for (int c = 0; c < 13; ++c) aw_carry_put(out, ip, l, AW_CARRY_TANGENT + c, *f[c]);
  for (int j = 0; j < AW_LANES; ++j)
    if (AW_LANE_ACTIVE(l, j))
      aw_record_i(out, ip, AW_OUT_CARRY, AW_LANE_RECORD(l, j))[AW_CARRY_INTS - 1] = me->tangent.steps;
}

AW_FN void aw_fx_indicators_carry_load(aw_config cfg, aw_fx_indicators_state* me, aw_fx_core* fx, aw_outputs out,
                                       AW_CONSTANT aw_iparams* ip, aw_lanes l) {
  lreal* const f[13] = AW_TANGENT_CARRIED(&me->tangent);
  for (int c = 0; c < 13; ++c) *f[c] = aw_carry_get(out, ip, l, AW_CARRY_TANGENT + c);
  me->tangent.steps = 0;
  for (int j = 0; j < AW_LANES; ++j)
    if (AW_LANE_ACTIVE(l, j))
      me->tangent.steps = aw_record_i(out, ip, AW_OUT_CARRY, AW_LANE_RECORD(l, j))[AW_CARRY_INTS - 1];
}

#endif /* AW_FX_INDICATORS_H */
