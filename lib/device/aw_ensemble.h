/* arnoldweb portable device core: the whole life of a lane of trajectories.
 *
 * initial state from (seed, index) -> windows of integration -> at the end of
 * each averaging window the averaged velocity V = (X(t + dt) - X(t)) / dt is
 * binned by direction -> counters, energy statistics, optional state records.
 * Everything stays in registers; only integer histograms, counters and (on
 * request) state records leave. The kernels in kernels_cl/ and kernels_cu/ and
 * the C++ backend call aw_ensemble_item() with the scene's feature mask; every
 * effect sits behind `features & AW_F_...`, a compile-time constant there.
 */
#ifndef AW_ENSEMBLE_H
#define AW_ENSEMBLE_H

#include "aw_healpix.h"
#include "aw_initial.h"
#include "aw_params.h"
#include "aw_stepper.h"

#define AW_HAS(flag) ((features & (flag)) != 0u)

#if defined(AW_OPENCL)
#define AW_ATOMIC_INC(p) atomic_inc(p)
#elif defined(AW_CUDA)
#define AW_ATOMIC_INC(p) atomicAdd((p), 1u)
#else
#define AW_ATOMIC_INC(p) __atomic_fetch_add((p), 1u, __ATOMIC_RELAXED)
#endif

/* Bin of the log2 histogram of an energy error e >= 0 (or NaN: last bin). */
AW_FN int aw_energy_bin(real e) {
  if (!(e < AW_R(65536.0))) return AW_EHIST_BINS - 1; /* >= 2^16, Inf, NaN */
  if (e < AW_R(5.421010862427522e-20)) return 0;      /* < 2^-64, zero */
  int ex;
  real m = AW_FREXP(e, &ex); /* e = m 2^ex, m in [1/2, 1) */
  int quarter = (int)((m - AW_R(0.5)) * AW_R(8.0));
  return 1 + (ex - 1 - AW_EHIST_MIN_EXP) * AW_EHIST_BINS_PER_OCTAVE + quarter;
}

/* Where the results of one work-item go. Pointers the scene does not need may
 * be null; they are never touched then. */
typedef struct {
  AW_GLOBAL aw_u32* map;       /* velocity map, 12 nside^2 counts */
  AW_GLOBAL aw_u32* counters;  /* AW_C_COUNT counters */
  AW_GLOBAL real* initial_r;   /* AW_STATE_REALS per trajectory of the chunk */
  AW_GLOBAL real* final_r;     /* AW_STATE_REALS per trajectory of the chunk */
  AW_GLOBAL aw_i64* final_i;   /* AW_STATE_INTS per trajectory of the chunk */
} aw_outputs;

AW_FN void aw_store_states(AW_GLOBAL real* out, aw_u64 rec, const aw_lstate* s, int j) {
  real a[AW_LANES];
  AW_STORE_LANES(s->ux, a); out[rec * AW_STATE_REALS + 0] = a[j];
  AW_STORE_LANES(s->uy, a); out[rec * AW_STATE_REALS + 1] = a[j];
  AW_STORE_LANES(s->uz, a); out[rec * AW_STATE_REALS + 2] = a[j];
  AW_STORE_LANES(s->px, a); out[rec * AW_STATE_REALS + 3] = a[j];
  AW_STORE_LANES(s->py, a); out[rec * AW_STATE_REALS + 4] = a[j];
  AW_STORE_LANES(s->pz, a); out[rec * AW_STATE_REALS + 5] = a[j];
}

/* Trajectories first .. first + AW_LANES - 1 (those >= end are idle lanes).
 * chunk_first is the index of the chunk's first trajectory (state records are
 * relative to it). On return, *emax and *esum hold the maximum and the sum of
 * max|dE| over this item's binned trajectories (zero without AW_F_ENERGY). */
