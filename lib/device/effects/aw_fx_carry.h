/* arnoldweb effect "carry" (open runs): a trajectory's whole state in its
 * carry record (aw_params.h: AW_OUT_CARRY, AW_CARRY_*), so that a launch can
 * start where another stopped:
 *   - a time slice that does not finish the trajectories saves everything
 *     the next one needs (state, windings, every effect's state, the start of
 *     the averaging window in progress); the next loads it. Where each
 *     effect's state goes: aw_params.h, AW_CARRY_*. The force (and
 *     the Hessian) at the saved position are computed again, from the same
 *     position: the same bits as if the run had gone on.
 *   - ensemble.initial = "file" starts from the state the host put in the
 *     record (position, momentum, windings, status).
 * Per lane; idle lanes read zeros and write nothing. */
/* What the host reads too (plain macros, gathered by the generated
 * effects/aw_effect_declarations.h that aw_params.h includes). */
#ifndef AW_FX_CARRY_DECLARATIONS
#define AW_FX_CARRY_DECLARATIONS
/* open runs (docs/scenes.md, "Open runs"): a launch may start trajectories
 * from states given in their records (ensemble.initial = "file") and stop
 * them at a time slice, leaving in their records all it needs to go on */
#define AW_F_CARRY 0x4000u
#define AW_OUT_CARRY 3 /* AW_CARRY_REALS reals, AW_CARRY_INTS integers: in and out (aw_params.h) */
#endif

#if !defined(AW_EFFECT_DECLARATIONS_ONLY) && !defined(AW_FX_CARRY_H)
#define AW_FX_CARRY_H

#include "effects/aw_effects.h"

/* The state at the start of the averaging window in progress. */
typedef struct {
  lreal ux, uy, uz;
  lint wx, wy, wz;
} aw_window_start;

/* Position (turns, wrapped), momentum and windings from the record; the
 * statuses into status[]. */
AW_FN void aw_carry_load_state(aw_lstate* s, int* status, aw_outputs out, AW_CONSTANT aw_iparams* ip, aw_lanes l) {
  s->ux = aw_carry_get(out, ip, l, 0);
  s->uy = aw_carry_get(out, ip, l, 1);
  s->uz = aw_carry_get(out, ip, l, 2);
  s->px = aw_carry_get(out, ip, l, 3);
  s->py = aw_carry_get(out, ip, l, 4);
  s->pz = aw_carry_get(out, ip, l, 5);
  s->wx = aw_carry_geti(out, ip, l, 0);
  s->wy = aw_carry_geti(out, ip, l, 1);
  s->wz = aw_carry_geti(out, ip, l, 2);
  for (int j = 0; j < AW_LANES; ++j)
    status[j] = AW_LANE_ACTIVE(l, j) ? (int)aw_record_i(out, ip, AW_OUT_CARRY, AW_LANE_RECORD(l, j))[3] : AW_STATUS_OK;
}

/* Everything after a time slice, saved (the state, the statuses, E(0), the
 * window's start, and every effect's state through its carry_save hook);
 * loaded again by aw_carry_load. */
AW_FN void aw_carry_save(aw_config cfg, const aw_lstate* s, aw_fx* fx, const aw_window_start* ws, aw_outputs out,
                         AW_CONSTANT aw_iparams* ip, aw_lanes l) {
  const lreal r[6] = {s->ux, s->uy, s->uz, s->px, s->py, s->pz};
  for (int c = 0; c < 6; ++c) aw_carry_put(out, ip, l, c, r[c]);
  aw_carry_put(out, ip, l, AW_CARRY_ENERGY, fx->core.e0);
  aw_carry_put(out, ip, l, AW_CARRY_WINDOW + 0, ws->ux);
  aw_carry_put(out, ip, l, AW_CARRY_WINDOW + 1, ws->uy);
  aw_carry_put(out, ip, l, AW_CARRY_WINDOW + 2, ws->uz);
  const lint w[6] = {s->wx, s->wy, s->wz, ws->wx, ws->wy, ws->wz};
  for (int c = 0; c < 3; ++c) aw_carry_puti(out, ip, l, c, w[c]);
  for (int c = 0; c < 3; ++c) aw_carry_puti(out, ip, l, AW_CARRY_INTS - 4 + c, w[3 + c]);
  for (int j = 0; j < AW_LANES; ++j)
    if (AW_LANE_ACTIVE(l, j)) aw_record_i(out, ip, AW_OUT_CARRY, AW_LANE_RECORD(l, j))[3] = fx->core.status[j];
  aw_fx_effects_carry_save(cfg, fx, out, ip, l);
}

AW_FN void aw_carry_load(aw_config cfg, aw_lstate* s, aw_fx* fx, aw_window_start* ws, aw_outputs out,
                         AW_CONSTANT aw_iparams* ip, aw_lanes l) {
  aw_carry_load_state(s, fx->core.status, out, ip, l);
  fx->core.e0 = aw_carry_get(out, ip, l, AW_CARRY_ENERGY);
  ws->ux = aw_carry_get(out, ip, l, AW_CARRY_WINDOW + 0);
  ws->uy = aw_carry_get(out, ip, l, AW_CARRY_WINDOW + 1);
  ws->uz = aw_carry_get(out, ip, l, AW_CARRY_WINDOW + 2);
  ws->wx = aw_carry_geti(out, ip, l, AW_CARRY_INTS - 4);
  ws->wy = aw_carry_geti(out, ip, l, AW_CARRY_INTS - 3);
  ws->wz = aw_carry_geti(out, ip, l, AW_CARRY_INTS - 2);
  aw_fx_effects_carry_load(cfg, fx, out, ip, l);
}

#endif /* AW_FX_CARRY_H */
