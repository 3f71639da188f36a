/* arnoldweb portable device core: the effects, composed. A trajectory's life
 * (aw_ensemble.h) calls these hooks; each does the core's part (the lanes'
 * status, E(0), the flags of a window, the status counters) and calls every
 * effect's hook of that name in the effects' order, through
 * effects/aw_effect_hooks.h, which cmake/ArnoldwebEffects.cmake generates
 * from the effect headers (effects/aw_fx_<name>.h: AW_EFFECT_ORDER(<n>), its
 * state aw_fx_<name>_state, its hooks aw_fx_<name>_<hook>):
 *   begin         after the initial state (test_inject first, initial_states)
 *   first_force   the force at the start; steps: a segment of steps (an
 *                 effect may take them in place of the plain stepper)
 *   counts        the sample counts at the first segment of a launch
 *   window_begin  at the start of every averaging window
 *   sample        after every segment (the finest sample interval)
 *   flag          at the end of a window: the lanes an effect flags
 *   window_end    then, for the lanes still fine (the binning)
 *   finish        after the run (time_reversal first, then the records)
 *   carry_save, carry_load  an effect's state between time slices
 *                 (effects/aw_fx_carry.h)
 * Adding an effect: its bit in aw_params.h, its header in effects/, its row in
 * the host's effect table (lib/src/plan/effects.cpp). Nothing here. */
#ifndef AW_EFFECTS_H
#define AW_EFFECTS_H

#include "aw_stepper.h"
#include "effects/aw_effect_hooks.h"

AW_FN void aw_fx_begin(aw_config cfg, aw_fx* fx, aw_lstate* s, lreal accepted, aw_lanes l,
                       AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  real tmp[AW_LANES];
  AW_STORE_LANES(accepted, tmp);
  for (int j = 0; j < AW_LANES; ++j) fx->core.status[j] = (tmp[j] != AW_R(0.0)) ? AW_STATUS_OK : AW_STATUS_INITIAL;
  fx->core.e0 = AW_LSPLAT(AW_R(0.0));
  aw_fx_effects_begin(cfg, fx, s, l, rp, ip, out);
  /* after the effects' begin: the test hook's injection counts in E(0) */
  if (AW_HAS(AW_F_WITH_E0)) fx->core.e0 = aw_energy(s, rp);
}

/* The force at the initial state (an effect may take it: the indicators' Hessian). */
AW_FN void aw_fx_first_force(aw_config cfg, aw_fx* fx, aw_lstate* s, AW_CONSTANT aw_rparams* rp) {
  if (!aw_fx_effects_first_force(cfg, fx, s, rp)) aw_force(s, rp);
}

/* One segment of steps: the plain stepper, or an effect's (the indicators
 * carry the tangent vector through the same steps, aw_tangent.h). */
AW_FN void aw_fx_segment(aw_config cfg, aw_fx* fx, aw_lstate* s, aw_i64 nsteps, AW_CONSTANT aw_rparams* rp) {
  if (!aw_fx_effects_steps(cfg, fx, s, nsteps, rp)) aw_segment(s, nsteps, rp, cfg.stages, cfg.kick_first, cfg.gradient);
}

/* The sample counts at the first segment of a launch, seg_first. */
AW_FN void aw_fx_counts_begin(aw_config cfg, aw_fx* fx, aw_i64 seg_first, AW_CONSTANT aw_iparams* ip) {
  aw_fx_effects_counts(cfg, fx, seg_first, ip);
}

AW_FN void aw_fx_window_begin(aw_config cfg, aw_fx* fx) { aw_fx_effects_window_begin(cfg, fx); }

/* After every segment (the counts begun by aw_fx_counts_begin say which
 * samples are due). */
AW_FN void aw_fx_sample(aw_config cfg, aw_fx* fx, const aw_lstate* s, aw_lanes l, AW_CONSTANT aw_rparams* rp,
                        AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  aw_fx_effects_sample(cfg, fx, s, l, rp, ip, out);
}

/* The end of window w: (dx, dy, dz) the displacement over it in turns, sane
 * 1 where the state is finite. A lane not flagged before is flagged here
 * (non-finite first, then each effect's flag in order: the first wins);
 * then the effects' window_end see the lanes still fine (the binning). */
AW_FN void aw_fx_window_end(aw_config cfg, aw_fx* fx, aw_i64 w, lreal dx, lreal dy, lreal dz, lreal sane, aw_lanes l,
                            AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  real ax[AW_LANES], ay[AW_LANES], az[AW_LANES], asane[AW_LANES];
  AW_STORE_LANES(dx, ax);
  AW_STORE_LANES(dy, ay);
  AW_STORE_LANES(dz, az);
  AW_STORE_LANES(sane, asane);
  int flag[AW_LANES];
  for (int j = 0; j < AW_LANES; ++j) flag[j] = (asane[j] == AW_R(0.0)) ? AW_STATUS_NONFINITE : AW_STATUS_OK;
  aw_fx_effects_flag(cfg, fx, flag);
  for (int j = 0; j < AW_LANES; ++j)
    if (fx->core.status[j] == AW_STATUS_OK && AW_LANE_ACTIVE(l, j)) fx->core.status[j] = flag[j];
  aw_fx_effects_window_end(cfg, fx, w, ax, ay, az, l, rp, ip, out);
}

/* After the run: every lane's status counted, then the effects' records;
 * (*emax, *esum) the maximum and the sum of max|dE| over the item's binned
 * lanes (the energy effect's), which the caller reduces over the work-group. */
AW_FN void aw_fx_finish(aw_config cfg, aw_fx* fx, aw_lstate* s, aw_lanes l, aw_outputs out, real* emax, real* esum,
                        AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip) {
  fx->core.binned_emax = AW_R(0.0);
  fx->core.binned_esum = AW_R(0.0);
  for (int j = 0; j < AW_LANES; ++j)
    if (AW_LANE_ACTIVE(l, j)) {
      const int st = fx->core.status[j];
      AW_ATOMIC_INC(&out.counters[st == AW_STATUS_OK ? AW_C_BINNED : st]);
    }
  aw_fx_effects_finish(cfg, fx, s, l, rp, ip, out);
  *emax = fx->core.binned_emax;
  *esum = fx->core.binned_esum;
}

#endif /* AW_EFFECTS_H */
