/* arnoldweb model "seibert2011": the Hamiltonian of Seibert, Denisov,
 * Ponomarev & Hänggi, Mapping the Arnold web with a GPU-supercomputer.
 *
 *   H = |P|^2 / 2 + V(X),   V = cos x cos y (1 + cos 2z) = 2 cos x cos y cos^2 z
 *
 * The force F = -grad V (with respect to x, in radians):
 *   F_x = 2 sin x cos y cos^2 z,  F_y = 2 cos x sin y cos^2 z,
 *   F_z = 4 cos x cos y sin z cos z.
 * Three sincos per evaluation. No parameters of its own: the energy E
 * (rp->energy) sets the effective perturbation 2/E.
 */
#ifndef AW_SEIBERT2011_H
#define AW_SEIBERT2011_H

#include "aw_math.h"
#include "aw_state.h"

AW_FN void aw_model_force(aw_lstate* s, AW_CONSTANT aw_rparams* rp) {
  lreal sx, cx, sy, cy, sz, cz;
  aw_sincos2pi(s->ux, &sx, &cx);
  aw_sincos2pi(s->uy, &sy, &cy);
  aw_sincos2pi(s->uz, &sz, &cz);
  lreal q = AW_R(2.0) * (cz * cz); /* 1 + cos 2z */
  s->fx = (sx * cy) * q;
  s->fy = (cx * sy) * q;
  s->fz = AW_R(4.0) * ((cx * cy) * (sz * cz));
}

/* The force and the Hessian of V (d^2V / dx_i dx_j, radians) at s->u, from
 * the same three sincos: hess = (xx, yy, zz, xy, xz, yz). For the tangent
 * dynamics of the chaos indicators and for force-gradient methods.
 *   V_xx = V_yy = -2 cx cy cz^2,  V_zz = -4 cx cy (cz^2 - sz^2),
 *   V_xy = 2 sx sy cz^2,  V_xz = 4 sx cy sz cz,  V_yz = 4 cx sy sz cz. */
AW_FN void aw_model_force_hessian(aw_lstate* s, AW_CONSTANT aw_rparams* rp, lreal* hess) {
  lreal sx, cx, sy, cy, sz, cz;
  aw_sincos2pi(s->ux, &sx, &cx);
  aw_sincos2pi(s->uy, &sy, &cy);
  aw_sincos2pi(s->uz, &sz, &cz);
  lreal q = AW_R(2.0) * (cz * cz); /* 1 + cos 2z */
  lreal szcz = sz * cz;
  lreal cxcy = cx * cy;
  s->fx = (sx * cy) * q;
  s->fy = (cx * sy) * q;
  s->fz = AW_R(4.0) * (cxcy * szcz);
  hess[0] = -(cxcy * q);
  hess[1] = hess[0];
  hess[2] = AW_R(-4.0) * (cxcy * (cz * cz - sz * sz));
  hess[3] = (sx * sy) * q;
  hess[4] = AW_R(4.0) * ((sx * cy) * szcz);
  hess[5] = AW_R(4.0) * ((cx * sy) * szcz);
}

AW_FN lreal aw_model_potential(lreal ux, lreal uy, lreal uz, AW_CONSTANT aw_rparams* rp) {
  lreal sx, cx, sy, cy, sz, cz;
  aw_sincos2pi(ux, &sx, &cx);
  aw_sincos2pi(uy, &sy, &cy);
  aw_sincos2pi(uz, &sz, &cz);
  return AW_R(2.0) * ((cx * cy) * (cz * cz));
}

AW_FN lreal aw_model_kinetic(lreal px, lreal py, lreal pz, AW_CONSTANT aw_rparams* rp) {
  return AW_R(0.5) * AW_FMA(pz, pz, AW_FMA(py, py, px * px));
}

/* The diagonal of d^2T/dP^2 (constant for every supported kinetic form): the tangent drift is du_i += d a_i dp_i. */
AW_FN void aw_model_kinetic_diag(AW_CONSTANT aw_rparams* rp, real* a) { a[0] = AW_R(1.0); a[1] = AW_R(1.0); a[2] = AW_R(1.0); }

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

#endif /* AW_SEIBERT2011_H */
