/* arnoldweb portable device core: the model.
 *
 *   H = |P|^2 / 2 + V(X),   V = cos x cos y (1 + cos 2z) = 2 cos x cos y cos^2 z
 *
 * Positions are carried in turns (u = x / 2pi) with integer winding counts.
 * The force F = -grad V (with respect to x, in radians):
 *   F_x = 2 sin x cos y cos^2 z,  F_y = 2 cos x sin y cos^2 z,
 *   F_z = 4 cos x cos y sin z cos z.
 * Three sincos per evaluation; the order of every operation is fixed here.
 */
#ifndef AW_MODEL_H
#define AW_MODEL_H

#include "aw_math.h"

/* A lane of trajectories: wrapped position (turns, in [-1/2, 1/2] after each
 * step), winding counts, momentum, and the force at the current position
 * (cached so that back-to-back steps share one evaluation). */
typedef struct {
  lreal ux, uy, uz;
  lint wx, wy, wz;
  lreal px, py, pz;
  lreal fx, fy, fz;
} aw_lstate;

AW_FN void aw_force(aw_lstate* s) {
  lreal sx, cx, sy, cy, sz, cz;
  aw_sincos2pi(s->ux, &sx, &cx);
  aw_sincos2pi(s->uy, &sy, &cy);
  aw_sincos2pi(s->uz, &sz, &cz);
  lreal q = AW_R(2.0) * (cz * cz); /* 1 + cos 2z */
  s->fx = (sx * cy) * q;
  s->fy = (cx * sy) * q;
  s->fz = AW_R(4.0) * ((cx * cy) * (sz * cz));
}

AW_FN lreal aw_potential(lreal ux, lreal uy, lreal uz) {
  lreal sx, cx, sy, cy, sz, cz;
  aw_sincos2pi(ux, &sx, &cx);
  aw_sincos2pi(uy, &sy, &cy);
  aw_sincos2pi(uz, &sz, &cz);
  return AW_R(2.0) * ((cx * cy) * (cz * cz));
}

AW_FN lreal aw_kinetic(lreal px, lreal py, lreal pz) {
  return AW_R(0.5) * AW_FMA(pz, pz, AW_FMA(py, py, px * px));
}

AW_FN lreal aw_energy(const aw_lstate* s) {
  return aw_kinetic(s->px, s->py, s->pz) + aw_potential(s->ux, s->uy, s->uz);
}

#endif /* AW_MODEL_H */
