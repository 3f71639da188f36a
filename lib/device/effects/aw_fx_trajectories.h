/* arnoldweb effect "trajectories" (observe.trajectories): the state and the
 * energy error E(t) - E(0) of a few picked trajectories at t = 0 and at the
 * end of every ip->pick_stride segments, as picked records (aw_params.h: in
 * the histogram buffer, indexed by the pick, so that their memory is the
 * picks' and not the ensemble's). A lane writes only when its trajectory is
 * one of ip->pick_ids (increasing: a binary search, at sample times only). */
/* What the host reads too (plain macros, gathered by the generated
 * effects/aw_effect_declarations.h that aw_params.h includes). */
#ifndef AW_FX_TRAJECTORIES_DECLARATIONS
#define AW_FX_TRAJECTORIES_DECLARATIONS
#define AW_F_TRAJECTORIES 0x20000u /* the sampled states of chosen trajectories (observe.trajectories) */
#define AW_OUT_TRAJECTORIES 6      /* picked: AW_PICK_REALS reals, AW_PICK_INTS integers per sample */
/* Picked records: a record per sample of each picked trajectory (at most
 * AW_MAX_PICKS, ip->pick_ids), not per trajectory: they lie in the histogram
 * buffer after the maps and the zoom, from word ip->pick_base on, each value
 * in two 32-bit words (a real's bits in the kernel's precision, low word
 * first; an integer's 64 bits), written once by the trajectory's work-item
 * and folded, summed and checkpointed with the counts (only the trajectory's
 * own launch writes a nonzero word: the sums are its bits). Record (k, q) of
 * pick k, sample q: u_x u_y u_z (turns, wrapped) p_x p_y p_z E(t) - E(0) |
 * winding x y z. */
#define AW_MAX_PICKS 1024
#define AW_PICK_REALS 7
#define AW_PICK_INTS 3
#define AW_FX_TRAJECTORIES_IPARAMS                                                             \
  aw_i64 pick_count;   /* picked trajectories: pick_ids[0 .. pick_count), increasing */         \
  aw_i64 pick_stride;  /* segments between two samples */                                      \
  aw_i64 pick_samples; /* S: samples after t = 0 */                                            \
  aw_i64 pick_base;    /* their first word in the histogram buffer (even) */                    \
  aw_i64 pick_ids[AW_MAX_PICKS];
#endif

#if !defined(AW_EFFECT_DECLARATIONS_ONLY) && !defined(AW_FX_TRAJECTORIES_H)
#define AW_FX_TRAJECTORIES_H

#include "aw_model.h"
#include "effects/aw_fx_common.h"

AW_EFFECT_ORDER(80)

/* The position of trajectory g among the picks, or -1. */
AW_FN aw_i64 aw_pick_of(AW_CONSTANT aw_iparams* ip, aw_u64 g) {
  aw_i64 lo = 0, hi = ip->pick_count; /* the pick, if any, is in [lo, hi) */
  while (lo < hi) {
    const aw_i64 mid = lo + (hi - lo) / 2;
    const aw_u64 v = (aw_u64)ip->pick_ids[mid];
    if (v == g) return mid;
    if (v < g)
      lo = mid + 1;
    else
      hi = mid;
  }
  return -1;
}

/* Sample q (0: t = 0) of the lanes that are picked: state s, energy error
 * E(s) - e0 (0 at q = 0), the energy evaluated only where a lane is picked. */
AW_FN void aw_trajectories_store(const aw_lstate* s, lreal e0, aw_i64 q, aw_lanes l, AW_CONSTANT aw_rparams* rp,
                                 AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  real r[AW_PICK_REALS][AW_LANES];
  aw_i64 w[AW_PICK_INTS][AW_LANES];
  int stored = 0;
  for (int j = 0; j < AW_LANES; ++j) {
    if (!AW_LANE_ACTIVE(l, j)) continue;
    const aw_i64 k = aw_pick_of(ip, l.first + (aw_u64)j);
    if (k < 0) continue;
    if (!stored) { /* the lanes' values, once per work-item and sample */
      const lreal de = (q == 0) ? AW_LSPLAT(AW_R(0.0)) : aw_energy(s, rp) - e0;
      AW_STORE_LANES(s->ux, r[0]);
      AW_STORE_LANES(s->uy, r[1]);
      AW_STORE_LANES(s->uz, r[2]);
      AW_STORE_LANES(s->px, r[3]);
      AW_STORE_LANES(s->py, r[4]);
      AW_STORE_LANES(s->pz, r[5]);
      AW_STORE_LANES(de, r[6]);
      AW_STORE_ILANES(s->wx, w[0]);
      AW_STORE_ILANES(s->wy, w[1]);
      AW_STORE_ILANES(s->wz, w[2]);
      stored = 1;
    }
    /* two words per value: a real in the low word's place (its own size), an integer in both */
    AW_GLOBAL aw_u32* at =
        out.hist + (aw_u64)ip->pick_base + (aw_u64)(2 * (AW_PICK_REALS + AW_PICK_INTS)) * (aw_u64)(k * (ip->pick_samples + 1) + q);
    for (int c = 0; c < AW_PICK_REALS; ++c) *(AW_GLOBAL real*)(at + 2 * c) = r[c][j];
    for (int c = 0; c < AW_PICK_INTS; ++c) *(AW_GLOBAL aw_i64*)(at + 2 * (AW_PICK_REALS + c)) = w[c][j];
  }
}

typedef struct {
  aw_count sample_at; /* (k + 1) / stride and its remainder after segment k */
} aw_fx_trajectories_state;

/* Sample 0, the start (its energy error is 0 by definition: E(0) is not read). */
AW_FN void aw_fx_trajectories_begin(aw_config cfg, aw_fx_trajectories_state* me, aw_fx_core* fx, aw_lstate* s,
                                    aw_lanes l, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip,
                                    aw_outputs out) {
  if (AW_HAS(AW_F_TRAJECTORIES)) aw_trajectories_store(s, fx->e0, 0, l, rp, ip, out);
}

AW_FN void aw_fx_trajectories_counts(aw_config cfg, aw_fx_trajectories_state* me, aw_fx_core* fx, aw_i64 seg_first,
                                     AW_CONSTANT aw_iparams* ip) {
  if (AW_HAS(AW_F_TRAJECTORIES)) me->sample_at = aw_count_at(seg_first, ip->pick_stride);
}

AW_FN void aw_fx_trajectories_sample(aw_config cfg, aw_fx_trajectories_state* me, aw_fx_core* fx,
                                     const aw_lstate* s, aw_lanes l, AW_CONSTANT aw_rparams* rp,
                                     AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  if (!AW_HAS(AW_F_TRAJECTORIES)) return;
  aw_count_next(&me->sample_at, ip->pick_stride);
  if (me->sample_at.r == 0 && me->sample_at.q <= ip->pick_samples)
    aw_trajectories_store(s, fx->e0, me->sample_at.q, l, rp, ip, out);
}

#endif /* AW_FX_TRAJECTORIES_H */
