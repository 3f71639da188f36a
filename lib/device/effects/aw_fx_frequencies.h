/* arnoldweb effect "frequencies" (observe.frequencies; docs/frequencies.md):
 * the leading frequency of every angle of every trajectory over two
 * consecutive windows of n samples, by NAFF (aw_naff.h), and how much it
 * changed between them (Laskar's frequency map analysis).
 *
 * Two kernels share the work. The ensemble kernel samples: the signal of
 * angle d is z_d(t) = exp(2 pi i u_d(t)) (u in turns), sampled every
 * ip->frequency_stride segments, sample k = 0 .. 2n - 1 at the end of segment
 * (k + 1) stride - 1, window k / n (aw_freq_sample). The analysis kernel
 * (aw_freq_analyse), launched after it over the same trajectories, refines
 * every angle's frequency in each window. They meet in the series buffer
 * (aw_series_at): per block of AW_SERIES_BLOCK consecutive trajectories of a
 * launch, element e of all of them side by side, then element e + 1, so that
 * a warp's pass over one signal reads one stream of memory:
 *   e = (g n + m) 2 + c            sample m (0 .. n - 1) of signal g = 3 w + d
 *                                  (window w, angle d), part c (re, im),
 *                                  multiplied by the window chi_p;
 *   e = 12 n + g                   the mean rate of signal g over its window
 *                                  (cycles per sample, windings included);
 *   e = 12 n + 6                   1 where the trajectory was fine at the end
 *                                  of the second window, else 0.
 * Kept apart, the integration kernel carries none of the analysis's registers
 * and the analysis runs at its own occupancy (its passes over the samples are
 * bound by memory; docs/frequencies.md, "What the frequencies cost").
 * The mean rate gives the refinement its start, and says which alias of the
 * sampled frequency is the true one: the frequency in turns per T is
 * (sigma + round(rate)) / every, for any speed.
 * The record (AW_OUT_FREQUENCIES, AW_FREQ_REALS reals): the three frequencies
 * of the first window, those of the second, and |nu(2) - nu(1)| (the host
 * writes its log10, the diffusion index); NaN where the trajectory was
 * flagged, or the refinement found no maximum. */
#ifndef AW_FX_FREQUENCIES_H
#define AW_FX_FREQUENCIES_H

#include "aw_naff.h"
#include "effects/aw_fx_common.h"

/* The series' elements after the samples (see above; AW_FREQ_SERIES_REALS in
 * aw_params.h counts them all). */
#define AW_FREQ_SAMPLE_AT(n, g, m) (((aw_u64)(g) * (aw_u64)(n) + (aw_u64)(m)) * 2)
#define AW_FREQ_RATE_AT(n, g) (12 * (aw_u64)(n) + (aw_u64)(g))
#define AW_FREQ_FINE_AT(n) (12 * (aw_u64)(n) + 6)

/* Element e of the series of record rec (see above). Lane groups never cross
 * a block: */
typedef char aw_lanes_divide_series_block[(AW_SERIES_BLOCK % AW_LANES == 0) ? 1 : -1];
AW_FN AW_GLOBAL real* aw_series_at(aw_outputs out, AW_CONSTANT aw_iparams* ip, aw_u64 rec, aw_u64 e) {
  return out.series + (rec / AW_SERIES_BLOCK) * ((aw_u64)ip->series_reals * AW_SERIES_BLOCK) + e * AW_SERIES_BLOCK +
         rec % AW_SERIES_BLOCK;
}

/* Sample k (0 .. 2n - 1) of the lanes' angles, multiplied by the window; at
 * the end of a window the mean rates, at the end of the second whether each
 * lane is fine. Every lane, active or not: the buffer holds whole blocks.
 * Nothing is kept in registers between samples (the unwrapped angles at a
 * window's first sample wait in the rates' places): the integration between
 * samples has every register it had without frequencies. */
