/* arnoldweb portable device core: the whole life of a lane of trajectories.
 *
 * initial state from (seed, index) -> windows of integration -> at the end of
 * each averaging window the averaged velocity V = (X(t + dt) - X(t)) / dt,
 * i.e. the displacement over the window, goes to the effects (binning by
 * direction, flags) -> counters, energy statistics, optional state records.
 * Everything stays in registers; only integer histograms, counters and (on
 * request) state records leave. The kernels in kernels_cl/ and kernels_cu/ and
 * the C++ backend call aw_ensemble_item(); every effect sits behind
 * `cfg.features & AW_F_...` (effects/aw_effects.h), a compile-time constant
 * there.
 */
#ifndef AW_ENSEMBLE_H
#define AW_ENSEMBLE_H

#include "aw_initial.h"
#include "aw_stepper.h"
#include "effects/aw_effects.h"

/* On return, *emax and *esum hold the maximum and the sum of max|dE| over this
 * item's binned trajectories (zero without AW_F_ENERGY). */
AW_FN void aw_ensemble_item(aw_config cfg, aw_lanes l, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip,
                            aw_outputs out, real* emax, real* esum) {
  aw_lstate s;
  aw_fx fx;
  lreal accepted = aw_initial_state(&s, cfg.initial, l.first, rp, ip);
  aw_fx_begin(cfg, &fx, &s, accepted, l, rp, ip, out);
  aw_fx_first_force(cfg, &fx, &s, rp);

  for (aw_i64 w = 0; w < ip->windows; ++w) {
    lreal ux0 = s.ux, uy0 = s.uy, uz0 = s.uz;
    lint wx0 = s.wx, wy0 = s.wy, wz0 = s.wz;
    aw_fx_window_begin(cfg, &fx);
    for (aw_i64 g = 0; g < ip->segments; ++g) {
      aw_fx_segment(cfg, &fx, &s, ip->steps_per_segment, rp);
      aw_fx_sample(cfg, &fx, &s, rp);
    }
    /* displacement over the window, in turns: exact integer part + wrapped part */
    lreal dx = AW_INT_TO_LANE(s.wx - wx0) + (s.ux - ux0);
    lreal dy = AW_INT_TO_LANE(s.wy - wy0) + (s.uy - uy0);
    lreal dz = AW_INT_TO_LANE(s.wz - wz0) + (s.uz - uz0);
    lreal sane = AW_SELECT(AW_LSPLAT(AW_R(0.0)), AW_LSPLAT(AW_R(1.0)),
                           AW_ISFINITE(s.ux) & AW_ISFINITE(s.uy) & AW_ISFINITE(s.uz) & AW_ISFINITE(s.px) &
                               AW_ISFINITE(s.py) & AW_ISFINITE(s.pz));
    aw_fx_window_end(cfg, &fx, w, dx, dy, dz, sane, l, rp, ip, out);
  }
  if (AW_HAS(AW_F_REVERSE)) aw_reverse(cfg, &s, rp, ip);
  aw_fx_finish(cfg, &fx, &s, l, out, emax, esum, rp);
}

#endif /* AW_ENSEMBLE_H */
