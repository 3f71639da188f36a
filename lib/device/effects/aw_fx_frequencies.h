/* arnoldweb effect "frequencies" (observe.frequencies; docs/frequencies.md):
 * the leading frequency of every angle of every trajectory over two
 * consecutive windows of n samples, by NAFF (aw_naff.h), and how much it
 * changed between them (Laskar's frequency map analysis).
 *
 * The signal of angle d is z_d(t) = exp(2 pi i u_d(t)) (u in turns), sampled
 * every ip->frequency_stride segments: sample k = 0 .. 2n - 1 at the end of
 * segment (k + 1) stride - 1, window k / n. The samples of the window in
 * progress, multiplied by the window chi_p, sit in the series buffer,
 * coalesced across the trajectories of a launch: sample m, angle d, part c
 * (re, im) of trajectory rec at
 *   series[((m * 3 + d) * 2 + c) * ip->series_stride + rec].
 * At the end of a window every angle's frequency is refined
 * (aw_naff_refine_lanes: all lanes in each pass) from the mean rate of the
 * angle over the window (its windings included), which also says which alias
 * of the sampled frequency is the true one: the frequency in turns per T is
 * (sigma + round(rate)) / every, for any speed.
 * The record (AW_OUT_FREQUENCIES, AW_FREQ_REALS reals): the three frequencies
 * of the first window, those of the second, and |nu(2) - nu(1)| (the host
 * writes its log10, the diffusion index); NaN where the trajectory was
 * flagged, or the refinement found no maximum. Per lane, scalar. */
#ifndef AW_FX_FREQUENCIES_H
#define AW_FX_FREQUENCIES_H

#include "aw_naff.h"
#include "effects/aw_fx_common.h"

/* What a lane keeps between samples: the unwrapped angles at the window's
 * first sample, and the first window's frequencies. */
typedef struct {
  lreal start[3];
  lreal nu1[3];
} aw_freq;

AW_FN void aw_freq_begin(aw_freq* f) {
  for (int d = 0; d < 3; ++d) {
    f->start[d] = AW_LSPLAT(AW_R(0.0));
    f->nu1[d] = AW_LSPLAT(AW_R(0.0));
  }
}

/* Sample k (0 .. 2n - 1) of the lanes' angles, multiplied by the window; the
 * analysis at the end of a window. */
AW_FN void aw_freq_sample(aw_freq* f, const aw_lstate* s, const int* status, aw_i64 k, aw_lanes l,
                          AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out, real nan) {
  const int n = (int)ip->frequency_samples;
  const int m = (int)(k % n);
  const aw_u64 stride = (aw_u64)ip->series_stride;
  const aw_u64 first = AW_LANE_RECORD(l, 0); /* the lanes' records are consecutive */
  const lreal unwrapped[3] = {AW_INT_TO_LANE(s->wx) + s->ux, AW_INT_TO_LANE(s->wy) + s->uy,
                              AW_INT_TO_LANE(s->wz) + s->uz};
  const lreal u[3] = {s->ux, s->uy, s->uz};
  if (m == 0)
    for (int d = 0; d < 3; ++d) f->start[d] = unwrapped[d];
  const lreal w = AW_LSPLAT(aw_naff_window_at(m, n, (int)ip->frequency_order));
  for (int d = 0; d < 3; ++d) {
    lreal sn, cs;
    aw_sincos2pi(u[d], &sn, &cs);
    /* every lane, active or not: the buffer holds whole lane groups (series_stride) */
    AW_GLOBAL real* at = out.series + (aw_u64)((m * 3 + d) * 2) * stride + first;
    const lreal re = w * cs, im = w * sn;
    AW_STORE_LANES(re, at);
    AW_STORE_LANES(im, at + stride);
  }
  if (m != n - 1) return;
  /* the end of a window: every lane's three frequencies. The mean rate of the
   * angle over the window (cycles per sample, windings included) gives the
   * start, and which alias of the sampled frequency is the true one. */
  int active[AW_LANES];
  for (int j = 0; j < AW_LANES; ++j) active[j] = AW_LANE_ACTIVE(l, j);
  real nu[3][AW_LANES];
  for (int d = 0; d < 3; ++d) {
    const lreal rate = (unwrapped[d] - f->start[d]) / (real)(n - 1);
    const lreal whole = AW_RINT_SMALL(rate);
    real wh[AW_LANES];
    int ok[AW_LANES] = {0}; /* set for the active lanes only */
    AW_STORE_LANES(whole, wh);
    AW_GLOBAL const real* re = out.series + (aw_u64)(d * 2) * stride + first;
    aw_naff_refine_lanes(re, re + stride, 6 * stride, n, rate - whole, active, nu[d], ok);
    for (int j = 0; j < AW_LANES; ++j)
      nu[d][j] = !active[j] ? AW_R(0.0) : ok[j] ? (nu[d][j] + wh[j]) / rp->frequency_every : nan;
  }
  if (k < n) { /* the first window: kept for the second */
    for (int d = 0; d < 3; ++d) f->nu1[d] = AW_LOAD_LANES(nu[d]);
    return;
  }
  real first_nu[3][AW_LANES];
  for (int d = 0; d < 3; ++d) AW_STORE_LANES(f->nu1[d], first_nu[d]);
  for (int j = 0; j < AW_LANES; ++j) {
    if (!active[j]) continue;
    AW_GLOBAL real* rec = aw_record_r(out, ip, AW_OUT_FREQUENCIES, AW_LANE_RECORD(l, j));
    const int fine = status[j] == AW_STATUS_OK;
    real dx = nu[0][j] - first_nu[0][j], dy = nu[1][j] - first_nu[1][j], dz = nu[2][j] - first_nu[2][j];
    for (int d = 0; d < 3; ++d) {
      rec[d] = fine ? first_nu[d][j] : nan;
      rec[3 + d] = fine ? nu[d][j] : nan;
    }
    rec[6] = fine ? AW_SQRT(AW_FMA(dz, dz, AW_FMA(dy, dy, dx * dx))) : nan;
  }
}

#endif /* AW_FX_FREQUENCIES_H */
