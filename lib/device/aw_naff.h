/* arnoldweb portable device core: frequency analysis (NAFF, Laskar 1990,
 * 1993, 2003), the leading frequency of a complex signal sampled at equal
 * steps, refined to the maximum of the windowed Fourier transform
 * (docs/frequencies.md).
 *
 * The signal: n samples z_k = re[k stride] + i im[k stride], k = 0..n-1, of
 * one trajectory, in an AW_GLOBAL buffer. The stride lets the caller keep a
 * chunk's samples coalesced: sample k of trajectory j at base + k * stride + j
 * (stride = the trajectories of the chunk times the reals per sample).
 * Frequencies are in cycles per sample, in [-1/2, 1/2); a signal sampled
 * every dt T has nu = sigma / dt cycles (turns) per T, which for an angle in
 * turns is its rate of rotation (for fgl: nu_j = I_j at epsilon = 0).
 *
 * With m_k = k - (n - 1)/2 (the time from the window's centre, in samples),
 * the window chi_p(k) = (1 + cos(2 pi m_k / (n - 1)))^p (Laskar's chi_p up to
 * a constant factor: p = 0 none, p = 1 Hanning; zero at both ends) and
 *   S_j(sigma) = sum_k m_k^j chi_p(k) z_k exp(-2 pi i sigma m_k),  j = 0, 1, 2,
 * the windowed transform phi(sigma) = S_0 / sum chi_p. Its modulus is largest
 * where F'(sigma) = 4 pi Im(conj(S_0) S_1) vanishes, with
 * F''(sigma) = 8 pi^2 (|S_1|^2 - Re(conj(S_0) S_2)): one pass over the samples
 * gives a Newton step, safeguarded by a bracket of the maximum. The error of
 * the frequency from the other terms of a quasi-periodic signal falls like
 * 1/T^(2p+2) with the length T of the window (Laskar 2003): 1/T^4 for the
 * Hanning window; the round-off of one pass is ~eps sqrt(n) / n cycles per
 * sample.
 *
 * Portable and bitwise reproducible: scalar `real` per trajectory (callers
 * with AW_LANES > 1 loop over their lanes), only + - * / and explicit fma,
 * and the portable sin/cos (aw_sincos2pi_1); sums in a fixed order; no
 * recursion and no allocation: the coarse search by FFT works in a buffer of
 * the caller's. exp(-2 pi i sigma m_k) and the window are complex rotations
 * from one sample to the next, recomputed exactly every AW_NAFF_ANCHOR
 * samples, so their rounding errors stay bounded.
 *
 * The calls, for one signal:
 *   coarse:  aw_naff_fft_peak (a radix-2 FFT of the windowed samples in a
 *            work buffer of 2 m reals, m = 2^log2m >= n; the largest bin,
 *            interpolated) or aw_naff_scan (no buffer: |phi|^2 on a grid of
 *            frequencies near a guess, e.g. the mean rate of an angle from its
 *            winding counts), then
 *   refine:  aw_naff_refine (bracket, then safeguarded Newton to round-off),
 *   further: aw_naff_subtract removes the term found (the next call finds
 *            the next largest).
 * The kernels' form ("teams" below) shares each pass among a team, and finds
 * an angle's largest term from its mean rate without a work buffer
 * (aw_naff_largest_team: the maximum uphill from the mean rate where it holds
 * most of the power, else a grid outward from it until Parseval's identity
 * leaves no room for a higher term, then the refinement of its largest
 * maxima).
 */
#ifndef AW_NAFF_H
#define AW_NAFF_H

#include "aw_math.h"
#include "aw_params.h"

#define AW_NAFF_ANCHOR 32   /* rotations recomputed exactly every this many samples */
#define AW_NAFF_MAX_ITER 40 /* Newton/bisection passes of aw_naff_refine at most */
#define AW_NAFF_TWO_PI AW_R(6.283185307179586)
#define AW_NAFF_QUADRATIC AW_R(0.125) /* the margin of the last Newton step (aw_naff_search_step) */
#ifndef AW_LOCAL
#define AW_LOCAL /* the address space of a parallel team's scratch (kernels define it) */
#endif
#ifndef AW_NAFF_TEAM_PARALLEL
#define AW_NAFF_TEAM_PARALLEL 0 /* 1: a team's members are work-items (GPUs; see "teams" below) */
#endif

/* One pass's sums at a frequency: S_0, S_1, S_2 (real and imaginary parts)
 * and the sum of the window's weights. */
typedef struct {
  real s0r, s0i, s1r, s1i, s2r, s2i;
  real wsum;
} aw_naff_sums;

/* The result of aw_naff_refine. */
typedef struct {
  real freq;           /* cycles per sample */
  real amp_re, amp_im; /* complex amplitude phi = S_0 / sum chi_p at freq (phase at the window's centre) */
  int passes;          /* passes over the samples */
  int ok;              /* 1: a maximum was bracketed and refined; 0: none near the start (freq = the start) */
} aw_naff_result;

/* A rotation exp(2 pi i u_k), u_k = a m_k: (c, s) advanced by (dc, ds) =
 * exp(2 pi i a) from one sample to the next, recomputed from a m_k at every
 * anchor. */
typedef struct {
  real c, s, dc, ds, a;
} aw_naff_rotor;

/* The two steps of every pass, on scalars or lanes (type T), shared by
 * aw_naff_sums_at and aw_naff_member_sums: a rotation (c, s) advanced by
 * (dc, ds); a term a = (ar, ai) at time m added to the sums S_0, S_1, S_2
 * (acc[0 .. 5]: re, im of each). */
