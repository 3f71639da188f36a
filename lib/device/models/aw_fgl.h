/* arnoldweb model "fgl": the Hamiltonian of Froeschle, Guzzo & Lega,
 * Graphical evolution of the Arnold web: from order to chaos, Science 289
 * (2000) 2108:
 *
 *   H = I1^2 / 2 + I2^2 / 2 + I3 + eps / (cos phi1 + cos phi2 + cos phi3 + 4)
 *
 * The angles phi are the torus coordinates X (turns u = phi / 2 pi), the
 * actions the momenta P: the kinetic form T = sum a_i p_i^2/2 + b_i p_i with
 * a = (1, 1, 0), b = (0, 0, 1) (kinetic/aw_kinetic.h). Parameter: eps =
 * rp->model[0]. With D = cos phi1 + cos phi2 + cos phi3 + 4 (1 <= D <= 7):
 *   F_i = -dV/dphi_i = -eps sin phi_i / D^2,
 *   V_ii = eps (cos phi_i / D^2 + 2 sin^2 phi_i / D^3),
 *   V_ij = 2 eps sin phi_i sin phi_j / D^3 (i != j).
 * Three sincos and one division per force.
 */
#ifndef AW_FGL_H
#define AW_FGL_H

#include "aw_math.h"
#include "aw_state.h"
#include "kinetic/aw_kinetic.h"

AW_FN void aw_model_force(aw_lstate* s, AW_CONSTANT aw_rparams* rp) {
  lreal sx, cx, sy, cy, sz, cz;
  aw_sincos2pi(s->ux, &sx, &cx);
  aw_sincos2pi(s->uy, &sy, &cy);
  aw_sincos2pi(s->uz, &sz, &cz);
  lreal d = ((cx + cy) + cz) + AW_R(4.0);
  lreal g = AW_LSPLAT(-rp->model[0]) / (d * d); /* -eps / D^2 */
  s->fx = g * sx;
  s->fy = g * sy;
  s->fz = g * sz;
}

AW_FN void aw_model_force_hessian(aw_lstate* s, AW_CONSTANT aw_rparams* rp, lreal* hess) {
  lreal sx, cx, sy, cy, sz, cz;
  aw_sincos2pi(s->ux, &sx, &cx);
  aw_sincos2pi(s->uy, &sy, &cy);
  aw_sincos2pi(s->uz, &sz, &cz);
  lreal d = ((cx + cy) + cz) + AW_R(4.0);
  lreal g = AW_LSPLAT(-rp->model[0]) / (d * d); /* -eps / D^2 */
  lreal q = (AW_R(-2.0) * g) / d;               /* 2 eps / D^3 */
  s->fx = g * sx;
  s->fy = g * sy;
  s->fz = g * sz;
  hess[0] = AW_FMA(q * sx, sx, -(g * cx));
  hess[1] = AW_FMA(q * sy, sy, -(g * cy));
  hess[2] = AW_FMA(q * sz, sz, -(g * cz));
  hess[3] = (q * sx) * sy;
  hess[4] = (q * sx) * sz;
  hess[5] = (q * sy) * sz;
}

AW_FN lreal aw_model_potential(lreal ux, lreal uy, lreal uz, AW_CONSTANT aw_rparams* rp) {
  lreal sx, cx, sy, cy, sz, cz;
  aw_sincos2pi(ux, &sx, &cx);
  aw_sincos2pi(uy, &sy, &cy);
  aw_sincos2pi(uz, &sz, &cz);
  return AW_LSPLAT(rp->model[0]) / (((cx + cy) + cz) + AW_R(4.0));
}

AW_FN lreal aw_model_kinetic(lreal px, lreal py, lreal pz, AW_CONSTANT aw_rparams* rp) {
  return AW_FMA(AW_R(0.5) * px, px, AW_FMA(AW_R(0.5) * py, py, pz));
}

/* u += d (I1, I2, 1) */
AW_FN void aw_model_drift(aw_lstate* s, real d, AW_CONSTANT aw_rparams* rp) {
  lreal dd = AW_LSPLAT(d);
  s->ux = AW_FMA(dd, s->px, s->ux);
  s->uy = AW_FMA(dd, s->py, s->uy);
  s->uz = s->uz + dd;
}

/* The diagonal of d^2T/dP^2 (constant for every supported kinetic form): the tangent drift is du_i += d a_i dp_i. */
AW_FN void aw_model_kinetic_diag(AW_CONSTANT aw_rparams* rp, real* a) { a[0] = AW_R(1.0); a[1] = AW_R(1.0); a[2] = AW_R(0.0); }

/* A = n1^2 + n2^2, B = n3 */
AW_FN lreal aw_model_speed(lreal ke, lreal dx, lreal dy, lreal dz, AW_CONSTANT aw_rparams* rp, lreal* ok) {
  return aw_kinetic_speed(ke, AW_FMA(dy, dy, dx * dx), dz, ok);
}

#endif /* AW_FGL_H */
