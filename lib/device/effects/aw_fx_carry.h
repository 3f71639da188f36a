/* arnoldweb effect "carry" (open runs): a trajectory's whole state in its
 * carry record (aw_params.h: AW_OUT_CARRY, AW_CARRY_*), so that a launch can
 * start where another stopped:
 *   - a time slice that does not finish the trajectories saves everything
 *     the next one needs (state, windings, every effect's state, the start of
 *     the averaging window in progress); the next loads it. The force (and
 *     the Hessian) at the saved position are computed again, from the same
 *     position: the same bits as if the run had gone on.
 *   - ensemble.initial = "file" starts from the state the host put in the
 *     record (position, momentum, windings, status).
 * Per lane; idle lanes read zeros and write nothing. */
#ifndef AW_FX_CARRY_H
#define AW_FX_CARRY_H

#include "effects/aw_effects.h"

/* The state at the start of the averaging window in progress. */
typedef struct {
  lreal ux, uy, uz;
  lint wx, wy, wz;
} aw_window_start;

AW_FN lreal aw_carry_get(aw_outputs out, AW_CONSTANT aw_iparams* ip, aw_lanes l, int c) {
  real a[AW_LANES];
  for (int j = 0; j < AW_LANES; ++j)
    a[j] = AW_LANE_ACTIVE(l, j) ? aw_record_r(out, ip, AW_OUT_CARRY, AW_LANE_RECORD(l, j))[c] : AW_R(0.0);
  return AW_LOAD_LANES(a);
}

AW_FN lint aw_carry_geti(aw_outputs out, AW_CONSTANT aw_iparams* ip, aw_lanes l, int c) {
  aw_i64 a[AW_LANES];
  for (int j = 0; j < AW_LANES; ++j)
    a[j] = AW_LANE_ACTIVE(l, j) ? aw_record_i(out, ip, AW_OUT_CARRY, AW_LANE_RECORD(l, j))[c] : 0;
  return AW_LOAD_ILANES(a);
}

AW_FN void aw_carry_put(aw_outputs out, AW_CONSTANT aw_iparams* ip, aw_lanes l, int c, lreal v) {
  real a[AW_LANES];
  AW_STORE_LANES(v, a);
  for (int j = 0; j < AW_LANES; ++j)
    if (AW_LANE_ACTIVE(l, j)) aw_record_r(out, ip, AW_OUT_CARRY, AW_LANE_RECORD(l, j))[c] = a[j];
}

AW_FN void aw_carry_puti(aw_outputs out, AW_CONSTANT aw_iparams* ip, aw_lanes l, int c, lint v) {
  aw_i64 a[AW_LANES];
  AW_STORE_ILANES(v, a);
  for (int j = 0; j < AW_LANES; ++j)
    if (AW_LANE_ACTIVE(l, j)) aw_record_i(out, ip, AW_OUT_CARRY, AW_LANE_RECORD(l, j))[c] = a[j];
}

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

/* Everything after a time slice, saved; loaded again by aw_carry_load. */
AW_FN void aw_carry_save(const aw_lstate* s, const aw_fx* fx, const aw_window_start* ws, aw_outputs out,
                         AW_CONSTANT aw_iparams* ip, aw_lanes l) {
  const lreal r[AW_CARRY_REALS] = {s->ux, s->uy, s->uz, s->px, s->py, s->pz,
                                   fx->e0, fx->emax, fx->over, fx->inside,
                                   ws->ux, ws->uy, ws->uz,
                                   fx->tangent.qx, fx->tangent.qy, fx->tangent.qz,
                                   fx->tangent.px, fx->tangent.py, fx->tangent.pz,
                                   fx->tangent.log2w, fx->tangent.max_n2, fx->tangent.s1,
                                   fx->tangent.ysum, fx->tangent.mean_y, fx->tangent.cov, fx->tangent.prev_n2};
  for (int c = 0; c < AW_CARRY_REALS; ++c) aw_carry_put(out, ip, l, c, r[c]);
  const lint w[6] = {s->wx, s->wy, s->wz, ws->wx, ws->wy, ws->wz};
  for (int c = 0; c < 3; ++c) aw_carry_puti(out, ip, l, c, w[c]);
  for (int c = 0; c < 3; ++c) aw_carry_puti(out, ip, l, AW_CARRY_INTS - 4 + c, w[3 + c]);
  for (int j = 0; j < AW_LANES; ++j)
    if (AW_LANE_ACTIVE(l, j)) {
      AW_GLOBAL aw_i64* i = aw_record_i(out, ip, AW_OUT_CARRY, AW_LANE_RECORD(l, j));
      i[3] = fx->status[j];
      i[AW_CARRY_INTS - 1] = fx->tangent.steps;
    }
}

