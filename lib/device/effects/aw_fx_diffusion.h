/* arnoldweb effect "diffusion" (observe.diffusion; docs/frequencies.md): the
 * actions of every trajectory at sample times, for the moments of their
 * displacement and the diffusion coefficient along a resonance (the host's
 * analysis, arnoldweb/diffusion.hpp). The actions are the momenta P (for fgl
 * the actions I; for the paper's model the momenta, its free actions).
 * The record (AW_OUT_ACTIONS): 3 (K + 1) reals, P at t = 0 and at the end of
 * every ip->diffusion_stride segments (K = ip->diffusion_samples), and one
 * integer, the trajectory's status at the end (a flagged one is left out).
 * With averaging (ip->diffusion_average_points m > 0) sample q >= 1 is the
 * mean of the actions at the m segment ends q D - j a, j = 0 .. m - 1 (D =
 * ip->diffusion_stride, a = ip->diffusion_average_stride, m a <= D): the
 * fast oscillations and the libration in a resonance average out. The sum
 * restarts at every sample, so a time slice that ends at a sample time
 * carries nothing (the planner asks for that). */
/* What the host reads too (plain macros, gathered by the generated
 * effects/aw_effect_declarations.h that aw_params.h includes). */
#ifndef AW_FX_DIFFUSION_DECLARATIONS
#define AW_FX_DIFFUSION_DECLARATIONS
#define AW_F_DIFFUSION 0x10000u /* action samples for diffusion (docs/frequencies.md) */
#define AW_OUT_ACTIONS 5        /* 3 (K + 1) reals, 1 integer */
#define AW_FX_DIFFUSION_RPARAMS real diffusion_average_weight; /* 1 / the actions averaged into a sample */
#define AW_FX_DIFFUSION_IPARAMS                                                                   \
  aw_i64 diffusion_stride;         /* segments between action samples */                          \
  aw_i64 diffusion_samples;        /* K: action samples after t = 0 */                            \
  aw_i64 diffusion_average_points; /* actions averaged into a sample (0: the actions at the sample time) */ \
  aw_i64 diffusion_average_stride; /* segments between two of them */
#endif

#if !defined(AW_EFFECT_DECLARATIONS_ONLY) && !defined(AW_FX_DIFFUSION_H)
#define AW_FX_DIFFUSION_H

#include "effects/aw_fx_common.h"

AW_EFFECT_ORDER(70)

/* Sample q (0: the start) of the lanes' actions (x, y, z). */
AW_FN void aw_actions_store(lreal x, lreal y, lreal z, aw_i64 q, aw_lanes l, AW_CONSTANT aw_iparams* ip,
                            aw_outputs out) {
  real px[AW_LANES], py[AW_LANES], pz[AW_LANES];
  AW_STORE_LANES(x, px);
  AW_STORE_LANES(y, py);
  AW_STORE_LANES(z, pz);
  for (int j = 0; j < AW_LANES; ++j) {
    if (!AW_LANE_ACTIVE(l, j)) continue;
    AW_GLOBAL real* r = aw_record_r(out, ip, AW_OUT_ACTIONS, AW_LANE_RECORD(l, j)) + 3 * q;
    r[0] = px[j];
    r[1] = py[j];
    r[2] = pz[j];
  }
}

/* After segment k (0-based; at = (k + 1) / D and its remainder r, D =
 * ip->diffusion_stride): the sample due at its end, or (averaging) the
 * actions added to the running sum `asum` when its end is one of the next
 * sample's points, and the mean stored at the sample. */
AW_FN void aw_actions_sample(lreal* asum, const aw_lstate* s, aw_count at, aw_lanes l, AW_CONSTANT aw_rparams* rp,
                             AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  const aw_i64 q = at.q, r = at.r;
  if (ip->diffusion_average_points == 0) {
    if (r == 0 && q <= ip->diffusion_samples) aw_actions_store(s->px, s->py, s->pz, q, l, ip, out);
    return;
  }
  const aw_i64 ahead = r == 0 ? 0 : ip->diffusion_stride - r; /* segments to the next sample */
  aw_i64 off;
  const aw_i64 j = aw_divrem(ahead, ip->diffusion_average_stride, &off);
  if (off == 0 && j < ip->diffusion_average_points) {
    asum[0] = asum[0] + s->px;
    asum[1] = asum[1] + s->py;
    asum[2] = asum[2] + s->pz;
  }
  if (r == 0 && q >= 1 && q <= ip->diffusion_samples) {
    const real w = rp->diffusion_average_weight;
    aw_actions_store(asum[0] * w, asum[1] * w, asum[2] * w, q, l, ip, out);
    for (int c = 0; c < 3; ++c) asum[c] = AW_LSPLAT(AW_R(0.0));
  }
}

typedef struct {
  lreal asum[3];      /* with averaging: the sum of the actions so far towards the next sample */
  aw_count sample_at; /* (k + 1) / stride and its remainder after segment k */
} aw_fx_diffusion_state;

AW_FN void aw_fx_diffusion_begin(aw_config cfg, aw_fx_diffusion_state* me, aw_fx_core* fx, aw_lstate* s, aw_lanes l,
                                 AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  for (int c = 0; c < 3; ++c) me->asum[c] = AW_LSPLAT(AW_R(0.0));
  if (AW_HAS(AW_F_DIFFUSION)) aw_actions_store(s->px, s->py, s->pz, 0, l, ip, out);
}

AW_FN void aw_fx_diffusion_counts(aw_config cfg, aw_fx_diffusion_state* me, aw_fx_core* fx, aw_i64 seg_first,
                                  AW_CONSTANT aw_iparams* ip) {
  if (AW_HAS(AW_F_DIFFUSION)) me->sample_at = aw_count_at(seg_first, ip->diffusion_stride);
}

AW_FN void aw_fx_diffusion_sample(aw_config cfg, aw_fx_diffusion_state* me, aw_fx_core* fx, const aw_lstate* s,
                                  aw_lanes l, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  if (!AW_HAS(AW_F_DIFFUSION)) return;
  aw_count_next(&me->sample_at, ip->diffusion_stride);
  aw_actions_sample(me->asum, s, me->sample_at, l, rp, ip, out);
}

/* The status at the end: a flagged trajectory is left out of the moments. */
AW_FN void aw_fx_diffusion_finish(aw_config cfg, aw_fx_diffusion_state* me, aw_fx_core* fx, aw_lstate* s, aw_lanes l,
                                  AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  if (!AW_HAS(AW_F_DIFFUSION)) return;
  for (int j = 0; j < AW_LANES; ++j)
    if (AW_LANE_ACTIVE(l, j)) aw_record_i(out, ip, AW_OUT_ACTIONS, AW_LANE_RECORD(l, j))[0] = fx->status[j];
}

/* The running mean restarts at every sample, and with averaging a slice ends
 * at a sample time (the planner's rule): nothing to carry. */
AW_FN void aw_fx_diffusion_carry_load(aw_config cfg, aw_fx_diffusion_state* me, aw_fx_core* fx, aw_outputs out,
                                      AW_CONSTANT aw_iparams* ip, aw_lanes l) {
  for (int c = 0; c < 3; ++c) me->asum[c] = AW_LSPLAT(AW_R(0.0));
}

#endif /* AW_FX_DIFFUSION_H */
