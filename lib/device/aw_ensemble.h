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

/* 1 in the lanes whose direction (x, y, z) lies in the gnomonic square region
 * r (AW_REGION_SIZE reals, layout in aw_params.h), 0 elsewhere. */
AW_FN lreal aw_in_region(AW_CONSTANT real* r, lreal x, lreal y, lreal z) {
  lreal dc = AW_FMA(z, AW_LSPLAT(r[2]), AW_FMA(y, AW_LSPLAT(r[1]), x * r[0]));
  lreal d1 = AW_FMA(z, AW_LSPLAT(r[5]), AW_FMA(y, AW_LSPLAT(r[4]), x * r[3]));
  lreal d2 = AW_FMA(z, AW_LSPLAT(r[8]), AW_FMA(y, AW_LSPLAT(r[7]), x * r[6]));
  lreal lim = dc * r[9];
  return AW_SELECT(AW_LSPLAT(AW_R(1.0)), AW_LSPLAT(AW_R(0.0)),
                   (dc <= AW_R(0.0)) | (AW_FABS(d1) > lim) | (AW_FABS(d2) > lim));
}

/* Bin of direction (x, y, z) in the R x R zoom histogram of region r, or -1. */
AW_FN aw_i64 aw_zoom_bin(AW_CONSTANT real* r, aw_i64 res, real x, real y, real z) {
  real dc = AW_FMA(z, r[2], AW_FMA(y, r[1], x * r[0]));
  if (!(dc > AW_R(0.0))) return -1;
  real gx = AW_FMA(z, r[5], AW_FMA(y, r[4], x * r[3])) / dc; /* tangent-plane coordinates */
  real gy = AW_FMA(z, r[8], AW_FMA(y, r[7], x * r[6])) / dc;
  real w = r[9];
  if (!(AW_FABS(gx) < w) || !(AW_FABS(gy) < w)) return -1;
  real n = (real)res;
  aw_i64 ix = (aw_i64)((gx / w + AW_R(1.0)) * AW_R(0.5) * n);
  aw_i64 iy = (aw_i64)((gy / w + AW_R(1.0)) * AW_R(0.5) * n);
  if (ix >= res) ix = res - 1;
  if (iy >= res) iy = res - 1;
  return iy * res + ix;
}

/* Frame of window w: the k with b_k <= w < b_k+1, or -1. */
AW_FN int aw_frame_of(AW_CONSTANT aw_i64* ip, aw_i64 w) {
  const int frames = (int)ip[AW_I_FRAMES];
  for (int k = 0; k < frames; ++k)
    if (w >= ip[AW_I_FRAME_BOUNDS + k] && w < ip[AW_I_FRAME_BOUNDS + k + 1]) return k;
  return -1;
}

/* Where the results of one work-item go. Pointers the scene does not need may
 * be null; they are never touched then. */
typedef struct {
  AW_GLOBAL aw_u32* map;       /* F velocity maps of 12 nside^2 counts, then the zoom */
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
AW_FN void aw_ensemble_item(aw_u32 features, int stages, int kick_first, int initial,
                            aw_u64 first, aw_u64 end, aw_u64 chunk_first, AW_CONSTANT real* rp,
                            AW_CONSTANT aw_i64* ip, aw_outputs out, real* emax, real* esum) {
  aw_lstate s;
  int status[AW_LANES];
  real tmp[AW_LANES];

  /* ---- initial state */
  lreal accepted = aw_initial_state(&s, initial, first, rp, ip);
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
  const aw_i64 npix = 12 * nside * nside;
  const aw_i64 zoom_res = ip[AW_I_ZOOM_RESOLUTION];
  AW_GLOBAL aw_u32* zoom = out.map + (aw_u64)(ip[AW_I_FRAMES] * npix);
  lreal inside = AW_LSPLAT(AW_R(1.0)); /* 0 once a lane has left the region */
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
      if (AW_HAS(AW_F_CONFINE))
        inside = inside * aw_in_region(rp + AW_P_CONFINE, s.px, s.py, s.pz);
    }
    /* displacement over the window, in turns: exact integer part + wrapped part */
    lreal dx = AW_INT_TO_LANE(s.wx - wx0) + (s.ux - ux0);
    lreal dy = AW_INT_TO_LANE(s.wy - wy0) + (s.uy - uy0);
    lreal dz = AW_INT_TO_LANE(s.wz - wz0) + (s.uz - uz0);
    lreal sane = AW_SELECT(AW_LSPLAT(AW_R(0.0)), AW_LSPLAT(AW_R(1.0)),
                           AW_ISFINITE(s.ux) & AW_ISFINITE(s.uy) & AW_ISFINITE(s.uz) &
                               AW_ISFINITE(s.px) & AW_ISFINITE(s.py) & AW_ISFINITE(s.pz));
    real ax[AW_LANES], ay[AW_LANES], az[AW_LANES], asane[AW_LANES], aover[AW_LANES], ain[AW_LANES];
    AW_STORE_LANES(dx, ax);
    AW_STORE_LANES(dy, ay);
    AW_STORE_LANES(dz, az);
    AW_STORE_LANES(sane, asane);
    AW_STORE_LANES(over, aover);
    AW_STORE_LANES(inside, ain);
    const int frame = AW_HAS(AW_F_FRAMES) ? aw_frame_of(ip, w) : 0;
    for (int j = 0; j < AW_LANES; ++j) {
      if (status[j] != AW_STATUS_OK || first + (aw_u64)j >= end) continue;
      if (asane[j] == AW_R(0.0)) {
        status[j] = AW_STATUS_NONFINITE;
      } else if (aover[j] != AW_R(0.0)) {
        status[j] = AW_STATUS_ENERGY;
      } else if (AW_HAS(AW_F_CONFINE) && ain[j] == AW_R(0.0)) {
        status[j] = AW_STATUS_LEFT_REGION;
      } else {
        const int moved = !(ax[j] == AW_R(0.0) && ay[j] == AW_R(0.0) && az[j] == AW_R(0.0));
        if (AW_HAS(AW_F_VELOCITY_MAP) && frame >= 0) {
          aw_i64 pix = moved ? aw_vec2pix_ring(nside, ax[j], ay[j], az[j]) : 0;
          AW_ATOMIC_INC(&out.map[(aw_u64)(frame * npix + pix)]);
        }
        if (AW_HAS(AW_F_ZOOM) && moved) {
          aw_i64 bin = aw_zoom_bin(rp + AW_P_ZOOM, zoom_res, ax[j], ay[j], az[j]);
          if (bin >= 0) AW_ATOMIC_INC(&zoom[bin]);
        }
      }
    }
  }

  /* ---- time reversal: P -> -P, the same steps again, P -> -P: back at the start */
  if (AW_HAS(AW_F_REVERSE)) {
    s.px = -s.px;
    s.py = -s.py;
    s.pz = -s.pz;
    for (aw_i64 w = 0; w < windows; ++w)
      for (aw_i64 g = 0; g < segments; ++g) aw_segment(&s, steps, rp, stages, kick_first);
    s.px = -s.px;
    s.py = -s.py;
    s.pz = -s.pz;
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
