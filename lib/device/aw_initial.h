/* arnoldweb portable device core: initial conditions on the energy shell.
 *
 * "shell": X uniform on the torus, the direction of P uniform on the sphere,
 * |P| = sqrt(2 (E - V(X))). Positions where V(X) >= E are not accessible and
 * are rejected; each trajectory tries at most AW_I_MAX_ATTEMPTS positions
 * (the host refuses energies whose accessible fraction makes failure likely)
 * and reports failure through the returned lane mask.
 *
 * Random draws per attempt (Philox counter = (index, attempt, draw)):
 *   draw 0: u_x, u_y   draw 1: u_z, cos(theta)   draw 2: phi (turns)
 */
#ifndef AW_INITIAL_H
#define AW_INITIAL_H

#include "aw_model.h"
#include "aw_params.h"
#include "aw_rng.h"

/* Fills s (force not yet computed) for the lanes first .. first+AW_LANES-1;
 * returns 1 in every lane that found an accessible state, 0 elsewhere. */
AW_FN lreal aw_initial_shell(aw_lstate* s, aw_u64 first, AW_CONSTANT real* rp,
                             AW_CONSTANT aw_i64* ip) {
  const aw_u64 seed = (aw_u64)ip[AW_I_SEED];
  const int max_attempts = (int)ip[AW_I_MAX_ATTEMPTS];
  const real energy = rp[AW_P_ENERGY];
  real r0[AW_LANES], r1[AW_LANES], r2[AW_LANES], r3[AW_LANES], r4[AW_LANES], r5[AW_LANES];
  lreal accepted = AW_LSPLAT(AW_R(0.0));
  s->ux = s->uy = s->uz = AW_LSPLAT(AW_R(0.0));
  s->px = s->py = s->pz = AW_LSPLAT(AW_R(0.0));
  s->wx = s->wy = s->wz = AW_ISPLAT(0);
  for (int attempt = 0; attempt < max_attempts; ++attempt) {
    for (int j = 0; j < AW_LANES; ++j) {
      aw_u64 index = first + (aw_u64)j;
      aw_uniform2(seed, index, (aw_u32)attempt, 0u, &r0[j], &r1[j]);
      aw_uniform2(seed, index, (aw_u32)attempt, 1u, &r2[j], &r3[j]);
      aw_uniform2(seed, index, (aw_u32)attempt, 2u, &r4[j], &r5[j]);
    }
    lreal ux = AW_LOAD_LANES(r0) - AW_R(0.5);
    lreal uy = AW_LOAD_LANES(r1) - AW_R(0.5);
    lreal uz = AW_LOAD_LANES(r2) - AW_R(0.5);
    lreal ke = energy - aw_potential(ux, uy, uz); /* kinetic energy left */
    lreal ct = AW_R(2.0) * AW_LOAD_LANES(r3) - AW_R(1.0);
    lreal st = AW_SQRT((AW_R(1.0) - ct) * (AW_R(1.0) + ct));
    lreal sphi, cphi;
    aw_sincos2pi(AW_LOAD_LANES(r4), &sphi, &cphi);
    lreal pm = AW_SQRT(AW_R(2.0) * AW_SELECT(AW_LSPLAT(AW_R(0.0)), ke, ke > AW_R(0.0)));
    lreal pt = pm * st;
    /* take the candidate where it is accessible and nothing was taken yet */
#define AW_TAKE_ (ke > AW_R(0.0)) & (accepted == AW_R(0.0))
    s->ux = AW_SELECT(s->ux, ux, AW_TAKE_);
    s->uy = AW_SELECT(s->uy, uy, AW_TAKE_);
    s->uz = AW_SELECT(s->uz, uz, AW_TAKE_);
    s->px = AW_SELECT(s->px, pt * cphi, AW_TAKE_);
    s->py = AW_SELECT(s->py, pt * sphi, AW_TAKE_);
    s->pz = AW_SELECT(s->pz, pm * ct, AW_TAKE_);
    accepted = AW_SELECT(accepted, AW_LSPLAT(AW_R(1.0)), AW_TAKE_);
#undef AW_TAKE_
    if (AW_ALL(accepted != AW_R(0.0))) break;
  }
  return accepted;
}

#endif /* AW_INITIAL_H */
