/* arnoldweb effects "initial_states" and "final_states": the state of every
 * trajectory (aw_params.h: AW_STATE_REALS reals, AW_STATE_INTS integers) in
 * its record (slots AW_OUT_INITIAL_STATE, AW_OUT_FINAL_STATE). */
/* What the host reads too (plain macros, gathered by the generated
 * effects/aw_effect_declarations.h that aw_params.h includes). */
#ifndef AW_FX_STATES_DECLARATIONS
#define AW_FX_STATES_DECLARATIONS
#define AW_F_INITIAL_STATES 0x8u /* write initial states */
#define AW_F_FINAL_STATES 0x10u  /* write final states */
#define AW_OUT_INITIAL_STATE 0   /* AW_STATE_REALS reals */
#define AW_OUT_FINAL_STATE 1     /* AW_STATE_REALS reals, AW_STATE_INTS integers */
#endif

#if !defined(AW_EFFECT_DECLARATIONS_ONLY) && !defined(AW_FX_STATES_H)
#define AW_FX_STATES_H

#include "effects/aw_fx_common.h"

AW_EFFECT_ORDER(20)

/* Lane j's position (turns) and momentum into r[0..5]. */
AW_FN void aw_store_state_reals(AW_GLOBAL real* r, const aw_lstate* s, int j) {
  real a[AW_LANES];
  AW_STORE_LANES(s->ux, a); r[0] = a[j];
  AW_STORE_LANES(s->uy, a); r[1] = a[j];
  AW_STORE_LANES(s->uz, a); r[2] = a[j];
  AW_STORE_LANES(s->px, a); r[3] = a[j];
  AW_STORE_LANES(s->py, a); r[4] = a[j];
  AW_STORE_LANES(s->pz, a); r[5] = a[j];
}

/* Lane j's winding counts and status into i[0..3]. */
AW_FN void aw_store_state_ints(AW_GLOBAL aw_i64* i, const aw_lstate* s, int j, int status) {
  lint wv[3] = {s->wx, s->wy, s->wz};
  for (int c = 0; c < 3; ++c) {
    aw_i64 wa[AW_LANES];
    AW_STORE_ILANES(wv[c], wa);
    i[c] = wa[j];
  }
  i[3] = status;
}

/* The initial states, after the test hook (order 10) changed them. */
AW_FN void aw_fx_states_begin(aw_config cfg, aw_fx_core* fx, aw_lstate* s, aw_lanes l, AW_CONSTANT aw_rparams* rp,
                              AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  if (!AW_HAS(AW_F_INITIAL_STATES)) return;
  for (int j = 0; j < AW_LANES; ++j)
    if (AW_LANE_ACTIVE(l, j))
      aw_store_state_reals(aw_record_r(out, ip, AW_OUT_INITIAL_STATE, AW_LANE_RECORD(l, j)), s, j);
}

AW_FN void aw_fx_states_finish(aw_config cfg, aw_fx_core* fx, aw_lstate* s, aw_lanes l, AW_CONSTANT aw_rparams* rp,
                               AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  if (!AW_HAS(AW_F_FINAL_STATES)) return;
  for (int j = 0; j < AW_LANES; ++j) {
    if (!AW_LANE_ACTIVE(l, j)) continue;
    const aw_u64 rec = AW_LANE_RECORD(l, j);
    aw_store_state_reals(aw_record_r(out, ip, AW_OUT_FINAL_STATE, rec), s, j);
    aw_store_state_ints(aw_record_i(out, ip, AW_OUT_FINAL_STATE, rec), s, j, fx->status[j]);
  }
}

#endif /* AW_FX_STATES_H */
