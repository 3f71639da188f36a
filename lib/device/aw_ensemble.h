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
#include "effects/aw_fx_carry.h"

/* One launch of the lanes' trajectories over the segments [seg_first,
 * seg_end) of their schedule (ip->windows windows of ip->segments segments;
 * a segment is the steps between two energy samples). A launch that starts at
 * segment 0 makes the initial states (or reads them from the records:
 * ensemble.initial = "file"); one that starts later continues from the carry
 * records (effects/aw_fx_carry.h); one that ends before the last segment
 * saves them. On return, *emax and *esum hold the maximum and the sum of
 * max|dE| over this item's binned trajectories (zero without AW_F_ENERGY, and
 * for a launch that does not finish its trajectories). */
AW_FN void aw_ensemble_item(aw_config cfg, aw_lanes l, aw_i64 seg_first, aw_i64 seg_end, AW_CONSTANT aw_rparams* rp,
                            AW_CONSTANT aw_iparams* ip, aw_outputs out, real* emax, real* esum) {
  aw_lstate s;
  aw_fx fx;
  aw_window_start ws;
  const aw_i64 segments = ip->segments;
  if (seg_first == 0) {
    int given[AW_LANES] = {0}; /* read only where aw_carry_load_state set it */
    lreal accepted = AW_LSPLAT(AW_R(1.0));
    if (AW_HAS(AW_F_CARRY) && cfg.initial == AW_INITIAL_FILE)
      aw_carry_load_state(&s, given, out, ip, l);
    else
      accepted = aw_initial_state(&s, cfg.initial, l.first, rp, ip);
    aw_fx_begin(cfg, &fx, &s, accepted, l, rp, ip, out);
    if (AW_HAS(AW_F_CARRY) && cfg.initial == AW_INITIAL_FILE)
      for (int j = 0; j < AW_LANES; ++j) fx.core.status[j] = given[j]; /* a state flagged before stays flagged */
    ws.ux = s.ux, ws.uy = s.uy, ws.uz = s.uz; /* the first window starts here */
    ws.wx = s.wx, ws.wy = s.wy, ws.wz = s.wz;
  } else {
    aw_carry_load(cfg, &s, &fx, &ws, out, ip, l);
  }
  aw_fx_first_force(cfg, &fx, &s, rp);
  aw_fx_counts_begin(cfg, &fx, seg_first, ip);

  aw_count at = aw_count_at(seg_first, segments); /* (window, segment g within it) of k */
  for (aw_i64 k = seg_first; k < seg_end; ++k) {
    const aw_i64 window = at.q, g = at.r;
    aw_count_next(&at, segments);
    if (g == 0) {
      ws.ux = s.ux, ws.uy = s.uy, ws.uz = s.uz;
      ws.wx = s.wx, ws.wy = s.wy, ws.wz = s.wz;
      aw_fx_window_begin(cfg, &fx);
    }
    aw_fx_segment(cfg, &fx, &s, ip->steps_per_segment, rp);
    aw_fx_sample(cfg, &fx, &s, l, rp, ip, out);
    if (g == segments - 1) {
      /* displacement over the window, in turns: exact integer part + wrapped part */
      lreal dx = AW_INT_TO_LANE(s.wx - ws.wx) + (s.ux - ws.ux);
      lreal dy = AW_INT_TO_LANE(s.wy - ws.wy) + (s.uy - ws.uy);
      lreal dz = AW_INT_TO_LANE(s.wz - ws.wz) + (s.uz - ws.uz);
      lreal sane = AW_SELECT(AW_LSPLAT(AW_R(0.0)), AW_LSPLAT(AW_R(1.0)),
                             AW_ISFINITE(s.ux) & AW_ISFINITE(s.uy) & AW_ISFINITE(s.uz) & AW_ISFINITE(s.px) &
                                 AW_ISFINITE(s.py) & AW_ISFINITE(s.pz));
      aw_fx_window_end(cfg, &fx, window, dx, dy, dz, sane, l, rp, ip, out);
    }
  }
  if (seg_end < ip->windows * segments) { /* a time slice: the next launch goes on from here */
    if (AW_HAS(AW_F_CARRY)) aw_carry_save(cfg, &s, &fx, &ws, out, ip, l);
    *emax = AW_R(0.0);
    *esum = AW_R(0.0);
    return;
  }
  aw_fx_finish(cfg, &fx, &s, l, out, emax, esum, rp, ip);
}

#endif /* AW_ENSEMBLE_H */
