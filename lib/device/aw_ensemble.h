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
 * for a launch that does not finish its trajectories). With AW_ITEMS > 1 the
 * work-item holds AW_ITEMS groups of lanes, from l.first on. */
AW_FN void aw_ensemble_item(aw_config cfg, aw_lanes l0, aw_i64 seg_first, aw_i64 seg_end, AW_CONSTANT aw_rparams* rp,
                            AW_CONSTANT aw_iparams* ip, aw_outputs out, real* emax, real* esum) {
  aw_lstate s[AW_ITEMS];
  aw_fx fx[AW_ITEMS];
  aw_window_start ws[AW_ITEMS];
  aw_lanes l[AW_ITEMS];
  const aw_i64 segments = ip->segments;
  AW_EACH_ITEM(p, AW_ITEMS) {
    aw_lstate* sp = &s[AW_ITEM(p)];
    aw_fx* fp = &fx[AW_ITEM(p)];
    aw_window_start* wp = &ws[AW_ITEM(p)];
    l[AW_ITEM(p)] = l0;
    l[AW_ITEM(p)].first = l0.first + (aw_u64)(p * AW_LANES);
    if (seg_first == 0) {
      int given[AW_LANES] = {0}; /* read only where aw_carry_load_state set it */
      lreal accepted = AW_LSPLAT(AW_R(1.0));
      if (AW_HAS(AW_F_CARRY) && cfg.initial == AW_INITIAL_FILE)
        aw_carry_load_state(sp, given, out, ip, l[AW_ITEM(p)]);
      else
        accepted = aw_initial_state(sp, cfg.initial, l[AW_ITEM(p)].first, rp, ip);
      aw_fx_begin(cfg, fp, sp, accepted, l[AW_ITEM(p)], rp, ip, out);
      if (AW_HAS(AW_F_CARRY) && cfg.initial == AW_INITIAL_FILE)
        for (int j = 0; j < AW_LANES; ++j) fp->status[j] = given[j]; /* a state flagged before stays flagged */
      wp->ux = sp->ux, wp->uy = sp->uy, wp->uz = sp->uz; /* the first window starts here */
      wp->wx = sp->wx, wp->wy = sp->wy, wp->wz = sp->wz;
    } else {
      aw_carry_load(sp, fp, wp, out, ip, l[AW_ITEM(p)]);
    }
    aw_fx_first_force(cfg, fp, sp, rp);
    aw_fx_counts_begin(cfg, fp, seg_first, ip);
  }

  aw_count at = aw_count_at(seg_first, segments); /* (window, segment g within it) of k */
  for (aw_i64 k = seg_first; k < seg_end; ++k) {
    const aw_i64 window = at.q, g = at.r;
    aw_count_next(&at, segments);
    if (g == 0) {
      AW_EACH_ITEM(p, AW_ITEMS) {
        const aw_lstate* sp = &s[AW_ITEM(p)];
        aw_window_start* wp = &ws[AW_ITEM(p)];
        wp->ux = sp->ux, wp->uy = sp->uy, wp->uz = sp->uz;
        wp->wx = sp->wx, wp->wy = sp->wy, wp->wz = sp->wz;
        aw_fx_window_begin(cfg, &fx[AW_ITEM(p)]);
      }
    }
    aw_fx_segment(cfg, fx, s, AW_ITEMS, ip->steps_per_segment, rp);
    AW_EACH_ITEM(p, AW_ITEMS) {
      const aw_lstate* sp = &s[AW_ITEM(p)];
      const aw_window_start* wp = &ws[AW_ITEM(p)];
      aw_fx_sample(cfg, &fx[AW_ITEM(p)], sp, l[AW_ITEM(p)], rp, ip, out);
      if (g == segments - 1) {
        /* displacement over the window, in turns: exact integer part + wrapped part */
        lreal dx = AW_INT_TO_LANE(sp->wx - wp->wx) + (sp->ux - wp->ux);
        lreal dy = AW_INT_TO_LANE(sp->wy - wp->wy) + (sp->uy - wp->uy);
        lreal dz = AW_INT_TO_LANE(sp->wz - wp->wz) + (sp->uz - wp->uz);
        lreal sane = AW_SELECT(AW_LSPLAT(AW_R(0.0)), AW_LSPLAT(AW_R(1.0)),
                               AW_ISFINITE(sp->ux) & AW_ISFINITE(sp->uy) & AW_ISFINITE(sp->uz) &
                                   AW_ISFINITE(sp->px) & AW_ISFINITE(sp->py) & AW_ISFINITE(sp->pz));
        aw_fx_window_end(cfg, &fx[AW_ITEM(p)], window, dx, dy, dz, sane, l[AW_ITEM(p)], rp, ip, out);
      }
    }
  }
  *emax = AW_R(0.0);
  *esum = AW_R(0.0);
  if (seg_end < ip->windows * segments) { /* a time slice: the next launch goes on from here */
    if (AW_HAS(AW_F_CARRY)) {
      AW_EACH_ITEM(p, AW_ITEMS) aw_carry_save(&s[AW_ITEM(p)], &fx[AW_ITEM(p)], &ws[AW_ITEM(p)], out, ip, l[AW_ITEM(p)]);
    }
    return;
  }
  AW_EACH_ITEM(p, AW_ITEMS) {
    real m, sum;
    if (AW_HAS(AW_F_REVERSE)) aw_reverse(cfg, &s[AW_ITEM(p)], rp, ip);
    aw_fx_finish(cfg, &fx[AW_ITEM(p)], &s[AW_ITEM(p)], l[AW_ITEM(p)], out, &m, &sum, rp, ip);
    if (AW_ITEM(p) == 0) {
      *emax = m;
      *esum = sum;
    } else { /* the pair's (max, sum), as the work-group reduction combines items */
      *emax = (m > *emax) ? m : *emax;
      *esum = *esum + sum;
    }
  }
}

#endif /* AW_ENSEMBLE_H */