#define AW_NAFF_ROTATE(T, c, s, dc, ds)                    \
  do {                                                     \
    const T rotated_c_ = AW_FMA((c), (dc), -((s) * (ds))); \
    const T rotated_s_ = AW_FMA((s), (dc), (c) * (ds));    \
    (c) = rotated_c_;                                      \
    (s) = rotated_s_;                                      \
  } while (0)
/* (m^2 is exact while |m| < 2^26 in double, 2^12 in float: n < 8192) */
#define AW_NAFF_ADD_TERM(T, acc, ar, ai, m)     \
  do {                                          \
    (acc)[0] = (acc)[0] + (ar);                 \
    (acc)[1] = (acc)[1] + (ai);                 \
    (acc)[2] = AW_FMA((m), (ar), (acc)[2]);     \
    (acc)[3] = AW_FMA((m), (ai), (acc)[3]);     \
    const T squared_m_ = (m) * (m);             \
    (acc)[4] = AW_FMA(squared_m_, (ar), (acc)[4]); \
    (acc)[5] = AW_FMA(squared_m_, (ai), (acc)[5]); \
  } while (0)

AW_FN void aw_naff_rotor_begin(aw_naff_rotor* r, real a) {
  r->a = a;
  aw_sincos2pi_1(a, &r->ds, &r->dc);
  r->c = AW_R(1.0);
  r->s = AW_R(0.0);
}

/* The rotation at sample k, m = m_k: exact at the anchors, one complex
 * product from the previous sample between them. */
AW_FN void aw_naff_rotor_at(aw_naff_rotor* r, int k, real m) {
  if (k % AW_NAFF_ANCHOR == 0)
    aw_sincos2pi_1(r->a * m, &r->s, &r->c);
  else
    AW_NAFF_ROTATE(real, r->c, r->s, r->dc, r->ds);
}

/* chi_p from cos(2 pi m_k / (n - 1)): (1 + cos)^p. */
AW_FN real aw_naff_window(real cosine, int p) {
  const real b = AW_R(1.0) + cosine;
  real w = AW_R(1.0);
  for (int i = 0; i < p; ++i) w = w * b;
  return w;
}

/* The sums from S_0, S_1, S_2 (re, im: v[0 .. 5]) and the window's weights. */
AW_FN void aw_naff_sums_set(aw_naff_sums* out, const real* v, real wsum) {
  out->s0r = v[0];
  out->s0i = v[1];
  out->s1r = v[2];
  out->s1i = v[3];
  out->s2r = v[4];
  out->s2i = v[5];
  out->wsum = wsum;
}

/* One pass: the sums at sigma. n >= 3. */
AW_FN void aw_naff_sums_at(AW_GLOBAL const real* re, AW_GLOBAL const real* im, aw_u64 stride, int n, int p,
                           real sigma, aw_naff_sums* out) {
  const real centre = AW_R(0.5) * (real)(n - 1);
  aw_naff_rotor e, win;
  aw_naff_rotor_begin(&e, -sigma);
  aw_naff_rotor_begin(&win, AW_R(1.0) / (real)(n - 1));
  real acc[6] = {AW_R(0.0), AW_R(0.0), AW_R(0.0), AW_R(0.0), AW_R(0.0), AW_R(0.0)};
  real wsum = AW_R(0.0);
  for (int k = 0; k < n; ++k) {
    const real m = (real)k - centre; /* exact: a half-integer or an integer */
    aw_naff_rotor_at(&e, k, m);
    aw_naff_rotor_at(&win, k, m);
    const real w = aw_naff_window(win.c, p);
    const real zr = re[(aw_u64)k * stride], zi = im[(aw_u64)k * stride];
    /* a = w z exp(-2 pi i sigma m) */
    const real ar = w * AW_FMA(zr, e.c, -(zi * e.s));
    const real ai = w * AW_FMA(zr, e.s, zi * e.c);
    AW_NAFF_ADD_TERM(real, acc, ar, ai, m);
    wsum = wsum + w;
  }
  aw_naff_sums_set(out, acc, wsum);
}

/* Im(conj(S_0) S_1): the sign of d|phi|^2 / dsigma. */
AW_FN real aw_naff_slope(const aw_naff_sums* s) { return AW_FMA(s->s0r, s->s1i, -(s->s0i * s->s1r)); }

/* |S_1|^2 - Re(conj(S_0) S_2): negative near a maximum of |phi|. */
AW_FN real aw_naff_curvature(const aw_naff_sums* s) {
  const real a = AW_FMA(s->s1r, s->s1r, s->s1i * s->s1i);
  const real b = AW_FMA(s->s0r, s->s2r, s->s0i * s->s2i);
  return a - b;
}

/* |phi(sigma)|^2 = |S_0|^2 / (sum chi_p)^2. */
AW_FN real aw_naff_power(const aw_naff_sums* s) {
  const real r = s->s0r / s->wsum, i = s->s0i / s->wsum;
  return AW_FMA(r, r, i * i);
}

/* The frequency of the largest |phi|^2 among sigma_lo + j (sigma_hi -
 * sigma_lo) / (points - 1), j = 0..points-1 (the first of equal ones): a
 * coarse search without a work buffer, points passes. */
AW_FN real aw_naff_scan(AW_GLOBAL const real* re, AW_GLOBAL const real* im, aw_u64 stride, int n, int p,
                        real sigma_lo, real sigma_hi, int points) {
  real best = sigma_lo, best_power = AW_R(-1.0);
  const real step = (points > 1) ? (sigma_hi - sigma_lo) / (real)(points - 1) : AW_R(0.0);
  for (int j = 0; j < points; ++j) {
    const real sigma = AW_FMA((real)j, step, sigma_lo);
    aw_naff_sums s;
    aw_naff_sums_at(re, im, stride, n, p, sigma, &s);
    const real power = aw_naff_power(&s);
    if (power > best_power) {
      best_power = power;
      best = sigma;
    }
  }
  return best;
}

