/* arnoldweb effect "diffusion" (observe.diffusion; docs/frequencies.md): the
 * actions of every trajectory at sample times, for the moments of their
 * displacement and the diffusion coefficient along a resonance (the host's
 * analysis, arnoldweb/diffusion.hpp). The actions are the momenta P (for fgl
 * the actions I; for the paper's model the momenta, its free actions).
 * The record (AW_OUT_ACTIONS): 3 (K + 1) reals, P at t = 0 and at the end of
 * every ip->diffusion_stride segments (K = ip->diffusion_samples), and one
 * integer, the trajectory's status at the end (a flagged one is left out). */
#ifndef AW_FX_DIFFUSION_H
#define AW_FX_DIFFUSION_H

#include "effects/aw_fx_common.h"

/* Sample q (0: the start) of the lanes' momenta. */
AW_FN void aw_actions_store(const aw_lstate* s, aw_i64 q, aw_lanes l, AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  real px[AW_LANES], py[AW_LANES], pz[AW_LANES];
  AW_STORE_LANES(s->px, px);
  AW_STORE_LANES(s->py, py);
  AW_STORE_LANES(s->pz, pz);
  for (int j = 0; j < AW_LANES; ++j) {
    if (!AW_LANE_ACTIVE(l, j)) continue;
    AW_GLOBAL real* r = aw_record_r(out, ip, AW_OUT_ACTIONS, AW_LANE_RECORD(l, j)) + 3 * q;
    r[0] = px[j];
    r[1] = py[j];
    r[2] = pz[j];
  }
}

#endif /* AW_FX_DIFFUSION_H */
