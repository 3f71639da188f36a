/* arnoldweb models: the kinetic half of the model interface (models/aw_models.h)
 * for the general form T = sum_i a_i p_i^2 / 2 + b_i p_i with a and b in
 * rp->model[0..2] and [3..5] (model.kinetic_a, model.kinetic_b). Used by the
 * fourier model and by expression models (kinetic/aw_expression_kinetic.h); one
 * copy, so both give the same bits for the same a and b.
 */
#ifndef AW_KINETIC_AB_H
#define AW_KINETIC_AB_H

#include "aw_state.h"
#include "kinetic/aw_kinetic.h"

AW_FN lreal aw_model_kinetic(lreal px, lreal py, lreal pz, AW_CONSTANT aw_rparams* rp) {
  AW_CONSTANT real* m = rp->model;
  lreal linear = AW_FMA(AW_LSPLAT(m[5]), pz, AW_FMA(AW_LSPLAT(m[4]), py, AW_LSPLAT(m[3]) * px));
  return AW_FMA(AW_LSPLAT(AW_R(0.5) * m[2]) * pz, pz,
                AW_FMA(AW_LSPLAT(AW_R(0.5) * m[1]) * py, py, AW_FMA(AW_LSPLAT(AW_R(0.5) * m[0]) * px, px, linear)));
}

/* u_i += d (a_i p_i + b_i) */
AW_FN void aw_model_drift(aw_lstate* s, real d, AW_CONSTANT aw_rparams* rp) {
  AW_CONSTANT real* m = rp->model;
  s->ux = AW_FMA(AW_LSPLAT(d * m[0]), s->px, s->ux + d * m[3]);
  s->uy = AW_FMA(AW_LSPLAT(d * m[1]), s->py, s->uy + d * m[4]);
  s->uz = AW_FMA(AW_LSPLAT(d * m[2]), s->pz, s->uz + d * m[5]);
}

/* the diagonal of d^2T/dP^2 */
AW_FN void aw_model_kinetic_diag(AW_CONSTANT aw_rparams* rp, real* a) {
  a[0] = rp->model[0];
  a[1] = rp->model[1];
  a[2] = rp->model[2];
}

/* s > 0 with T(s n) = ke along the unit direction n: A s^2/2 + B s = ke with
 * A = sum a_i n_i^2, B = sum b_i n_i (kinetic/aw_kinetic.h) */
AW_FN lreal aw_model_speed(lreal ke, lreal dx, lreal dy, lreal dz, AW_CONSTANT aw_rparams* rp, lreal* ok) {
  AW_CONSTANT real* m = rp->model;
  lreal A = AW_FMA(AW_LSPLAT(m[2]), dz * dz, AW_FMA(AW_LSPLAT(m[1]), dy * dy, AW_LSPLAT(m[0]) * (dx * dx)));
  lreal B = AW_FMA(AW_LSPLAT(m[5]), dz, AW_FMA(AW_LSPLAT(m[4]), dy, AW_LSPLAT(m[3]) * dx));
  return aw_kinetic_speed(ke, A, B, ok);
}

#endif /* AW_KINETIC_AB_H */