AW_FN void aw_carry_load(aw_lstate* s, aw_fx* fx, aw_window_start* ws, aw_outputs out, AW_CONSTANT aw_iparams* ip,
                         aw_lanes l) {
  aw_carry_load_state(s, fx->status, out, ip, l);
  fx->e0 = aw_carry_get(out, ip, l, AW_CARRY_ENERGY + 0);
  fx->emax = aw_carry_get(out, ip, l, AW_CARRY_ENERGY + 1);
  fx->over = aw_carry_get(out, ip, l, AW_CARRY_ENERGY + 2);
  fx->inside = aw_carry_get(out, ip, l, AW_CARRY_ENERGY + 3);
  ws->ux = aw_carry_get(out, ip, l, AW_CARRY_WINDOW + 0);
  ws->uy = aw_carry_get(out, ip, l, AW_CARRY_WINDOW + 1);
  ws->uz = aw_carry_get(out, ip, l, AW_CARRY_WINDOW + 2);
  ws->wx = aw_carry_geti(out, ip, l, AW_CARRY_INTS - 4);
  ws->wy = aw_carry_geti(out, ip, l, AW_CARRY_INTS - 3);
  ws->wz = aw_carry_geti(out, ip, l, AW_CARRY_INTS - 2);
  aw_tangent* t = &fx->tangent;
  t->qx = aw_carry_get(out, ip, l, AW_CARRY_TANGENT + 0);
  t->qy = aw_carry_get(out, ip, l, AW_CARRY_TANGENT + 1);
  t->qz = aw_carry_get(out, ip, l, AW_CARRY_TANGENT + 2);
  t->px = aw_carry_get(out, ip, l, AW_CARRY_TANGENT + 3);
  t->py = aw_carry_get(out, ip, l, AW_CARRY_TANGENT + 4);
  t->pz = aw_carry_get(out, ip, l, AW_CARRY_TANGENT + 5);
  t->log2w = aw_carry_get(out, ip, l, AW_CARRY_TANGENT + 6);
  t->max_n2 = aw_carry_get(out, ip, l, AW_CARRY_TANGENT + 7);
  t->s1 = aw_carry_get(out, ip, l, AW_CARRY_TANGENT + 8);
  t->ysum = aw_carry_get(out, ip, l, AW_CARRY_TANGENT + 9);
  t->mean_y = aw_carry_get(out, ip, l, AW_CARRY_TANGENT + 10);
  t->cov = aw_carry_get(out, ip, l, AW_CARRY_TANGENT + 11);
  t->prev_n2 = aw_carry_get(out, ip, l, AW_CARRY_TANGENT + 12);
  t->steps = 0;
  for (int j = 0; j < AW_LANES; ++j)
    if (AW_LANE_ACTIVE(l, j)) t->steps = aw_record_i(out, ip, AW_OUT_CARRY, AW_LANE_RECORD(l, j))[AW_CARRY_INTS - 1];
  /* the diffusion's running mean restarts at every sample, and with averaging
   * a slice ends at a sample time (the planner's rule): nothing to carry */
  for (int c = 0; c < 3; ++c) fx->asum[c] = AW_LSPLAT(AW_R(0.0));
}

#endif /* AW_FX_CARRY_H */
