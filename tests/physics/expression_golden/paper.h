/* arnoldweb expression model: generated from model.potential (lib/src/physics/expression/).
 *   V = cos(x)*cos(y)*(1 + cos(2*z))
 * One statement per operation, in a fixed order; see docs/models.md. */
#ifndef AW_EXPRESSION_MODEL_H
#define AW_EXPRESSION_MODEL_H

#include "aw_exp.h"
#include "aw_math.h"
#include "aw_state.h"

AW_FN lreal aw_model_potential(lreal ux, lreal uy, lreal uz, AW_CONSTANT aw_rparams* rp) {
  lreal s1, c1;
  aw_sincos2pi(ux, &s1, &c1);
  lreal s3, c3;
  aw_sincos2pi(uy, &s3, &c3);
  const lreal t5 = c1 * c3;
  const lreal t8 = AW_R(2.0) * uz;
  lreal s8, c8;
  aw_sincos2pi(t8, &s8, &c8);
  const lreal t10 = AW_R(1.0) + c8;
  const lreal t11 = t5 * t10;
  return t11;
}

AW_FN void aw_model_force(aw_lstate* s, AW_CONSTANT aw_rparams* rp) {
  const lreal ux = s->ux;
  const lreal uy = s->uy;
  const lreal uz = s->uz;
  lreal s1, c1;
  aw_sincos2pi(ux, &s1, &c1);
  lreal s3, c3;
  aw_sincos2pi(uy, &s3, &c3);
  const lreal t5 = c1 * c3;
  const lreal t8 = AW_R(2.0) * uz;
  lreal s8, c8;
  aw_sincos2pi(t8, &s8, &c8);
  const lreal t10 = AW_R(1.0) + c8;
  const lreal t13 = c3 * s1;
  const lreal t14 = t10 * t13;
  const lreal t17 = c1 * s3;
  const lreal t18 = t10 * t17;
  const lreal t21 = AW_R(2.0) * s8;
  const lreal t22 = t5 * t21;
  s->fx = t14;
  s->fy = t18;
  s->fz = t22;
}

AW_FN void aw_model_force_hessian(aw_lstate* s, AW_CONSTANT aw_rparams* rp, lreal* hess) {
  const lreal ux = s->ux;
  const lreal uy = s->uy;
  const lreal uz = s->uz;
  lreal s1, c1;
  aw_sincos2pi(ux, &s1, &c1);
  lreal s3, c3;
  aw_sincos2pi(uy, &s3, &c3);
  const lreal t5 = c1 * c3;
  const lreal t8 = AW_R(2.0) * uz;
  lreal s8, c8;
  aw_sincos2pi(t8, &s8, &c8);
  const lreal t10 = AW_R(1.0) + c8;
  const lreal t11 = t5 * t10;
  const lreal t13 = c3 * s1;
  const lreal t14 = t10 * t13;
  const lreal t17 = c1 * s3;
  const lreal t18 = t10 * t17;
  const lreal t21 = AW_R(2.0) * s8;
  const lreal t22 = t5 * t21;
  const lreal t24 = -t11;
  const lreal t25 = AW_R(2.0) * c8;
  const lreal t26 = AW_R(2.0) * t25;
  const lreal t27 = t5 * t26;
  const lreal t28 = -t27;
  const lreal t29 = s1 * s3;
  const lreal t30 = t10 * t29;
  const lreal t31 = t13 * t21;
  const lreal t32 = t17 * t21;
  s->fx = t14;
  s->fy = t18;
  s->fz = t22;
  hess[0] = t24;
  hess[1] = t24;
  hess[2] = t28;
  hess[3] = t30;
  hess[4] = t31;
  hess[5] = t32;
}

#endif /* AW_EXPRESSION_MODEL_H */