/* Bit reversal of j (bits low bits). */
AW_FN aw_u32 aw_naff_reverse(aw_u32 j, int bits) {
  aw_u32 r = 0;
  for (int b = 0; b < bits; ++b) {
    r = (r << 1) | (j & 1u);
    j >>= 1;
  }
  return r;
}

/* A coarse frequency: the windowed samples, zero-padded to m = 2^log2m >= n,
 * through an in-place radix-2 FFT in the work buffer (wre[j wstride], wim[j
 * wstride], j < m: 2 m reals the caller provides, overwritten); the bin of
 * the largest modulus (the first of equal ones), moved by the vertex of the
 * parabola through it and its two neighbours. Cycles per sample, in
 * [-1/2, 1/2). Cost: m sin/cos and (m/2) log2 m butterflies. */
AW_FN real aw_naff_fft_peak(AW_GLOBAL const real* re, AW_GLOBAL const real* im, aw_u64 stride, int n, int p,
                            AW_GLOBAL real* wre, AW_GLOBAL real* wim, aw_u64 wstride, int log2m) {
  const aw_u32 m = 1u << log2m;
  const real centre = AW_R(0.5) * (real)(n - 1);
  aw_naff_rotor win;
  aw_naff_rotor_begin(&win, AW_R(1.0) / (real)(n - 1));
  /* windowed samples in bit-reversed order; the padding zero */
  for (aw_u32 j = 0; j < m; ++j) {
    real xr = AW_R(0.0), xi = AW_R(0.0);
    if ((int)j < n) {
      aw_naff_rotor_at(&win, (int)j, (real)(int)j - centre);
      const real w = aw_naff_window(win.c, p);
      xr = w * re[(aw_u64)j * stride];
      xi = w * im[(aw_u64)j * stride];
    }
    const aw_u64 r = (aw_u64)aw_naff_reverse(j, log2m) * wstride;
    wre[r] = xr;
    wim[r] = xi;
  }
  /* butterflies: X = sum_k x_k exp(-2 pi i j k / m) */
  for (aw_u32 len = 2; len <= m; len <<= 1) {
    const aw_u32 span = len >> 1;
    const real inv_len = AW_R(1.0) / (real)len; /* a power of two: exact */
    for (aw_u32 j = 0; j < span; ++j) {
      real ts, tc;
      aw_sincos2pi_1(-((real)j * inv_len), &ts, &tc);
      for (aw_u32 b = j; b < m; b += len) {
        const aw_u64 ia = (aw_u64)b * wstride, ib = (aw_u64)(b + span) * wstride;
        const real br = AW_FMA(wre[ib], tc, -(wim[ib] * ts));
        const real bi = AW_FMA(wre[ib], ts, wim[ib] * tc);
        const real ar = wre[ia], ai = wim[ia];
        wre[ia] = ar + br;
        wim[ia] = ai + bi;
        wre[ib] = ar - br;
        wim[ib] = ai - bi;
      }
    }
  }
  /* the largest bin */
  aw_u32 jmax = 0;
  real pmax = AW_R(-1.0);
  for (aw_u32 j = 0; j < m; ++j) {
    const aw_u64 i = (aw_u64)j * wstride;
    const real power = AW_FMA(wre[i], wre[i], wim[i] * wim[i]);
    if (power > pmax) {
      pmax = power;
      jmax = j;
    }
  }
  const aw_u64 il = (aw_u64)((jmax + m - 1u) & (m - 1u)) * wstride, ir = (aw_u64)((jmax + 1u) & (m - 1u)) * wstride;
  const real al = AW_SQRT(AW_FMA(wre[il], wre[il], wim[il] * wim[il]));
  const real ar = AW_SQRT(AW_FMA(wre[ir], wre[ir], wim[ir] * wim[ir]));
  const real a0 = AW_SQRT(pmax);
  const real den = (al + ar) - AW_R(2.0) * a0;
  const real shift = (den < AW_R(0.0)) ? (AW_R(0.5) * (al - ar)) / den : AW_R(0.0); /* in (-1/2, 1/2) at a peak */
  real sigma = ((real)jmax + shift) / (real)m;
  if (sigma >= AW_R(0.5)) sigma = sigma - AW_R(1.0);
  return sigma;
}

/* The state of the search for one maximum (aw_naff_refine's steps). */
typedef struct {
  real x, lo, hi, last_newton;
  int have_lo, have_hi, newton_before, done;
} aw_naff_search;

AW_FN void aw_naff_search_begin(aw_naff_search* q, real sigma0) {
  q->x = sigma0;
  q->lo = q->hi = q->last_newton = AW_R(0.0);
  q->have_lo = q->have_hi = q->newton_before = q->done = 0;
}

/* One step of the search from the sums at q->x: 1 when it moved q->x and
 * wants the sums there, 0 when it stopped (q->done: at a maximum; else the
 * sums were not finite). */
