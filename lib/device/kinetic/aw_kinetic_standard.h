/* arnoldweb models: the kinetic half of the model interface (aw_model.h) for
 * T = |P|^2 / 2, the form of the paper's model: a model with this kinetic
 * energy includes this header and writes only its potential half.
 */
#ifndef AW_KINETIC_STANDARD_H
#define AW_KINETIC_STANDARD_H

#include "aw_state.h"

AW_FN lreal aw_model_kinetic(lreal px, lreal py, lreal pz, AW_CONSTANT aw_rparams* rp) {
  return AW_R(0.5) * AW_FMA(pz, pz, AW_FMA(py, py, px * px));
}

/* The diagonal of d^2T/dP^2 (constant for every supported kinetic form): the tangent drift is du_i += d a_i dp_i. */
AW_FN void aw_model_kinetic_diag(AW_CONSTANT aw_rparams* rp, real* a) { a[0] = AW_R(1.0); a[1] = AW_R(1.0); a[2] = AW_R(1.0); }

/* u += d P */
AW_FN void aw_model_drift(aw_lstate* s, real d, AW_CONSTANT aw_rparams* rp) {
  lreal dd = AW_LSPLAT(d);
  s->ux = AW_FMA(dd, s->px, s->ux);
  s->uy = AW_FMA(dd, s->py, s->uy);
  s->uz = AW_FMA(dd, s->pz, s->uz);
}

/* |P|^2 / 2 = ke along any direction: s = sqrt(2 ke); ok where ke > 0. */
AW_FN lreal aw_model_speed(lreal ke, lreal dx, lreal dy, lreal dz, AW_CONSTANT aw_rparams* rp, lreal* ok) {
  *ok = AW_SELECT(AW_LSPLAT(AW_R(0.0)), AW_LSPLAT(AW_R(1.0)), ke > AW_R(0.0));
  return AW_SQRT(AW_R(2.0) * AW_SELECT(AW_LSPLAT(AW_R(0.0)), ke, ke > AW_R(0.0)));
}

#endif /* AW_KINETIC_STANDARD_H */