AW_FN void aw_freq_sample(const aw_lstate* s, const int* status, aw_i64 k, aw_lanes l, AW_CONSTANT aw_iparams* ip,
                          aw_outputs out) {
  const int n = (int)ip->frequency_samples;
  const int m = (int)(k % n);
  const aw_u64 first = AW_LANE_RECORD(l, 0); /* the lanes' records are consecutive */
  const int window = (int)(k / n);
  const lreal unwrapped[3] = {AW_INT_TO_LANE(s->wx) + s->ux, AW_INT_TO_LANE(s->wy) + s->uy,
                              AW_INT_TO_LANE(s->wz) + s->uz};
  const lreal u[3] = {s->ux, s->uy, s->uz};
  if (m == 0)
    for (int d = 0; d < 3; ++d)
      AW_STORE_LANES(unwrapped[d], aw_series_at(out, ip, first, AW_FREQ_RATE_AT(n, window * 3 + d)));
  const lreal w = AW_LSPLAT(aw_naff_window_at(m, n, (int)ip->frequency_order));
  for (int d = 0; d < 3; ++d) {
    lreal sn, cs;
    aw_sincos2pi(u[d], &sn, &cs);
    AW_GLOBAL real* at = aw_series_at(out, ip, first, AW_FREQ_SAMPLE_AT(n, window * 3 + d, m));
    const lreal re = w * cs, im = w * sn;
    AW_STORE_LANES(re, at);
    AW_STORE_LANES(im, at + AW_SERIES_BLOCK);
  }
  if (m != n - 1) return;
  for (int d = 0; d < 3; ++d) {
    AW_GLOBAL real* at = aw_series_at(out, ip, first, AW_FREQ_RATE_AT(n, window * 3 + d));
    const lreal rate = (unwrapped[d] - AW_LOAD_LANES(at)) / (real)(n - 1);
    AW_STORE_LANES(rate, at);
  }
  if (window == 1) {
    AW_GLOBAL real* fine = aw_series_at(out, ip, first, AW_FREQ_FINE_AT(n));
    for (int j = 0; j < AW_LANES; ++j) fine[j] = (status[j] == AW_STATUS_OK) ? AW_R(1.0) : AW_R(0.0);
  }
}

/* The start of the refinement of signal g = 3 w + d (window w, angle d) of
 * lane group `first`: its samples, and its mean rate split into the whole
 * cycles per sample (which alias) and the rest (the start). */
AW_FN AW_GLOBAL const real* aw_freq_signal(AW_CONSTANT aw_iparams* ip, aw_outputs out, aw_u64 first, int g,
                                           lreal* whole, lreal* start) {
  const int n = (int)ip->frequency_samples;
  const lreal rate = AW_LOAD_LANES(aw_series_at(out, ip, first, AW_FREQ_RATE_AT(n, g)));
  *whole = AW_RINT_SMALL(rate);
  *start = rate - *whole;
  return aw_series_at(out, ip, first, AW_FREQ_SAMPLE_AT(n, g, 0));
}

/* The record of a lane from its six frequencies nu[3 w + d] (turns per T). */
AW_FN void aw_freq_record(aw_lanes l, int j, const real* nu, AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  const int n = (int)ip->frequency_samples;
  const real nan = aw_nan_real();
  AW_GLOBAL real* rec = aw_record_r(out, ip, AW_OUT_FREQUENCIES, AW_LANE_RECORD(l, j));
  const aw_u64 first = AW_LANE_RECORD(l, 0);
  const int fine = aw_series_at(out, ip, first, AW_FREQ_FINE_AT(n))[j] != AW_R(0.0);
  real dx = nu[3] - nu[0], dy = nu[4] - nu[1], dz = nu[5] - nu[2];
  for (int d = 0; d < 6; ++d) rec[d] = fine ? nu[d] : nan;
  rec[6] = fine ? AW_SQRT(AW_FMA(dz, dz, AW_FMA(dy, dy, dx * dx))) : nan;
}

/* The analysis of a group of lanes (a vector of trajectories on CPUs, one on
 * GPUs): the lanes refine the same signal together, signal after signal
 * (aw_naff_refine_lanes). On a GPU the work-items of a warp thus read one
 * signal at a time, side by side in memory (a warp whose work-items each went
 * on to their next signal as they finished, tried, read six signals at once
 * from scattered sectors: more bytes for fewer passes; docs/frequencies.md). */
AW_FN void aw_freq_analyse(aw_lanes l, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  const int n = (int)ip->frequency_samples;
  const aw_u64 first = AW_LANE_RECORD(l, 0);
  int active[AW_LANES];
  for (int j = 0; j < AW_LANES; ++j) active[j] = AW_LANE_ACTIVE(l, j);
  real nu[AW_LANES][6];
  for (int g = 0; g < 6; ++g) {
    lreal whole, start;
    AW_GLOBAL const real* re = aw_freq_signal(ip, out, first, g, &whole, &start);
    real wh[AW_LANES], f[AW_LANES] = {0};
    int ok[AW_LANES] = {0}; /* set for the active lanes only */
    AW_STORE_LANES(whole, wh);
    aw_naff_refine_lanes(re, re + AW_SERIES_BLOCK, 2 * AW_SERIES_BLOCK, n, start, active, f, ok);
    for (int j = 0; j < AW_LANES; ++j)
      nu[j][g] = !active[j] ? AW_R(0.0) : ok[j] ? (f[j] + wh[j]) / rp->frequency_every : aw_nan_real();
  }
  for (int j = 0; j < AW_LANES; ++j)
    if (active[j]) aw_freq_record(l, j, nu[j], ip, out);
}

#endif /* AW_FX_FREQUENCIES_H */
