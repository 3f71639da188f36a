/* arnoldweb portable device core: the effects, composed. A trajectory's life
 * (aw_ensemble.h) calls these hooks; each calls the effects the kernel was
 * compiled with, in a fixed order:
 *   aw_fx_begin         after the initial state: status, test_inject, initial_states, E(0)
 *   aw_fx_window_begin  at the start of every averaging window
 *   aw_fx_sample        after every segment (the finest sample interval): energy,
 *                       confinement, frequency, action and picked trajectories'
 *                       samples, each at its stride
 *   aw_fx_window_end    at the end of a window: flags, then the binning effects
 *   aw_fx_finish        after the run: counters, energy statistics, final_states
 * Adding an effect: its bit in aw_params.h, its header in effects/, its state
 * here (aw_fx) and its calls in the hooks, its row in the host's effect table
 * (lib/src/plan/effects.cpp). */
#ifndef AW_EFFECTS_H
#define AW_EFFECTS_H

#include "effects/aw_fx_binning.h"
#include "effects/aw_fx_common.h"
#include "effects/aw_fx_diffusion.h"
#include "effects/aw_fx_energy.h"
#include "effects/aw_fx_frequencies.h"
#include "effects/aw_fx_indicators.h"
#include "effects/aw_fx_states.h"
#include "effects/aw_fx_testing.h"
#include "effects/aw_fx_trajectories.h"

/* What the effects keep per lane between the hooks. */
typedef struct {
  int status[AW_LANES]; /* AW_STATUS_*: a trajectory flagged stays flagged */
  lreal e0, emax;       /* energy_error: E(0), max |dE| so far */
  lreal over;           /* max_energy_error: 1 where |dE| exceeded the limit in this window */
  lreal inside;         /* confine: 0 once a lane has left the region */
  aw_tangent tangent;   /* indicators: the tangent vector and its observers */
  lreal asum[3];        /* diffusion with averaging: the sum of the actions so far towards the next sample */
  /* (k + 1) / stride and its remainder after segment k, for the energy, the
   * frequency, the action and the picked trajectories' samples (aw_count: no
   * division per segment) */
  aw_count energy_at, frequency_at, actions_at, picks_at;
} aw_fx;

AW_FN void aw_fx_begin(aw_config cfg, aw_fx* fx, aw_lstate* s, lreal accepted, aw_lanes l,
                       AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  real tmp[AW_LANES];
  AW_STORE_LANES(accepted, tmp);
  for (int j = 0; j < AW_LANES; ++j) fx->status[j] = (tmp[j] != AW_R(0.0)) ? AW_STATUS_OK : AW_STATUS_INITIAL;
  if (AW_HAS(AW_F_TEST_INJECT)) aw_inject(s, l, rp, ip);
  if (AW_HAS(AW_F_INITIAL_STATES))
    for (int j = 0; j < AW_LANES; ++j)
      if (AW_LANE_ACTIVE(l, j))
        aw_store_state_reals(aw_record_r(out, ip, AW_OUT_INITIAL_STATE, AW_LANE_RECORD(l, j)), s, j);
  fx->e0 = AW_LSPLAT(AW_R(0.0));
  fx->emax = AW_LSPLAT(AW_R(0.0));
  fx->over = AW_LSPLAT(AW_R(0.0));
  fx->inside = AW_LSPLAT(AW_R(1.0));
  if (AW_HAS(AW_F_ENERGY) || AW_HAS(AW_F_TRAJECTORIES)) fx->e0 = aw_energy(s, rp);
  aw_tangent_begin(&fx->tangent, rp); /* a few stores; every field defined for the run-time bits of the cpu backend */
  for (int c = 0; c < 3; ++c) fx->asum[c] = AW_LSPLAT(AW_R(0.0));
  if (AW_HAS(AW_F_DIFFUSION)) aw_actions_store(s->px, s->py, s->pz, 0, l, ip, out);
  if (AW_HAS(AW_F_TRAJECTORIES)) aw_trajectories_store(s, fx->e0, 0, l, rp, ip, out);
}

/* The force at the initial state (and, with the indicators, the Hessian). */
AW_FN void aw_fx_first_force(aw_config cfg, aw_fx* fx, aw_lstate* s, AW_CONSTANT aw_rparams* rp) {
  if (AW_HAS(AW_F_TANGENT))
    aw_tangent_force(s, &fx->tangent, rp);
  else
    aw_force(s, rp);
}

/* One segment of steps: the plain stepper, or with the indicators the same
 * steps carrying the tangent vector (aw_tangent.h). */
AW_FN void aw_fx_segment(aw_config cfg, aw_fx* fx, aw_lstate* s, aw_i64 nsteps, AW_CONSTANT aw_rparams* rp) {
  if (AW_HAS(AW_F_TANGENT))
    aw_segment_tangent(cfg, s, &fx->tangent, nsteps, rp);
  else
    aw_segment(s, nsteps, rp, cfg.stages, cfg.kick_first, cfg.gradient);
}

/* The sample counts at the first segment of a launch, seg_first. */
AW_FN void aw_fx_counts_begin(aw_config cfg, aw_fx* fx, aw_i64 seg_first, AW_CONSTANT aw_iparams* ip) {
  if (AW_HAS(AW_F_ENERGY)) fx->energy_at = aw_count_at(seg_first, ip->energy_stride);
  if (AW_HAS(AW_F_FREQUENCIES)) fx->frequency_at = aw_count_at(seg_first, ip->frequency_stride);
  if (AW_HAS(AW_F_DIFFUSION)) fx->actions_at = aw_count_at(seg_first, ip->diffusion_stride);
  if (AW_HAS(AW_F_TRAJECTORIES)) fx->picks_at = aw_count_at(seg_first, ip->pick_stride);
}