AW_FN int aw_naff_search_step(aw_naff_search* q, const aw_naff_sums* s, int n) {
#ifdef AW_FLOAT
  const real eps = AW_R(1.1920928955078125e-07);
#else
  const real eps = AW_R(2.220446049250313e-16);
#endif
  const real half_bin = AW_R(0.5) / (real)n;
  const real g = aw_naff_slope(s), c = aw_naff_curvature(s);
  if (!(g == g && c == c)) return 0; /* not finite */
  if (g == AW_R(0.0) && c < AW_R(0.0)) {
    q->done = 1;
    return 0;
  }
  if (g > AW_R(0.0)) {
    q->lo = q->x;
    q->have_lo = 1;
  } else {
    q->hi = q->x;
    q->have_hi = 1;
  }
  real step = (c < AW_R(0.0)) ? -g / (AW_NAFF_TWO_PI * c) : AW_R(0.0);
  int newton = c < AW_R(0.0) && AW_FABS(step) <= half_bin;
  if (!newton) step = (g > AW_R(0.0)) ? half_bin : -half_bin; /* uphill */
  /* Newton converges quadratically: after a step of size s the error is about
   * s^2 / (the width of the peak, ~ a bin), so a step below
   * AW_NAFF_QUADRATIC sqrt(eps (|x| + half a bin) half a bin) leaves an error
   * below eps (|x| + half a bin), round-off, without another pass to see it
   * (compared squared: no square root in every pass). */
  if (newton && step * step <= AW_NAFF_QUADRATIC * AW_NAFF_QUADRATIC * (eps * (AW_FABS(q->x) + half_bin) * half_bin)) {
    q->x = q->x + step;
    q->done = 1;
    return 0;
  }
  real next = q->x + step;
  if (q->have_lo && q->have_hi && !(next > q->lo && next < q->hi)) {
    next = AW_R(0.5) * (q->lo + q->hi);
    newton = 0;
  }
  const real size = AW_FABS(next - q->x);
  if (size <= eps * (AW_FABS(q->x) + half_bin)) { /* a bracket as narrow as round-off */
    q->x = next;
    q->done = 1;
    return 0;
  }
  if (newton && q->newton_before && size > AW_R(0.5) * q->last_newton) {
    q->done = 1; /* the round-off floor: keep x */
    return 0;
  }
  q->newton_before = newton;
  if (newton) q->last_newton = size;
  q->x = next;
  return 1;
}

/* The frequency of the maximum of |phi| nearest to sigma0 (within the main
 * lobe of the window, about p + 1 bins of 1/n), to round-off. Each pass gives
 * the slope g and the curvature c of |phi|^2 at x: where c < 0 (near the
 * maximum) the Newton step -g / (2 pi c) if it is below half a bin, else half
 * a bin uphill; once the maximum is bracketed (slopes of both signs seen), a
 * Newton step that leaves the bracket is replaced by its midpoint. It stops
 * after a Newton step below AW_NAFF_QUADRATIC sqrt(eps (|x| + 1/(2n)) / (2n))
 * (Newton's error after it, quadratic, is below round-off), when a step (or
 * the bracket) is below eps (|x| + 1/(2n)), or when two Newton steps in a row
 * stop shrinking (the round-off floor of g: the last x is kept).
 * ok = 0 (and freq = sigma0) where no maximum was found within
 * AW_NAFF_MAX_ITER passes, or the samples are not finite. n >= 3, p >= 0. */
AW_FN void aw_naff_refine(AW_GLOBAL const real* re, AW_GLOBAL const real* im, aw_u64 stride, int n, int p,
                          real sigma0, aw_naff_result* out) {
  aw_naff_search q;
  aw_naff_search_begin(&q, sigma0);
  aw_naff_sums s;
  aw_naff_sums_at(re, im, stride, n, p, q.x, &s);
  int passes = 1;
  for (int it = 0; it < AW_NAFF_MAX_ITER && aw_naff_search_step(&q, &s, n); ++it) {
    aw_naff_sums_at(re, im, stride, n, p, q.x, &s);
    passes += 1;
  }
  out->ok = q.done;
  out->freq = q.done ? q.x : sigma0;
  out->amp_re = s.s0r / s.wsum;
  out->amp_im = s.s0i / s.wsum;
  out->passes = passes;
}

/* z_k -= a exp(2 pi i sigma m_k): the term (sigma, a) of aw_naff_refine
 * removed from the samples in place, so that the next refinement finds the
 * next largest term (Laskar's NAFF subtracts the found terms in turn; for
 * frequencies separated by many bins their exponentials are orthogonal over
 * the window to O(1/(T dnu)^(2p+1)), which this neglects). */
AW_FN void aw_naff_subtract(AW_GLOBAL real* re, AW_GLOBAL real* im, aw_u64 stride, int n, real sigma, real amp_re,
                            real amp_im) {
  const real centre = AW_R(0.5) * (real)(n - 1);
  aw_naff_rotor e;
  aw_naff_rotor_begin(&e, sigma);
  for (int k = 0; k < n; ++k) {
    aw_naff_rotor_at(&e, k, (real)k - centre);
    const aw_u64 i = (aw_u64)k * stride;
    re[i] = re[i] - AW_FMA(amp_re, e.c, -(amp_im * e.s));
    im[i] = im[i] - AW_FMA(amp_re, e.s, amp_im * e.c);
  }
}

