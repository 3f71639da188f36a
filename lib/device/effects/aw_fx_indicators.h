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
#ifndef AW_FX_INDICATORS_H
#define AW_FX_INDICATORS_H

#include "aw_tangent.h"

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

#endif /* AW_FX_INDICATORS_H */
