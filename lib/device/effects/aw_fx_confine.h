/* arnoldweb effect "confine" (observe.confine): only trajectories whose
 * momentum stays in a gnomonic square region of directions count; one that
 * leaves it at a sample is flagged AW_STATUS_LEFT_REGION at the end of its
 * window and binned no more. */
/* What the host reads too (plain macros, gathered by the generated
 * effects/aw_effect_declarations.h that aw_params.h includes). */
#ifndef AW_FX_CONFINE_DECLARATIONS
#define AW_FX_CONFINE_DECLARATIONS
#define AW_F_CONFINE 0x80u /* only trajectories that stay in a region count */
#define AW_FX_CONFINE_RPARAMS aw_region confine;
#endif

#if !defined(AW_EFFECT_DECLARATIONS_ONLY) && !defined(AW_FX_CONFINE_H)
#define AW_FX_CONFINE_H

#include "effects/aw_fx_common.h"

AW_EFFECT_ORDER(40)

/* 1 in the lanes whose direction (x, y, z) lies in the gnomonic square region
 * r (aw_params.h), 0 elsewhere. */
AW_FN lreal aw_in_region(AW_CONSTANT aw_region* r, lreal x, lreal y, lreal z) {
  lreal dc = AW_FMA(z, AW_LSPLAT(r->c[2]), AW_FMA(y, AW_LSPLAT(r->c[1]), x * r->c[0]));
  lreal d1 = AW_FMA(z, AW_LSPLAT(r->e1[2]), AW_FMA(y, AW_LSPLAT(r->e1[1]), x * r->e1[0]));
  lreal d2 = AW_FMA(z, AW_LSPLAT(r->e2[2]), AW_FMA(y, AW_LSPLAT(r->e2[1]), x * r->e2[0]));
  lreal lim = dc * r->half_width;
  return AW_SELECT(AW_LSPLAT(AW_R(1.0)), AW_LSPLAT(AW_R(0.0)),
                   (dc <= AW_R(0.0)) | (AW_FABS(d1) > lim) | (AW_FABS(d2) > lim));
}

typedef struct {
  lreal inside; /* 0 once a lane has left the region */
} aw_fx_confine_state;

AW_FN void aw_fx_confine_begin(aw_config cfg, aw_fx_confine_state* me, aw_fx_core* fx, aw_lstate* s, aw_lanes l,
                               AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  me->inside = AW_LSPLAT(AW_R(1.0));
}

AW_FN void aw_fx_confine_sample(aw_config cfg, aw_fx_confine_state* me, aw_fx_core* fx, const aw_lstate* s,
                                aw_lanes l, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  if (AW_HAS(AW_F_CONFINE)) me->inside = me->inside * aw_in_region(&rp->confine, s->px, s->py, s->pz);
}

AW_FN void aw_fx_confine_flag(aw_config cfg, aw_fx_confine_state* me, aw_fx_core* fx, int* flag) {
  if (!AW_HAS(AW_F_CONFINE)) return;
  real ain[AW_LANES];
  AW_STORE_LANES(me->inside, ain);
  for (int j = 0; j < AW_LANES; ++j)
    if (flag[j] == AW_STATUS_OK && ain[j] == AW_R(0.0)) flag[j] = AW_STATUS_LEFT_REGION;
}

AW_FN void aw_fx_confine_carry_save(aw_config cfg, aw_fx_confine_state* me, aw_fx_core* fx, aw_outputs out,
                                    AW_CONSTANT aw_iparams* ip, aw_lanes l) {
  aw_carry_put(out, ip, l, AW_CARRY_CONFINE, me->inside);
}

AW_FN void aw_fx_confine_carry_load(aw_config cfg, aw_fx_confine_state* me, aw_fx_core* fx, aw_outputs out,
                                    AW_CONSTANT aw_iparams* ip, aw_lanes l) {
  me->inside = aw_carry_get(out, ip, l, AW_CARRY_CONFINE);
}

#endif /* AW_FX_CONFINE_H */