/* ------------------------------------------------------------------ teams
 * The kernels' passes. A window's samples z_k = (re, im) are stored in
 * groups of G = AW_NAFF_GROUP: samples G q .. G q + G - 1 as 2 G reals (re,
 * im, re, im, ..) at z + q gs (gs = 2 G where the groups follow each other;
 * the series buffer interleaves the groups of a block of trajectories:
 * effects/aw_fx_frequencies.h), already multiplied by the window chi_p
 * (aw_naff_window_at), and padded with zeros to np = AW_NAFF_PADDED(n)
 * samples. A pass is shared by a team of T = AW_NAFF_TEAM members: member t
 * sums the samples k = t + T i (i = 0 .. np/T - 1) in order, its rotation
 * exp(-2 pi i sigma m_k) recomputed exactly every AW_NAFF_ANCHOR of its
 * samples and advanced by exp(-2 pi i sigma T) between them; the members'
 * sums are then added pairwise, p[t] += p[t + h] for h = T/2, T/4, .., 1
 * (aw_naff_tree). On a GPU the team is a warp, one member a work-item, and
 * a load of the warp reads eight whole groups (several passes of a
 * trajectory from the cache); on a CPU one work-item computes every
 * member, AW_LANES members at a time in a vector. Either way every member's
 * sums are the same operations in the same order, and so is the tree: the
 * same bits everywhere (tests/frequencies: "team"). The sums differ from
 * aw_naff_sums_at's by round-off only (another order of the same terms). */

/* chi_p at sample k of n (aw_naff_sums_at's window, exact at every sample):
 * the samples are stored multiplied by it. */
AW_FN real aw_naff_window_at(int k, int n, int p) {
  real s, c;
  aw_sincos2pi_1(((real)k - AW_R(0.5) * (real)(n - 1)) / (real)(n - 1), &s, &c);
  return aw_naff_window(c, p);
}

/* Where sample k lies from the window's first real, its groups gs reals
 * apart: group k / G, place k % G (its re; its im follows). */
AW_FN aw_u64 aw_naff_sample_at(int k, aw_u64 gs) {
  return (aw_u64)(k / AW_NAFF_GROUP) * gs + (aw_u64)(2 * (k % AW_NAFF_GROUP));
}

/* A member's samples lie at one place of their groups (aw_naff_member_sums). */
typedef char aw_naff_group_divides_team[(AW_NAFF_TEAM % AW_NAFF_GROUP == 0) ? 1 : -1];

/* Add the members' values pairwise (p[0 .. T-1], overwritten): the tree. */
AW_FN real aw_naff_tree(real* p) {
  for (int h = AW_NAFF_TEAM / 2; h >= 1; h >>= 1)
    for (int t = 0; t < h; ++t) p[t] = p[t] + p[t + h];
  return p[0];
}

/* Members t0 .. t0 + AW_LANES - 1 (a lane each): their sums S_0, S_1, S_2
 * (re, im) at sigma, v[0 .. 5]; with full = 0 only S_0 (v[2 .. 5] zero: the
 * grid of aw_naff_largest_team needs |S_0| only; S_0 the same bits). Their
 * samples are loaded AW_NAFF_BATCH ahead of their use: a member's pass is a
 * chain of dependent rotations, and a GPU work-item waiting for each load in
 * turn would run at the memory's latency. */
#ifndef AW_NAFF_BATCH
#define AW_NAFF_BATCH 8
#endif
AW_FN void aw_naff_member_sums(AW_GLOBAL const real* z, aw_u64 gs, int n, int t0, real sigma, int full, lreal* v) {
  const int chain = AW_NAFF_PADDED(n) / AW_NAFF_TEAM;
  const real centre = AW_R(0.5) * (real)(n - 1);
  /* a member's samples k = t + T i lie in groups t / G + (T / G) i at place
   * t % G: from its first one to the next, `along` reals (no division per
   * sample: dividing each sample's index was a quarter of the GPU analysis
   * kernel's instructions) */
  const aw_u64 along = (aw_u64)(AW_NAFF_TEAM / AW_NAFF_GROUP) * gs;
  real first[AW_LANES];
  aw_u64 start[AW_LANES];
  for (int j = 0; j < AW_LANES; ++j) {
    first[j] = (real)(t0 + j) - centre; /* exact: half-integers or integers */
    start[j] = aw_naff_sample_at(t0 + j, gs);
  }
  lreal m = AW_LOAD_LANES(first); /* the time of the member's sample i: + T per sample, exact */
  const lreal team_time = AW_LSPLAT((real)AW_NAFF_TEAM);
  const lreal a = AW_LSPLAT(-sigma);
  real ds1, dc1;
  aw_sincos2pi_1(-sigma * (real)AW_NAFF_TEAM, &ds1, &dc1);
  const lreal dc = AW_LSPLAT(dc1), ds = AW_LSPLAT(ds1);
  lreal ec = AW_LSPLAT(AW_R(1.0)), es = AW_LSPLAT(AW_R(0.0));
  lreal acc[6] = {es, es, es, es, es, es};
  for (int i0 = 0; i0 < chain; i0 += AW_NAFF_BATCH) {
    lreal zr[AW_NAFF_BATCH], zi[AW_NAFF_BATCH];
    for (int b = 0; b < AW_NAFF_BATCH; ++b) {
      const int i = (i0 + b < chain) ? i0 + b : chain - 1; /* past the end: loaded again, not used */
      const aw_u64 offset = (aw_u64)i * along;
#if AW_LANES == 1
      AW_LOAD_PAIR(z + start[0] + offset, zr[b], zi[b]);
#else
      real r[AW_LANES], q[AW_LANES];
      for (int j = 0; j < AW_LANES; ++j) {
        r[j] = z[start[j] + offset];
        q[j] = z[start[j] + offset + 1];
      }
      zr[b] = AW_LOAD_LANES(r);
      zi[b] = AW_LOAD_LANES(q);
#endif
    }
    for (int b = 0; b < AW_NAFF_BATCH && i0 + b < chain; ++b) {
      if ((i0 + b) % AW_NAFF_ANCHOR == 0)
        aw_sincos2pi(a * m, &es, &ec);
      else
        AW_NAFF_ROTATE(lreal, ec, es, dc, ds);
      const lreal ar = AW_FMA(zr[b], ec, -(zi[b] * es));
      const lreal ai = AW_FMA(zr[b], es, zi[b] * ec);
      if (full) {
        AW_NAFF_ADD_TERM(lreal, acc, ar, ai, m);
      } else {
        acc[0] = acc[0] + ar;
        acc[1] = acc[1] + ai;
      }
      m = m + team_time;
    }
  }
  for (int q = 0; q < 6; ++q) v[q] = acc[q];
}

