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
 * every angle's frequency in each window. They meet in the series buffer, in
 * blocks of AW_SERIES_BLOCK = 32 consecutive trajectories of a launch
 * (ip->series_reals reals each):
 *   samples     the samples of signal g = 3 w + d (window w, angle d) in
 *               groups q = m / G of G = AW_NAFF_GROUP (m = 0 .. np - 1;
 *               np = AW_NAFF_PADDED(n), the padding past n made zero by the
 *               analysis), each group of trajectory j of the block 2 G reals
 *               (re, im of its samples in turn), multiplied by the window
 *               chi_p, at
 *               ((g np/G + q) 32 + j) 2 G;
 *   tail        element e of trajectory j at (12 np + e) 32 + j: e = g the
 *               mean rate of signal g over its window (cycles per sample,
 *               windings included), e = 6 1 where the trajectory was fine at
 *               the end of the second window, else 0.
 * A warp of the integration stores one sample of its 32 trajectories within
 * 2 KB, whose sectors the next samples complete in the cache; a team of the
 * analysis (aw_naff.h, "teams") reads one trajectory's groups whole, eight
 * of them in a load of its warp. (One trajectory's series in one piece was
 * tried: the sampling then wrote 1.7 times the series to memory. Groups of
 * two samples, 32 bytes: the analysis read 1.7 times the series.)
 * Kept apart, the integration kernel carries none of the analysis's registers
 * and the analysis runs at its own occupancy (its passes over the samples are
 * bound by memory; docs/frequencies.md, "What the frequencies cost").
 * The mean rate gives the search for the largest term its start, and says
 * which alias of the sampled frequency is the true one: the frequency in
 * turns per T is (sigma + round(rate)) / every, for any speed.
 * The record (AW_OUT_FREQUENCIES, AW_FREQ_REALS reals): the three frequencies
 * of the first window, those of the second, and ||nu(2)| - |nu(1)|| (the
 * host writes its log10, the diffusion index); NaN where the trajectory was
 * flagged, or the search found no maximum. */
/* What the host reads too (plain macros, gathered by the generated
 * effects/aw_effect_declarations.h that aw_params.h includes). */
#ifndef AW_FX_FREQUENCIES_DECLARATIONS
#define AW_FX_FREQUENCIES_DECLARATIONS
#define AW_F_FREQUENCIES 0x8000u /* frequency analysis (NAFF) over two windows (docs/frequencies.md) */
#define AW_OUT_FREQUENCIES 4     /* AW_FREQ_REALS reals */
#define AW_FREQ_REALS 7
/* A frequency pass over a window's samples is shared by a team of
 * AW_NAFF_TEAM members (aw_naff.h): member t takes samples t, t + T, ...;
 * a window holds its samples padded with zeros to a multiple of the team. */
#define AW_NAFF_TEAM 32
#define AW_NAFF_PADDED(n) ((((n) + AW_NAFF_TEAM - 1) / AW_NAFF_TEAM) * AW_NAFF_TEAM)
/* ... and stored in groups of AW_NAFF_GROUP consecutive samples (64 bytes in
 * double: what a GPU's memory delivers at once; aw_naff.h, "teams"). */
#define AW_NAFF_GROUP 4
/* The frequencies' work memory per trajectory (series buffer) for windows of
 * n samples: both windows' samples (padded), the mean rates, a flag, and one
 * real unused so that every trajectory's series starts 32 bytes apart. */
#define AW_FREQ_SERIES_REALS(n) (12 * AW_NAFF_PADDED(n) + 8)
#define AW_FX_FREQUENCIES_RPARAMS real frequency_every; /* T between two frequency samples */
#define AW_FX_FREQUENCIES_IPARAMS                                         \
  aw_i64 frequency_stride;  /* segments between frequency samples */      \
  aw_i64 frequency_samples; /* n: samples per window (two windows) */     \
  aw_i64 frequency_order;   /* p of Laskar's window chi_p */
#endif

#if !defined(AW_EFFECT_DECLARATIONS_ONLY) && !defined(AW_FX_FREQUENCIES_H)
#define AW_FX_FREQUENCIES_H

#include "aw_naff.h"
#include "effects/aw_fx_common.h"

AW_EFFECT_ORDER(60)

/* Reals between a trajectory's consecutive groups of samples (see above). */
#define AW_FREQ_GROUP_STRIDE (2 * AW_NAFF_GROUP * (aw_u64)AW_SERIES_BLOCK)
#define AW_FREQ_TAIL_RATE(g) (g)
#define AW_FREQ_TAIL_FINE 6

/* The first real of the block of record rec (its place in the block: rec % AW_SERIES_BLOCK). */
AW_FN AW_GLOBAL real* aw_series_block(aw_outputs out, AW_CONSTANT aw_iparams* ip, aw_u64 rec) {
  return out.series + (rec / AW_SERIES_BLOCK) * ((aw_u64)ip->series_reals * AW_SERIES_BLOCK);
}

