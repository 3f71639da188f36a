/* arnoldweb test hooks: "test_inject" poisons one trajectory's momentum (the
 * flagging tests), "time_reversal" integrates back after the run (P -> -P,
 * the same steps again, P -> -P: back at the start, to rounding). Compiled in
 * only by the tests that ask for them. */
/* What the host reads too (plain macros, gathered by the generated
 * effects/aw_effect_declarations.h that aw_params.h includes). */
#ifndef AW_FX_TESTING_DECLARATIONS
#define AW_FX_TESTING_DECLARATIONS
#define AW_F_TEST_INJECT 0x20u /* test hook: poison one trajectory */
#define AW_F_REVERSE 0x200u    /* test of time reversibility: after the run, flip P,
                                  integrate as long again, flip P back (final states) */
#define AW_FX_TESTING_RPARAMS real inject_value; /* test hook: value added to p_x (NaN, Inf) */
#define AW_FX_TESTING_IPARAMS aw_i64 inject_index; /* test hook: the trajectory to poison */
#endif

#if !defined(AW_EFFECT_DECLARATIONS_ONLY) && !defined(AW_FX_TESTING_H)
#define AW_FX_TESTING_H

#include "aw_stepper.h"
#include "effects/aw_fx_common.h"

AW_EFFECT_ORDER(10) /* first: the injection changes the state every other effect sees */

AW_FN void aw_inject(aw_lstate* s, aw_lanes l, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip) {
  real tmp[AW_LANES];
  AW_STORE_LANES(s->px, tmp);
  for (int j = 0; j < AW_LANES; ++j)
    if (l.first + (aw_u64)j == (aw_u64)ip->inject_index) tmp[j] += rp->inject_value;
  s->px = AW_LOAD_LANES(tmp);
}

AW_FN void aw_reverse(aw_config cfg, aw_lstate* s, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip) {
  s->px = -s->px;
  s->py = -s->py;
  s->pz = -s->pz;
  for (aw_i64 w = 0; w < ip->windows; ++w)
    for (aw_i64 g = 0; g < ip->segments; ++g)
      aw_segment(s, ip->steps_per_segment, rp, cfg.stages, cfg.kick_first, cfg.gradient);
  s->px = -s->px;
  s->py = -s->py;
  s->pz = -s->pz;
}

AW_FN void aw_fx_testing_begin(aw_config cfg, aw_fx_core* fx, aw_lstate* s, aw_lanes l, AW_CONSTANT aw_rparams* rp,
                               AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  if (AW_HAS(AW_F_TEST_INJECT)) aw_inject(s, l, rp, ip);
}

AW_FN void aw_fx_testing_finish(aw_config cfg, aw_fx_core* fx, aw_lstate* s, aw_lanes l, AW_CONSTANT aw_rparams* rp,
                                AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  if (AW_HAS(AW_F_REVERSE)) aw_reverse(cfg, s, rp, ip);
}

#endif /* AW_FX_TESTING_H */