/* Who computes a pass: on a GPU (AW_NAFF_TEAM_PARALLEL, one lane) this
 * work-item is member `member` of a team whose work-items meet in `scratch`
 * (OpenCL: 6 T reals of local memory, the team a work-group; CUDA: a warp,
 * by shuffles, no scratch); elsewhere one work-item is the whole team. */
typedef struct {
  int member;
  AW_LOCAL real* scratch;
} aw_naff_team;

#if AW_NAFF_TEAM_PARALLEL
typedef char aw_naff_team_parallel_needs_one_lane[(AW_LANES == 1) ? 1 : -1];
#if defined(AW_CUDA)
typedef char aw_naff_team_is_a_warp[(AW_NAFF_TEAM == 32) ? 1 : -1];
#endif
/* The tree across the team's work-items: every member gets the total. With
 * shuffles, member t adds the value of member t ^ h: its node of the tree
 * (addition commutes, bit for bit). */
AW_FN void aw_naff_team_tree(aw_naff_team team, real* v) {
#if defined(AW_CUDA)
  /* Scattered, then gathered: at each of the first levels a member keeps half
   * of the values it still holds and adds its partner's copies of them (the
   * partner, t ^ h, keeps the other half): the same sums in the same pairs,
   * 9 additions and 15 shuffles for the six totals instead of 30 and 30.
   * Member t then holds the total of value (t >> 2) & 7 (6, 7: zeros). */
  const int t = team.member;
  real a[8] = {v[0], v[1], v[2], v[3], v[4], v[5], AW_R(0.0), AW_R(0.0)};
  int held = 8;
  for (int h = AW_NAFF_TEAM / 2; h >= 1; h >>= 1) {
    if (held > 1) {
      held /= 2;
      const int upper = (t & h) != 0; /* keeps a[held ..], gives a[0 .. held) */
      for (int j = 0; j < held; ++j) {
        const real keep = upper ? a[j + held] : a[j];
        const real give = upper ? a[j] : a[j + held];
        a[j] = keep + __shfl_xor_sync(0xffffffffu, give, h);
      }
    } else {
      a[0] = a[0] + __shfl_xor_sync(0xffffffffu, a[0], h);
    }
  }
  for (int q = 0; q < 6; ++q) v[q] = __shfl_sync(0xffffffffu, a[0], q << 2);
#else
  const int t = team.member;
  AW_LOCAL real* p = team.scratch; /* p[q T + t]: value q of member t */
  for (int q = 0; q < 6; ++q) p[q * AW_NAFF_TEAM + t] = v[q];
  AW_BARRIER();
  for (int h = AW_NAFF_TEAM / 2; h >= 1; h >>= 1) {
    if (t < h)
      for (int q = 0; q < 6; ++q) p[q * AW_NAFF_TEAM + t] = p[q * AW_NAFF_TEAM + t] + p[q * AW_NAFF_TEAM + t + h];
    AW_BARRIER();
  }
  for (int q = 0; q < 6; ++q) v[q] = p[q * AW_NAFF_TEAM];
  AW_BARRIER(); /* every member has read the totals before the next pass writes */
#endif
}
#endif

/* The padding of a window's samples (np - n of them past sample n - 1) made
 * zero by the members who read it: member t's last sample t + T (np/T - 1)
 * where it is past n. The buffer is not cleared beforehand (clearing a
 * launch's whole series took 10 ms of a 0.27 s run on an H200); each member
 * reads only its own samples, so its own stores are all the order its passes
 * need. On a CPU the work-item clears every member's. */
AW_FN void aw_naff_clear_padding(AW_GLOBAL real* z, aw_u64 gs, int n, aw_naff_team team) {
#if AW_NAFF_TEAM_PARALLEL
  const int t0 = team.member, t1 = team.member + 1;
#else
  const int t0 = 0, t1 = AW_NAFF_TEAM;
  (void)team;
#endif
  for (int t = t0; t < t1; ++t) {
    const int k = AW_NAFF_PADDED(n) - AW_NAFF_TEAM + t; /* the member's last sample */
    if (k < n) continue;
    AW_STORE_PAIR(z + aw_naff_sample_at(k, gs), AW_R(0.0), AW_R(0.0));
  }
}

/* One pass of the team at sigma: the sums of aw_naff_sums_at with p = 0 (the
 * samples prewindowed), in the team's order; S_0 only where full = 0. */
AW_FN void aw_naff_team_sums(AW_GLOBAL const real* z, aw_u64 gs, int n, real sigma, int full, aw_naff_team team,
                             aw_naff_sums* s) {
  real v[6];
#if AW_NAFF_TEAM_PARALLEL
  aw_naff_member_sums(z, gs, n, team.member, sigma, full, v);
  aw_naff_team_tree(team, v);
#else
  (void)team;
  real p[6][AW_NAFF_TEAM];
  for (int t0 = 0; t0 < AW_NAFF_TEAM; t0 += AW_LANES) {
    lreal lv[6];
    aw_naff_member_sums(z, gs, n, t0, sigma, full, lv);
    for (int q = 0; q < 6; ++q) AW_STORE_LANES(lv[q], &p[q][t0]);
  }
  for (int q = 0; q < 6; ++q) v[q] = aw_naff_tree(p[q]);
#endif
  aw_naff_sums_set(s, v, AW_R(1.0));
}