/* Reals from a sample of signal g to the same sample of signal g + 1. */
AW_FN aw_u64 aw_series_signal(AW_CONSTANT aw_iparams* ip) {
  return (aw_u64)(AW_NAFF_PADDED((int)ip->frequency_samples) / AW_NAFF_GROUP) * AW_FREQ_GROUP_STRIDE;
}

/* Sample m (0 .. np - 1) of signal g of record rec: its re, then its im. */
AW_FN AW_GLOBAL real* aw_series_sample(aw_outputs out, AW_CONSTANT aw_iparams* ip, aw_u64 rec, int g, int m) {
  return aw_series_block(out, ip, rec) + (aw_u64)g * aw_series_signal(ip) +
         (rec % AW_SERIES_BLOCK) * (2 * AW_NAFF_GROUP) + aw_naff_sample_at(m, AW_FREQ_GROUP_STRIDE);
}

/* Element e of the tail of record rec. */
AW_FN AW_GLOBAL real* aw_series_tail(aw_outputs out, AW_CONSTANT aw_iparams* ip, aw_u64 rec, int e) {
  const aw_u64 np = (aw_u64)AW_NAFF_PADDED((int)ip->frequency_samples);
  return aw_series_block(out, ip, rec) + (12 * np + (aw_u64)e) * AW_SERIES_BLOCK + rec % AW_SERIES_BLOCK;
}

/* A group of lanes never crosses a block: the lanes' tail elements e are
 * consecutive (one vector load or store at aw_series_tail of the first). */
typedef char aw_lanes_divide_series_block[(AW_SERIES_BLOCK % AW_LANES == 0) ? 1 : -1];

#ifdef AW_FREQ_WINDOW_TABLE
/* A kernel's table of the window's weights (declared by the kernel, shared by
 * its group): item `item` of `items` computes its share. */
AW_FN void aw_freq_window_fill(AW_CONSTANT aw_iparams* ip, int item, int items) {
  const int n = (int)ip->frequency_samples;
  if (n > AW_FREQ_WINDOW_TABLE) return;
  for (int m = item; m < n; m += items) aw_freq_window_table[m] = aw_naff_window_at(m, n, (int)ip->frequency_order);
}
#endif

/* The window's weight chi_p at sample m of n: from the kernel's table where
 * it has one (the same function made it), else computed here. */
AW_FN real aw_freq_weight(AW_CONSTANT aw_iparams* ip, int m, int n) {
#ifdef AW_FREQ_WINDOW_TABLE
  if (n <= AW_FREQ_WINDOW_TABLE) return aw_freq_window_table[m];
#endif
  return aw_naff_window_at(m, n, (int)ip->frequency_order);
}

/* Sample k (0 .. 2n - 1) of the lanes' angles, multiplied by the window; at
 * the end of a window the mean rates, at the end of the second whether each
 * lane is fine. The padding past n is left alone (the analysis clears it:
 * aw_naff_clear_padding). Every lane, active or not: the buffer holds whole
 * blocks. Nothing is kept in registers between samples (the unwrapped angles
 * at a window's first sample wait in the rates' places): the integration
 * between samples has every register it had without frequencies. */
AW_FN void aw_freq_sample(const aw_lstate* s, const int* status, int k, aw_lanes l, AW_CONSTANT aw_iparams* ip,
                          aw_outputs out) {
  const int n = (int)ip->frequency_samples;
  const int window = (k >= n) ? 1 : 0;
  const int m = k - window * n;
  const aw_u64 first = AW_LANE_RECORD(l, 0); /* the lanes' records are consecutive */
  /* lane j's sample of angle d: at + d signal + j 2G (the lanes side by side in one block) */
  AW_GLOBAL real* at = aw_series_sample(out, ip, first, window * 3, m);
  const aw_u64 signal = aw_series_signal(ip);
  const lreal unwrapped[3] = {AW_INT_TO_LANE(s->wx) + s->ux, AW_INT_TO_LANE(s->wy) + s->uy,
                              AW_INT_TO_LANE(s->wz) + s->uz};
  const lreal u[3] = {s->ux, s->uy, s->uz};
  if (m == 0)
    for (int d = 0; d < 3; ++d)
      AW_STORE_LANES(unwrapped[d], aw_series_tail(out, ip, first, AW_FREQ_TAIL_RATE(window * 3 + d)));
  const real w = aw_freq_weight(ip, m, n);
  for (int d = 0; d < 3; ++d) {
    lreal sn, cs;
    aw_sincos2pi(u[d], &sn, &cs);
    real re[AW_LANES], im[AW_LANES];
    const lreal wr = AW_LSPLAT(w) * cs, wi = AW_LSPLAT(w) * sn;
    AW_STORE_LANES(wr, re);
    AW_STORE_LANES(wi, im);
    for (int j = 0; j < AW_LANES; ++j)
      AW_STORE_PAIR(at + (aw_u64)d * signal + (aw_u64)(2 * AW_NAFF_GROUP * j), re[j], im[j]);
  }
  if (m != n - 1) return;
  for (int d = 0; d < 3; ++d) {
    AW_GLOBAL real* tail = aw_series_tail(out, ip, first, AW_FREQ_TAIL_RATE(window * 3 + d));
    const lreal rate = (unwrapped[d] - AW_LOAD_LANES(tail)) / (real)(n - 1);
    AW_STORE_LANES(rate, tail);
  }
  if (window == 1)
    for (int j = 0; j < AW_LANES; ++j) {
      AW_GLOBAL real* fine = aw_series_tail(out, ip, first + (aw_u64)j, AW_FREQ_TAIL_FINE);
      *fine = (status[j] == AW_STATUS_OK) ? AW_R(1.0) : AW_R(0.0);
    }
}

