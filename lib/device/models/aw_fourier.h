/* arnoldweb model "fourier": a truncated Fourier potential with the general
 * kinetic form,
 *
 *   H = sum_i a_i p_i^2 / 2 + sum_i b_i p_i + sum_k c_k cos(k.X + phi_k),
 *
 * with integer wave vectors k, given in the scene (model.harmonics,
 * model.kinetic_a, model.kinetic_b). Parameters (rp->model):
 *   [0..2] a   [3..5] b   [6] the number of harmonics n (<= AW_FOURIER_MAX)
 *   [7 + 5 j + 0..4] harmonic j: k_x, k_y, k_z, c, phi (phi in turns)
 * With theta = k.X + phi:
 *   F_i = -dV/dx_i = sum c k_i sin theta,   V_ij = -sum c k_i k_j cos theta.
 * One sincos per harmonic, summed in the order of the scene.
 */
#ifndef AW_FOURIER_H
#define AW_FOURIER_H

#include "aw_math.h"
#include "aw_state.h"
#include "kinetic/aw_kinetic_ab.h" /* the kinetic half: a, b in rp->model[0..5] */

#define AW_FOURIER_MAX 32 /* harmonics */
#define AW_FOURIER_FIRST 7 /* index of the first harmonic in rp->model */

/* theta of harmonic j at u, in turns */
AW_FN lreal aw_fourier_phase(AW_CONSTANT real* h, lreal ux, lreal uy, lreal uz) {
  return AW_FMA(AW_LSPLAT(h[2]), uz, AW_FMA(AW_LSPLAT(h[1]), uy, AW_FMA(AW_LSPLAT(h[0]), ux, AW_LSPLAT(h[4]))));
}

AW_FN void aw_model_force(aw_lstate* s, AW_CONSTANT aw_rparams* rp) {
  const int n = (int)rp->model[6];
  lreal fx = AW_LSPLAT(AW_R(0.0)), fy = fx, fz = fx;
  for (int j = 0; j < n; ++j) {
    AW_CONSTANT real* h = &rp->model[AW_FOURIER_FIRST + 5 * j];
    lreal sn, cs;
    aw_sincos2pi(aw_fourier_phase(h, s->ux, s->uy, s->uz), &sn, &cs);
    lreal w = AW_LSPLAT(h[3]) * sn; /* c sin theta */
    fx = AW_FMA(AW_LSPLAT(h[0]), w, fx);
    fy = AW_FMA(AW_LSPLAT(h[1]), w, fy);
    fz = AW_FMA(AW_LSPLAT(h[2]), w, fz);
  }
  s->fx = fx;
  s->fy = fy;
  s->fz = fz;
}

AW_FN void aw_model_force_hessian(aw_lstate* s, AW_CONSTANT aw_rparams* rp, lreal* hess) {
  const int n = (int)rp->model[6];
  lreal fx = AW_LSPLAT(AW_R(0.0)), fy = fx, fz = fx;
  for (int i = 0; i < 6; ++i) hess[i] = fx;
  for (int j = 0; j < n; ++j) {
    AW_CONSTANT real* h = &rp->model[AW_FOURIER_FIRST + 5 * j];
    lreal sn, cs;
    aw_sincos2pi(aw_fourier_phase(h, s->ux, s->uy, s->uz), &sn, &cs);
    lreal w = AW_LSPLAT(h[3]) * sn;   /* c sin theta */
    lreal v = AW_LSPLAT(-h[3]) * cs;  /* -c cos theta */
    fx = AW_FMA(AW_LSPLAT(h[0]), w, fx);
    fy = AW_FMA(AW_LSPLAT(h[1]), w, fy);
    fz = AW_FMA(AW_LSPLAT(h[2]), w, fz);
    hess[0] = AW_FMA(AW_LSPLAT(h[0] * h[0]), v, hess[0]);
    hess[1] = AW_FMA(AW_LSPLAT(h[1] * h[1]), v, hess[1]);
    hess[2] = AW_FMA(AW_LSPLAT(h[2] * h[2]), v, hess[2]);
    hess[3] = AW_FMA(AW_LSPLAT(h[0] * h[1]), v, hess[3]);
    hess[4] = AW_FMA(AW_LSPLAT(h[0] * h[2]), v, hess[4]);
    hess[5] = AW_FMA(AW_LSPLAT(h[1] * h[2]), v, hess[5]);
  }
  s->fx = fx;
  s->fy = fy;
  s->fz = fz;
}

AW_FN lreal aw_model_potential(lreal ux, lreal uy, lreal uz, AW_CONSTANT aw_rparams* rp) {
  const int n = (int)rp->model[6];
  lreal v = AW_LSPLAT(AW_R(0.0));
  for (int j = 0; j < n; ++j) {
    AW_CONSTANT real* h = &rp->model[AW_FOURIER_FIRST + 5 * j];
    lreal sn, cs;
    aw_sincos2pi(aw_fourier_phase(h, ux, uy, uz), &sn, &cs);
    v = AW_FMA(AW_LSPLAT(h[3]), cs, v);
  }
  return v;
}

#endif /* AW_FOURIER_H */
