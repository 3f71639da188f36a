/* arnoldweb effects "energy_error", "max_energy_error" and "energy_errors":
 * |E(t) - E(0)| at every sample; its maximum per trajectory goes into a log2
 * histogram and the work-group statistics (and with observe.energy_errors into
 * the trajectory's record); above observe.max_energy_error a trajectory is
 * flagged at the end of the window. */
/* What the host reads too (plain macros, gathered by the generated
 * effects/aw_effect_declarations.h that aw_params.h includes). */
#ifndef AW_FX_ENERGY_DECLARATIONS
#define AW_FX_ENERGY_DECLARATIONS
#define AW_F_ENERGY 0x2u       /* track |E(t) - E(0)| at every sample */
#define AW_F_ENERGY_LIMIT 0x4u /* flag trajectories above a threshold */
#define AW_F_ENERGY_ERRORS 0x40000u /* write every trajectory's max |dE| (observe.energy_errors) */
#define AW_OUT_ENERGY_ERRORS 7      /* 1 real: the trajectory's max |dE| over the energy samples */
#define AW_FX_ENERGY_RPARAMS real energy_limit; /* flag when |dE| exceeds this */
#define AW_FX_ENERGY_IPARAMS aw_i64 energy_stride; /* segments between energy samples (1: every segment) */
#endif

#if !defined(AW_EFFECT_DECLARATIONS_ONLY) && !defined(AW_FX_ENERGY_H)
#define AW_FX_ENERGY_H

#include "aw_model.h"
#include "effects/aw_fx_common.h"

AW_EFFECT_ORDER(30)

/* Bin of the log2 histogram of an energy error e >= 0 (or NaN: last bin). */
AW_FN int aw_energy_bin(real e) {
  if (!(e < AW_R(65536.0))) return AW_EHIST_BINS - 1; /* >= 2^16, Inf, NaN */
  if (e < AW_R(5.421010862427522e-20)) return 0;      /* < 2^-64, zero */
  int ex;
  real m = AW_FREXP(e, &ex); /* e = m 2^ex, m in [1/2, 1) */
  int quarter = (int)((m - AW_R(0.5)) * AW_R(8.0));
  return 1 + (ex - 1 - AW_EHIST_MIN_EXP) * AW_EHIST_BINS_PER_OCTAVE + quarter;
}

/* At a sample: the error, its running maximum, and whether it is over the
 * limit (kept until the end of the window). */
AW_FN void aw_energy_sample(const aw_lstate* s, AW_CONSTANT aw_rparams* rp, lreal e0, lreal* emax, lreal* over,
                            int limit) {
  lreal de = AW_FABS(aw_energy(s, rp) - e0);
  *emax = AW_SELECT(*emax, de, de > *emax);
  if (limit) *over = AW_SELECT(*over, AW_LSPLAT(AW_R(1.0)), de > rp->energy_limit);
}

typedef struct {
  lreal emax;        /* max |dE| so far */
  lreal over;        /* max_energy_error: 1 where |dE| exceeded the limit in this window */
  aw_count sample_at; /* (k + 1) / stride and its remainder after segment k (no division per segment) */
} aw_fx_energy_state;

AW_FN void aw_fx_energy_begin(aw_config cfg, aw_fx_energy_state* me, aw_fx_core* fx, aw_lstate* s, aw_lanes l,
                              AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  me->emax = AW_LSPLAT(AW_R(0.0));
  me->over = AW_LSPLAT(AW_R(0.0));
}

AW_FN void aw_fx_energy_counts(aw_config cfg, aw_fx_energy_state* me, aw_fx_core* fx, aw_i64 seg_first,
                               AW_CONSTANT aw_iparams* ip) {
  if (AW_HAS(AW_F_ENERGY)) me->sample_at = aw_count_at(seg_first, ip->energy_stride);
}

AW_FN void aw_fx_energy_window_begin(aw_config cfg, aw_fx_energy_state* me, aw_fx_core* fx) {
  me->over = AW_LSPLAT(AW_R(0.0));
}

AW_FN void aw_fx_energy_sample(aw_config cfg, aw_fx_energy_state* me, aw_fx_core* fx, const aw_lstate* s,
                               aw_lanes l, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  if (!AW_HAS(AW_F_ENERGY)) return;
  aw_count_next(&me->sample_at, ip->energy_stride);
  if (me->sample_at.r == 0) aw_energy_sample(s, rp, fx->e0, &me->emax, &me->over, AW_HAS(AW_F_ENERGY_LIMIT));
}

/* At the end of a window: over the limit in it (a lane not flagged before). */
AW_FN void aw_fx_energy_flag(aw_config cfg, aw_fx_energy_state* me, aw_fx_core* fx, int* flag) {
  real aover[AW_LANES];
  AW_STORE_LANES(me->over, aover);
  for (int j = 0; j < AW_LANES; ++j)
    if (flag[j] == AW_STATUS_OK && aover[j] != AW_R(0.0)) flag[j] = AW_STATUS_ENERGY;
}

/* Every lane's max|dE| in the histogram (and, asked for, in its record); the
 * binned lanes' maximum and sum. */
AW_FN void aw_fx_energy_finish(aw_config cfg, aw_fx_energy_state* me, aw_fx_core* fx, aw_lstate* s, aw_lanes l,
                               AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  if (!AW_HAS(AW_F_ENERGY)) return;
  real amax[AW_LANES];
  AW_STORE_LANES(me->emax, amax);
  for (int j = 0; j < AW_LANES; ++j) {
    if (!AW_LANE_ACTIVE(l, j)) continue;
    AW_ATOMIC_INC(&out.counters[AW_C_EHIST + aw_energy_bin(amax[j])]);
    if (AW_HAS(AW_F_ENERGY_ERRORS)) aw_record_r(out, ip, AW_OUT_ENERGY_ERRORS, AW_LANE_RECORD(l, j))[0] = amax[j];
    if (fx->status[j] == AW_STATUS_OK) {
      fx->binned_emax = (amax[j] > fx->binned_emax) ? amax[j] : fx->binned_emax;
      fx->binned_esum += amax[j];
    }
  }
}

AW_FN void aw_fx_energy_carry_save(aw_config cfg, aw_fx_energy_state* me, aw_fx_core* fx, aw_outputs out,
                                   AW_CONSTANT aw_iparams* ip, aw_lanes l) {
  aw_carry_put(out, ip, l, AW_CARRY_ENERGY + 1, me->emax);
  aw_carry_put(out, ip, l, AW_CARRY_ENERGY + 2, me->over);
}

AW_FN void aw_fx_energy_carry_load(aw_config cfg, aw_fx_energy_state* me, aw_fx_core* fx, aw_outputs out,
                                   AW_CONSTANT aw_iparams* ip, aw_lanes l) {
  me->emax = aw_carry_get(out, ip, l, AW_CARRY_ENERGY + 1);
  me->over = aw_carry_get(out, ip, l, AW_CARRY_ENERGY + 2);
}

#endif /* AW_FX_ENERGY_H */
