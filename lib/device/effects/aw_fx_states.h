/* arnoldweb effects "initial_states" and "final_states": state records of
 * every trajectory (aw_params.h: AW_STATE_REALS reals, AW_STATE_INTS
 * integers), by index relative to the chunk's first trajectory. */
#ifndef AW_FX_STATES_H
#define AW_FX_STATES_H

#include "effects/aw_fx_common.h"

AW_FN void aw_store_states(AW_GLOBAL real* out, aw_u64 rec, const aw_lstate* s, int j) {
  real a[AW_LANES];
  AW_STORE_LANES(s->ux, a); out[rec * AW_STATE_REALS + 0] = a[j];
  AW_STORE_LANES(s->uy, a); out[rec * AW_STATE_REALS + 1] = a[j];
  AW_STORE_LANES(s->uz, a); out[rec * AW_STATE_REALS + 2] = a[j];
  AW_STORE_LANES(s->px, a); out[rec * AW_STATE_REALS + 3] = a[j];
  AW_STORE_LANES(s->py, a); out[rec * AW_STATE_REALS + 4] = a[j];
  AW_STORE_LANES(s->pz, a); out[rec * AW_STATE_REALS + 5] = a[j];
}

/* The final record of lane j: its state, winding counts and status. */
AW_FN void aw_store_final(aw_outputs out, aw_u64 rec, const aw_lstate* s, int j, int status) {
  aw_store_states(out.final_r, rec, s, j);
  lint wv[3] = {s->wx, s->wy, s->wz};
  for (int c = 0; c < 3; ++c) {
    aw_i64 wa[AW_LANES];
    AW_STORE_ILANES(wv[c], wa);
    out.final_i[rec * AW_STATE_INTS + c] = wa[j];
  }
  out.final_i[rec * AW_STATE_INTS + 3] = status;
}

#endif /* AW_FX_STATES_H */