AW_FN void aw_fx_window_begin(aw_config cfg, aw_fx* fx) { fx->over = AW_LSPLAT(AW_R(0.0)); }

/* After every segment (the counts begun by aw_fx_counts_begin say which
 * samples are due). */
AW_FN void aw_fx_sample(aw_config cfg, aw_fx* fx, const aw_lstate* s, aw_lanes l, AW_CONSTANT aw_rparams* rp,
                        AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  if (AW_HAS(AW_F_ENERGY)) {
    aw_count_next(&fx->energy_at, ip->energy_stride);
    if (fx->energy_at.r == 0) aw_energy_sample(s, rp, fx->e0, &fx->emax, &fx->over, AW_HAS(AW_F_ENERGY_LIMIT));
  }
  if (AW_HAS(AW_F_CONFINE)) fx->inside = fx->inside * aw_in_region(&rp->confine, s->px, s->py, s->pz);
  if (AW_HAS(AW_F_FREQUENCIES)) {
    aw_count_next(&fx->frequency_at, ip->frequency_stride);
    const aw_i64 q = fx->frequency_at.q - 1;
    if (fx->frequency_at.r == 0 && q < 2 * ip->frequency_samples) aw_freq_sample(s, fx->status, (int)q, l, ip, out);
  }
  if (AW_HAS(AW_F_DIFFUSION)) {
    aw_count_next(&fx->actions_at, ip->diffusion_stride);
    aw_actions_sample(fx->asum, s, fx->actions_at, l, rp, ip, out);
  }
  if (AW_HAS(AW_F_TRAJECTORIES)) {
    aw_count_next(&fx->picks_at, ip->pick_stride);
    if (fx->picks_at.r == 0 && fx->picks_at.q <= ip->pick_samples)
      aw_trajectories_store(s, fx->e0, fx->picks_at.q, l, rp, ip, out);
  }
}

/* The end of window w: (dx, dy, dz) the displacement over it in turns, sane
 * 1 where the state is finite. A lane is flagged (non-finite, energy) or
 * leaves the region here; otherwise its displacement is binned. */
AW_FN void aw_fx_window_end(aw_config cfg, aw_fx* fx, aw_i64 w, lreal dx, lreal dy, lreal dz, lreal sane, aw_lanes l,
                            AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  real ax[AW_LANES], ay[AW_LANES], az[AW_LANES], asane[AW_LANES], aover[AW_LANES], ain[AW_LANES];
  AW_STORE_LANES(dx, ax);
  AW_STORE_LANES(dy, ay);
  AW_STORE_LANES(dz, az);
  AW_STORE_LANES(sane, asane);
  AW_STORE_LANES(fx->over, aover);
  AW_STORE_LANES(fx->inside, ain);
  const int frame = AW_HAS(AW_F_FRAMES) ? aw_frame_of(ip, w) : 0;
  for (int j = 0; j < AW_LANES; ++j) {
    if (fx->status[j] != AW_STATUS_OK || !AW_LANE_ACTIVE(l, j)) continue;
    if (asane[j] == AW_R(0.0)) {
      fx->status[j] = AW_STATUS_NONFINITE;
    } else if (aover[j] != AW_R(0.0)) {
      fx->status[j] = AW_STATUS_ENERGY;
    } else if (AW_HAS(AW_F_CONFINE) && ain[j] == AW_R(0.0)) {
      fx->status[j] = AW_STATUS_LEFT_REGION;
    } else {
      aw_bin_window(cfg, rp, ip, out, frame, ax[j], ay[j], az[j]);
    }
  }
}

/* After the run: every lane's status counted; with energy_error its max |dE|
 * in the histogram and, for binned lanes, in this item's (max, sum), which
 * the caller reduces over the work-group; the final state records. */
AW_FN void aw_fx_finish(aw_config cfg, aw_fx* fx, const aw_lstate* s, aw_lanes l, aw_outputs out, real* emax,
                        real* esum, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip) {
  real amax[AW_LANES];
  AW_STORE_LANES(fx->emax, amax);
  *emax = AW_R(0.0);
  *esum = AW_R(0.0);
  for (int j = 0; j < AW_LANES; ++j) {
    if (!AW_LANE_ACTIVE(l, j)) continue;
    const int st = fx->status[j];
    AW_ATOMIC_INC(&out.counters[st == AW_STATUS_OK ? AW_C_BINNED : st]);
    if (AW_HAS(AW_F_ENERGY)) {
      AW_ATOMIC_INC(&out.counters[AW_C_EHIST + aw_energy_bin(amax[j])]);
      if (st == AW_STATUS_OK) {
        *emax = (amax[j] > *emax) ? amax[j] : *emax;
        *esum += amax[j];
      }
    }
    const aw_u64 rec = AW_LANE_RECORD(l, j);
    if (AW_HAS(AW_F_FINAL_STATES)) {
      aw_store_state_reals(aw_record_r(out, ip, AW_OUT_FINAL_STATE, rec), s, j);
      aw_store_state_ints(aw_record_i(out, ip, AW_OUT_FINAL_STATE, rec), s, j, st);
    }
    if (AW_HAS(AW_F_TANGENT))
      aw_store_indicators(cfg, aw_record_r(out, ip, AW_OUT_INDICATORS, rec), &fx->tangent, j,
                          st == AW_STATUS_OK || st == AW_STATUS_LEFT_REGION, rp);
    if (AW_HAS(AW_F_DIFFUSION)) aw_record_i(out, ip, AW_OUT_ACTIONS, rec)[0] = st;
  }
}

#endif /* AW_EFFECTS_H */