/* |S_0|^2 of a pass: |phi|^2 times (sum chi_p)^2. */
AW_FN real aw_naff_team_power(const aw_naff_sums* s) { return AW_FMA(s->s0r, s->s0r, s->s0i * s->s0i); }

/* aw_naff_refine's search from sigma0 with the team's passes: *freq its
 * frequency (cycles per sample; sigma0 where *ok = 0), *power |S_0|^2 of its
 * last pass (|phi|^2 (sum chi_p)^2), *ok as aw_naff_refine's ok. Every member
 * of a parallel team takes the same steps (the same totals). */
AW_FN void aw_naff_refine_team(AW_GLOBAL const real* z, aw_u64 gs, int n, real sigma0, aw_naff_team team, real* freq,
                               real* power, int* ok) {
  aw_naff_search q;
  aw_naff_search_begin(&q, sigma0);
  aw_naff_sums s;
  aw_naff_team_sums(z, gs, n, q.x, 1, team, &s);
  for (int it = 0; it < AW_NAFF_MAX_ITER && aw_naff_search_step(&q, &s, n); ++it)
    aw_naff_team_sums(z, gs, n, q.x, 1, team, &s);
  *ok = q.done;
  *freq = q.done ? q.x : sigma0;
  *power = aw_naff_team_power(&s);
}

/* ---------------------------------------------------------- the largest term
 * NAFF's frequency is that of the largest term: the highest maximum of |phi|
 * over the spectrum, not the one nearest a guess. aw_naff_largest_team finds
 * it for the signal of an angle, z_k = chi_p(k) exp(2 pi i u_k) (modulus 1
 * before the window), from sigma0, the angle's mean rate over the window:
 *  1. the maximum uphill from sigma0 (aw_naff_refine_team), at sigma1, of
 *     |phi|^2 = A^2. Where A^2 >= AW_NAFF_SURE = (4 + sqrt 7) / 8 (A >=
 *     0.911) it is the largest term (below), and that is the answer: a
 *     rotating angle's leading term holds nearly all of its power, and this is
 *     the frequency, bit for bit, that the search from the mean rate alone
 *     gave.
 *  2. Else (a librating angle: its terms at k times the libration frequency
 *     about the centre's rate, the largest often not the one nearest the mean
 *     rate; a chaotic one): |phi|^2 on the grid sigma1 + j / n, j = 0, 1,
 *     -1, 2, -2, ... (a pass per point, S_0 alone), until what the grid's
 *     points not yet seen can hold is too little for a term above the highest
 *     seen: by Parseval, the n points of the whole period (spacing 1/n) add
 *     up to n sum |z_k|^2 = n sum chi_p^2 (in |S_0|^2), so the points not yet
 *     seen hold at most R = n sum chi_p^2 - (the sum seen), and the grid
 *     stops when R < AW_NAFF_CANDIDATE B, B the highest |S_0|^2 seen (at
 *     sigma1 or on the grid); at most the n points. Where A^2 >=
 *     AW_NAFF_MAIN_LOBE (0.52; AW_NAFF_MAIN_LOBE_0 = 0.655 without a
 *     window), only j = -(p + 1) .. p + 1: a higher maximum can only lie in
 *     the main lobe of the one found (below).
 *  3. The grid's local maxima (its ends against their one neighbour; not
 *     j = 0, sigma1's own) whose |S_0|^2 is at least AW_NAFF_CANDIDATE B, at
 *     most AW_NAFF_CANDIDATES of them, largest first, each refined; the answer
 *     is the highest of these maxima and sigma1 (the earlier of equal ones).
 * Why these suffice: in the inner product <f, g> = sum chi_p f conj(g) /
 * sum chi_p the signal has norm 1 and phi(sigma) = <z, e_sigma> with
 * e_sigma(k) = exp(2 pi i sigma m_k), also of norm 1, and <e_a, e_b> =
 * W(a - b), the window's normalised transform. Were |phi(b)| = B >= |phi(a)|
 * = A for some b, then z = phi(b) e_b + r with |r|^2 = 1 - B^2, and A <=
 * B |W(a - b)| + sqrt(1 - B^2), so |W(a - b)| >= A - sqrt(1 - A^2): from
 * A^2 = (4 + sqrt 7) / 8 on that is >= 1/2, and a higher maximum could lie
 * only where the window's transform is above half its peak, within its
 * half-width (about a bin for the Hanning window), on the same hump, where
 * two terms are not resolved; beyond the main lobe (p + 1 bins) |W| is at
 * most the window's largest sidelobe (0.221 for p = 0, 0.027 for p >= 1: the
 * Hanning window's 0.0267, less for p >= 2; measured for n = 16 to 4096),
 * and A - sqrt(1 - A^2) exceeds it from A^2 = 0.655, 0.52 on. A lobe's peak
 * lies within half a bin of a grid point, where the window's transform is at
 * least 2/pi of its peak (p = 0; more for p >= 1): its nearest point has
 * |S_0|^2 of at least (2/pi)^2 = 0.405 of the peak's, hence AW_NAFF_CANDIDATE
 * = 0.4: a lobe higher than B among the points not seen would put more than
 * 0.4 B there. Tested against an independent NAFF (tests/frequencies: a dense
 * scan of the whole spectrum in long double) on librating signals, and on
 * every cell of the FGL frequency map (docs/frequencies.md). Every member of a
 * parallel team takes the same steps from the same totals: the same bits on
 * every device and form. */
