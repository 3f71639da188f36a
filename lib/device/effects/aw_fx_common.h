/* arnoldweb portable device core: what every effect header uses: the feature
 * test, atomic increments of the 32-bit counters, and the outputs of a
 * work-item. */
#ifndef AW_FX_COMMON_H
#define AW_FX_COMMON_H

#include "aw_state.h"

/* features is a compile-time constant in OpenCL and CUDA (aw_config built
 * from -D options), so an effect that is not asked for folds away. */
#define AW_HAS(flag) ((cfg.features & (flag)) != 0u)

#if defined(AW_OPENCL)
#define AW_ATOMIC_INC(p) atomic_inc(p)
#elif defined(AW_CUDA)
#define AW_ATOMIC_INC(p) atomicAdd((p), 1u)
#else
#define AW_ATOMIC_INC(p) __atomic_fetch_add((p), 1u, __ATOMIC_RELAXED)
#endif

/* Where the results of one work-item go: the output arenas of the kernel's
 * buffers (aw_params.h). */
typedef struct {
  AW_GLOBAL aw_u32* hist;      /* F velocity maps of 12 nside^2 counts, then the zoom */
  AW_GLOBAL aw_u32* counters;  /* AW_C_COUNT counters */
  AW_GLOBAL real* rec_r;       /* ip->rec_reals reals per trajectory of the chunk */
  AW_GLOBAL aw_i64* rec_i;     /* ip->rec_ints integers per trajectory of the chunk */
  AW_GLOBAL real* series;      /* the sampled time series, ip->series_reals per trajectory (aw_params.h) */
} aw_outputs;

/* A quiet NaN with the same bits everywhere (0/0 gives the sign bit set on
 * x86 and not where the compiler folds it): from its bit pattern. */
#ifdef AW_FLOAT
#define AW_QNAN_BITS AW_BITS_C(0x7FC00000)
#else
#define AW_QNAN_BITS AW_BITS_C(0x7FF8000000000000)
#endif
AW_FN real aw_nan_real(void) {
  lreal n = AW_FROM_BITS(AW_AS_BITS(AW_LSPLAT(AW_R(0.0))) | AW_QNAN_BITS);
  real a[AW_LANES];
  AW_STORE_LANES(n, a);
  return a[0];
}

/* The columns of output `slot` in the records of trajectory `rec` (relative
 * to the chunk's first): reals and integers. Only slots the plan lays out
 * (the kernel's features ask for them) may be written. */
AW_FN AW_GLOBAL real* aw_record_r(aw_outputs out, AW_CONSTANT aw_iparams* ip, int slot, aw_u64 rec) {
  return out.rec_r + rec * (aw_u64)ip->rec_reals + (aw_u64)ip->rec_col_r[slot];
}
AW_FN AW_GLOBAL aw_i64* aw_record_i(aw_outputs out, AW_CONSTANT aw_iparams* ip, int slot, aw_u64 rec) {
  return out.rec_i + rec * (aw_u64)ip->rec_ints + (aw_u64)ip->rec_col_i[slot];
}

/* The trajectories of one work-item: first .. first + AW_LANES - 1; those at
 * or beyond end are idle lanes. chunk_first: the chunk's first trajectory
 * (state records are relative to it). */
typedef struct {
  aw_u64 first, end, chunk_first;
} aw_lanes;

/* A lane of the work-item that holds a trajectory. */
#define AW_LANE_ACTIVE(l, j) ((l).first + (aw_u64)(j) < (l).end)
/* The record of lane j: its trajectory's index relative to the chunk's first. */
#define AW_LANE_RECORD(l, j) ((l).first + (aw_u64)(j) - (l).chunk_first)

/* Element c of the lanes' carry records (AW_OUT_CARRY, aw_params.h): reals
 * and integers, read (idle lanes read 0) and written (idle lanes write
 * nothing). */
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

/* An effect header (effects/aw_fx_<name>.h) declares its place among the
 * effects on a line of its own, AW_EFFECT_ORDER(<n>): its hooks are called in
 * increasing n (cmake/ArnoldwebEffects.cmake generates the calls,
 * effects/aw_effect_hooks.h; docs/design.md, "The effect hooks"). */
#define AW_EFFECT_ORDER(n)

/* What every effect may read of a lane's life (effects/aw_effects.h keeps it):
 * the status of each lane, E(0) where an effect asked for it (AW_F_WITH_E0),
 * and after the run the maximum and the sum of max|dE| over the item's binned
 * lanes (the energy effect's finish hook adds them). */
typedef struct {
  int status[AW_LANES]; /* AW_STATUS_*: a trajectory flagged stays flagged */
  lreal e0;             /* E(0) */
  real binned_emax, binned_esum;
} aw_fx_core;

#endif /* AW_FX_COMMON_H */
