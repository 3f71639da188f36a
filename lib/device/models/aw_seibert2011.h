/* arnoldweb model "seibert2011": the Hamiltonian of Seibert, Denisov,
 * Ponomarev & Hänggi, Mapping the Arnold web with a GPU-supercomputer.
 *
 *   H = |P|^2 / 2 + V(X),   V = cos x cos y (1 + cos 2z) = 2 cos x cos y cos^2 z
 *
 * The force F = -grad V (with respect to x, in radians), from the sin and cos
 * of x, y and 2z:
 *   F_x = sin x cos y (1 + cos 2z),  F_y = cos x sin y (1 + cos 2z),
 *   F_z = 2 cos x cos y sin 2z,
 * each a (1 + c) as fma(a, c, a): three sincos and 7 operations an
 * evaluation. No parameters of its own: the energy E (rp->energy) sets the
 * effective perturbation 2/E.
 */
#ifndef AW_SEIBERT2011_H
#define AW_SEIBERT2011_H

#include "aw_math.h"
#include "aw_state.h"
#include "kinetic/aw_kinetic_standard.h" /* T = |P|^2 / 2 */

/* sin and cos of x, y and 2z (from the angles in turns) */
typedef struct {
  lreal sx, cx, sy, cy, s2, c2;
} aw_seibert_trig;

AW_FN aw_seibert_trig aw_seibert_trig_at(lreal ux, lreal uy, lreal uz) {
  aw_seibert_trig t;
  aw_sincos2pi(ux, &t.sx, &t.cx);
  aw_sincos2pi(uy, &t.sy, &t.cy);
  aw_sincos2pi_n(uz, AW_R(2.0), &t.s2, &t.c2);
  return t;
}

/* F from the sincos at s->u into s->f: the one place the force is written,
 * so aw_model_force and aw_model_force_hessian give it the same bits. */
AW_FN void aw_seibert_force_of(aw_lstate* s, const aw_seibert_trig* t) {
  lreal sxcy = t->sx * t->cy, cxsy = t->cx * t->sy, cxcy = t->cx * t->cy;
  s->fx = AW_FMA(sxcy, t->c2, sxcy);
  s->fy = AW_FMA(cxsy, t->c2, cxsy);
  s->fz = (cxcy + cxcy) * t->s2;
}

AW_FN void aw_model_force(aw_lstate* s, AW_CONSTANT aw_rparams* rp) {
  const aw_seibert_trig t = aw_seibert_trig_at(s->ux, s->uy, s->uz);
  aw_seibert_force_of(s, &t);
}

/* The force and the Hessian of V (d^2V / dx_i dx_j, radians) at s->u, from
 * the same three sincos: hess = (xx, yy, zz, xy, xz, yz). For the tangent
 * dynamics of the chaos indicators and for force-gradient methods.
 *   V_xx = V_yy = -cx cy (1 + c2),  V_zz = -4 cx cy c2,
 *   V_xy = sx sy (1 + c2),  V_xz = 2 sx cy s2,  V_yz = 2 cx sy s2
 * (c2, s2: cos 2z, sin 2z). */
AW_FN void aw_model_force_hessian(aw_lstate* s, AW_CONSTANT aw_rparams* rp, lreal* hess) {
  const aw_seibert_trig t = aw_seibert_trig_at(s->ux, s->uy, s->uz);
  aw_seibert_force_of(s, &t);
  lreal sxcy = t.sx * t.cy, cxsy = t.cx * t.sy, cxcy = t.cx * t.cy, sxsy = t.sx * t.sy;
  hess[0] = -AW_FMA(cxcy, t.c2, cxcy);
  hess[1] = hess[0];
  hess[2] = AW_R(-4.0) * (cxcy * t.c2);
  hess[3] = AW_FMA(sxsy, t.c2, sxsy);
  hess[4] = (sxcy + sxcy) * t.s2;
  hess[5] = (cxsy + cxsy) * t.s2;
}

AW_FN lreal aw_model_potential(lreal ux, lreal uy, lreal uz, AW_CONSTANT aw_rparams* rp) {
  const aw_seibert_trig t = aw_seibert_trig_at(ux, uy, uz);
  lreal cxcy = t.cx * t.cy;
  return AW_FMA(cxcy, t.c2, cxcy);
}

#endif /* AW_SEIBERT2011_H */