#define AW_NAFF_SURE AW_R(0.8307189138830738) /* (4 + sqrt 7) / 8 */
#define AW_NAFF_MAIN_LOBE AW_R(0.52)    /* A - sqrt(1 - A^2) > 0.027, the largest sidelobe of chi_p, p >= 1 */
#define AW_NAFF_MAIN_LOBE_0 AW_R(0.655) /* A - sqrt(1 - A^2) > 0.221, the largest sidelobe without a window */
#define AW_NAFF_CANDIDATE AW_R(0.4)
#define AW_NAFF_CANDIDATES 3

/* sum_k chi_p(k), k = 0..n-1: (n - 1) C(2p, p) / 2^p, and 1 more for p = 0
 * (the mean of (1 + cos)^p over a period times the n - 1 intervals; n - 1 > p;
 * the last sample's weight is (1 + cos pi)^p, 0 for p >= 1). sum chi_p^2 is
 * aw_naff_window_sum(n, 2 p). */
AW_FN real aw_naff_window_sum(int n, int p) {
  real c = AW_R(1.0);
  for (int i = 1; i <= p; ++i) c = c * (real)(2 * i - 1) / (real)i;
  return c * (real)(n - 1) + ((p == 0) ? AW_R(1.0) : AW_R(0.0));
}

/* A grid maximum (sigma, |S_0|^2) into the list of the largest (at most
 * AW_NAFF_CANDIDATES, largest first; after equal ones). */
AW_FN void aw_naff_candidate(real* f, real* pw, int* count, real sigma, real power) {
  int i = *count;
  if (i == AW_NAFF_CANDIDATES) {
    if (!(power > pw[i - 1])) return;
    i -= 1;
  } else {
    *count += 1;
  }
  for (; i > 0 && power > pw[i - 1]; --i) {
    f[i] = f[i - 1];
    pw[i] = pw[i - 1];
  }
  f[i] = sigma;
  pw[i] = power;
}

/* One end of the grid as it grows outward from sigma1: its last two powers
 * (inner, outer) and the outer one's frequency. */
typedef struct {
  real inner, outer, sigma;
} aw_naff_edge;

/* The edge grows by a point (sigma, power): its former outer point, now
 * between two seen ones, is a candidate where it is a local maximum (not
 * j = 0, sigma1's own: at_centre). */
AW_FN void aw_naff_edge_grow(aw_naff_edge* e, real sigma, real power, int at_centre, real* f, real* pw, int* count) {
  if (!at_centre && e->outer >= e->inner && e->outer >= power) aw_naff_candidate(f, pw, count, e->sigma, e->outer);
  e->inner = e->outer;
  e->outer = power;
  e->sigma = sigma;
}

/* The frequency of the largest term (cycles per sample; sigma0 where *ok = 0)
 * of an angle's signal, prewindowed by chi_p, as the team's passes find it
 * from the angle's mean rate sigma0 (see above). *ok = 0 where no maximum was
 * found (the samples not finite). */
AW_FN void aw_naff_largest_team(AW_GLOBAL const real* z, aw_u64 gs, int n, int p, real sigma0, aw_naff_team team,
                                real* freq, int* ok) {
  real best, best_power;
  aw_naff_refine_team(z, gs, n, sigma0, team, &best, &best_power, ok);
  const real weights = aw_naff_window_sum(n, p), scale = weights * weights;
  if (!*ok || best_power >= AW_NAFF_SURE * scale) { /* the largest term, or not finite */
    *freq = *ok ? best : sigma0;
    return;
  }
  const int points = (best_power >= ((p == 0) ? AW_NAFF_MAIN_LOBE_0 : AW_NAFF_MAIN_LOBE) * scale) ? 2 * p + 3 : n;
  const real bin = AW_R(1.0) / (real)n;
  real unseen = (real)n * aw_naff_window_sum(n, 2 * p); /* Parseval: the grid's total |S_0|^2 */
  real highest = best_power, f[AW_NAFF_CANDIDATES], pw[AW_NAFF_CANDIDATES];
  int count = 0;
  aw_naff_edge left = {AW_R(-1.0), AW_R(-1.0), best}, right = left;
  for (int s = 0; s < points; ++s) {
    const int j = (s & 1) ? (s + 1) / 2 : -(s / 2); /* 0, 1, -1, 2, -2, ... */
    const real sigma = AW_FMA((real)j, bin, best);
    aw_naff_sums q;
    aw_naff_team_sums(z, gs, n, sigma, 0, team, &q);
    const real power = aw_naff_team_power(&q);
    unseen = unseen - power;
    highest = (power > highest) ? power : highest;
    if (j > 0 || s == 0) aw_naff_edge_grow(&right, sigma, power, j == 1, f, pw, &count);
    if (j < 0 || s == 0) aw_naff_edge_grow(&left, sigma, power, j == -1, f, pw, &count);
    if (unseen < AW_NAFF_CANDIDATE * highest) break;
  }
  /* the ends, against their one inner neighbour */
  if (right.outer >= right.inner && right.sigma != best) aw_naff_candidate(f, pw, &count, right.sigma, right.outer);
  if (left.outer >= left.inner && left.sigma != best) aw_naff_candidate(f, pw, &count, left.sigma, left.outer);
  for (int i = 0; i < count; ++i) {
    if (!(pw[i] >= AW_NAFF_CANDIDATE * highest)) break;
    real g, power;
    int good;
    aw_naff_refine_team(z, gs, n, f[i], team, &g, &power, &good);
    if (good && power > best_power) {
      best = g;
      best_power = power;
    }
  }
  *freq = best;
}

#endif /* AW_NAFF_H */