AW_FN void aw_ensemble_item(aw_u32 features, int stages, int kick_first, aw_u64 first,
                            aw_u64 end, aw_u64 chunk_first, AW_CONSTANT real* rp,
                            AW_CONSTANT aw_i64* ip, aw_outputs out, real* emax, real* esum) {
  aw_lstate s;
  int status[AW_LANES];
  real tmp[AW_LANES];

  /* ---- initial state */
  lreal accepted = aw_initial_shell(&s, first, rp, ip);
  AW_STORE_LANES(accepted, tmp);
  for (int j = 0; j < AW_LANES; ++j) status[j] = (tmp[j] != AW_R(0.0)) ? AW_STATUS_OK : AW_STATUS_INITIAL;

  if (AW_HAS(AW_F_TEST_INJECT)) {
    AW_STORE_LANES(s.px, tmp);
    for (int j = 0; j < AW_LANES; ++j)
      if (first + (aw_u64)j == (aw_u64)ip[AW_I_INJECT_INDEX]) tmp[j] += rp[AW_P_INJECT_VALUE];
    s.px = AW_LOAD_LANES(tmp);
  }
  if (AW_HAS(AW_F_INITIAL_STATES))
    for (int j = 0; j < AW_LANES; ++j)
      if (first + (aw_u64)j < end) aw_store_states(out.initial_r, first + (aw_u64)j - chunk_first, &s, j);

  aw_force(&s);
  lreal e0 = AW_LSPLAT(AW_R(0.0));
  lreal emax_l = AW_LSPLAT(AW_R(0.0));
  if (AW_HAS(AW_F_ENERGY)) e0 = aw_energy(&s);

  /* ---- windows */
  const aw_i64 windows = ip[AW_I_WINDOWS];
  const aw_i64 segments = ip[AW_I_SEGMENTS];
  const aw_i64 steps = ip[AW_I_STEPS_PER_SEGMENT];
  const aw_i64 nside = ip[AW_I_NSIDE];
  for (aw_i64 w = 0; w < windows; ++w) {
    lreal ux0 = s.ux, uy0 = s.uy, uz0 = s.uz;
    lint wx0 = s.wx, wy0 = s.wy, wz0 = s.wz;
    lreal over = AW_LSPLAT(AW_R(0.0)); /* 1 where |dE| exceeded the limit */
    for (aw_i64 g = 0; g < segments; ++g) {
      aw_segment(&s, steps, rp, stages, kick_first);
      if (AW_HAS(AW_F_ENERGY)) {
        lreal de = AW_FABS(aw_energy(&s) - e0);
        emax_l = AW_SELECT(emax_l, de, de > emax_l);
        if (AW_HAS(AW_F_ENERGY_LIMIT))
          over = AW_SELECT(over, AW_LSPLAT(AW_R(1.0)), de > rp[AW_P_ENERGY_LIMIT]);
      }
    }
    /* displacement over the window, in turns: exact integer part + wrapped part */
    lreal dx = AW_INT_TO_LANE(s.wx - wx0) + (s.ux - ux0);
    lreal dy = AW_INT_TO_LANE(s.wy - wy0) + (s.uy - uy0);
    lreal dz = AW_INT_TO_LANE(s.wz - wz0) + (s.uz - uz0);
    lreal sane = AW_SELECT(AW_LSPLAT(AW_R(0.0)), AW_LSPLAT(AW_R(1.0)),
                           AW_ISFINITE(s.ux) & AW_ISFINITE(s.uy) & AW_ISFINITE(s.uz) &
                               AW_ISFINITE(s.px) & AW_ISFINITE(s.py) & AW_ISFINITE(s.pz));
    real ax[AW_LANES], ay[AW_LANES], az[AW_LANES], asane[AW_LANES], aover[AW_LANES];
    AW_STORE_LANES(dx, ax);
    AW_STORE_LANES(dy, ay);
    AW_STORE_LANES(dz, az);
    AW_STORE_LANES(sane, asane);
    AW_STORE_LANES(over, aover);
    for (int j = 0; j < AW_LANES; ++j) {
      if (status[j] != AW_STATUS_OK || first + (aw_u64)j >= end) continue;
      if (asane[j] == AW_R(0.0)) {
        status[j] = AW_STATUS_NONFINITE;
      } else if (aover[j] != AW_R(0.0)) {
        status[j] = AW_STATUS_ENERGY;
      } else if (AW_HAS(AW_F_VELOCITY_MAP)) {
        aw_i64 pix = (ax[j] == AW_R(0.0) && ay[j] == AW_R(0.0) && az[j] == AW_R(0.0))
                         ? 0
                         : aw_vec2pix_ring(nside, ax[j], ay[j], az[j]);
        AW_ATOMIC_INC(&out.map[pix]);
      }
    }
  }

  /* ---- bookkeeping */
  real amax[AW_LANES];
  AW_STORE_LANES(emax_l, amax);
  *emax = AW_R(0.0);
  *esum = AW_R(0.0);
  for (int j = 0; j < AW_LANES; ++j) {
    aw_u64 index = first + (aw_u64)j;
    if (index >= end) continue;
    int st = status[j];
    AW_ATOMIC_INC(&out.counters[st == AW_STATUS_OK ? AW_C_BINNED : st]);
    if (AW_HAS(AW_F_ENERGY)) {
      AW_ATOMIC_INC(&out.counters[AW_C_EHIST + aw_energy_bin(amax[j])]);
      if (st == AW_STATUS_OK) {
        *emax = (amax[j] > *emax) ? amax[j] : *emax;
        *esum += amax[j];
      }
    }
    if (AW_HAS(AW_F_FINAL_STATES)) {
      aw_u64 rec = index - chunk_first;
      aw_store_states(out.final_r, rec, &s, j);
      lint wv[3] = {s.wx, s.wy, s.wz};
      for (int c = 0; c < 3; ++c) {
        aw_i64 wa[AW_LANES];
        AW_STORE_ILANES(wv[c], wa);
        out.final_i[rec * AW_STATE_INTS + c] = wa[j];
      }
      out.final_i[rec * AW_STATE_INTS + 3] = st;
    }
  }
}

#endif /* AW_ENSEMBLE_H */