/* The frequency (turns per T) of signal g = 3 w + d (window w, angle d) of
 * record rec: that of its largest term, found by the team from its mean rate
 * (aw_naff_largest_team): the rate's whole cycles per sample say which alias
 * of the sampled frequency is the true one, the rest is the start. NaN where
 * no maximum was found. */
AW_FN real aw_freq_signal(AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out, aw_u64 rec, int g,
                          aw_naff_team team) {
  const real rate = *aw_series_tail(out, ip, rec, AW_FREQ_TAIL_RATE(g));
  const real whole = AW_RINT_SMALL(rate);
  real f;
  int ok;
  AW_GLOBAL real* z = aw_series_sample(out, ip, rec, g, 0);
  aw_naff_clear_padding(z, AW_FREQ_GROUP_STRIDE, (int)ip->frequency_samples, team);
  aw_naff_largest_team(z, AW_FREQ_GROUP_STRIDE, (int)ip->frequency_samples, (int)ip->frequency_order, rate - whole,
                       team, &f, &ok);
  return ok ? (f + whole) / rp->frequency_every : aw_nan_real();
}

/* The analysis of record rec: its six frequencies and the record
 * (AW_OUT_FREQUENCIES); written by member 0 of a parallel team. The index
 * compares |nu|: a librating angle's largest term is one of a pair +-k f
 * about the centre's rate 0 of nearly equal amplitudes, either of which can be
 * the larger in a window (docs/frequencies.md); a rotating angle keeps its
 * sign, and its |nu(2)| - |nu(1)| is +-(nu(2) - nu(1)), the same square. */
AW_FN void aw_freq_analyse_record(aw_u64 rec, aw_naff_team team, AW_CONSTANT aw_rparams* rp,
                                  AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  const real nan = aw_nan_real();
  AW_GLOBAL real* r = aw_record_r(out, ip, AW_OUT_FREQUENCIES, rec);
  if (*aw_series_tail(out, ip, rec, AW_FREQ_TAIL_FINE) == AW_R(0.0)) { /* flagged: no analysis */
    if (team.member == 0)
      for (int d = 0; d < AW_FREQ_REALS; ++d) r[d] = nan;
    return;
  }
  real nu[6];
  for (int g = 0; g < 6; ++g) nu[g] = aw_freq_signal(rp, ip, out, rec, g, team);
  if (team.member != 0) return;
  const real dx = AW_FABS(nu[3]) - AW_FABS(nu[0]), dy = AW_FABS(nu[4]) - AW_FABS(nu[1]),
             dz = AW_FABS(nu[5]) - AW_FABS(nu[2]);
  for (int d = 0; d < 6; ++d) r[d] = nu[d];
  r[6] = AW_SQRT(AW_FMA(dz, dz, AW_FMA(dy, dy, dx * dx)));
}

#if !AW_NAFF_TEAM_PARALLEL
/* The analysis of a group of lanes on a CPU: one trajectory after another,
 * the team's members AW_LANES at a time in a vector (aw_naff.h, "teams"). */
AW_FN void aw_freq_analyse(aw_lanes l, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip, aw_outputs out) {
  const aw_naff_team team = {0, 0};
  for (int j = 0; j < AW_LANES; ++j)
    if (AW_LANE_ACTIVE(l, j)) aw_freq_analyse_record(AW_LANE_RECORD(l, j), team, rp, ip, out);
}
#endif

typedef struct {
  aw_count sample_at; /* (k + 1) / stride and its remainder after segment k */
} aw_fx_frequencies_state;

AW_FN void aw_fx_frequencies_counts(aw_config cfg, aw_fx_frequencies_state* me, aw_fx_core* fx, aw_i64 seg_first,
                                    AW_CONSTANT aw_iparams* ip) {
  if (AW_HAS(AW_F_FREQUENCIES)) me->sample_at = aw_count_at(seg_first, ip->frequency_stride);
}

AW_FN void aw_fx_frequencies_sample(aw_config cfg, aw_fx_frequencies_state* me, aw_fx_core* fx, const aw_lstate* s,
                                    aw_lanes l, AW_CONSTANT aw_rparams* rp, AW_CONSTANT aw_iparams* ip,
                                    aw_outputs out) {
  if (!AW_HAS(AW_F_FREQUENCIES)) return;
  aw_count_next(&me->sample_at, ip->frequency_stride);
  const aw_i64 q = me->sample_at.q - 1;
  if (me->sample_at.r == 0 && q < 2 * ip->frequency_samples) aw_freq_sample(s, fx->status, (int)q, l, ip, out);
}

#endif /* AW_FX_FREQUENCIES_H */
