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
 */
#ifndef AW_NAFF_H
#define AW_NAFF_H

#include "aw_math.h"

#define AW_NAFF_ANCHOR 32   /* rotations recomputed exactly every this many samples */
#define AW_NAFF_MAX_ITER 40 /* Newton/bisection passes of aw_naff_refine at most */
#define AW_NAFF_TWO_PI AW_R(6.283185307179586)
#define AW_NAFF_QUADRATIC AW_R(0.125) /* the margin of the last Newton step (aw_naff_search_step) */

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

AW_FN void aw_naff_rotor_begin(aw_naff_rotor* r, real a) {
  r->a = a;
  aw_sincos2pi_1(a, &r->ds, &r->dc);
  r->c = AW_R(1.0);
  r->s = AW_R(0.0);
}

/* The rotation at sample k, m = m_k: exact at the anchors, one complex
 * product from the previous sample between them. */
AW_FN void aw_naff_rotor_at(aw_naff_rotor* r, int k, real m) {
  if (k % AW_NAFF_ANCHOR == 0) {
    aw_sincos2pi_1(r->a * m, &r->s, &r->c);
  } else {
    const real c = AW_FMA(r->c, r->dc, -(r->s * r->ds));
    const real s = AW_FMA(r->s, r->dc, r->c * r->ds);
    r->c = c;
    r->s = s;
  }
}

/* chi_p from cos(2 pi m_k / (n - 1)): (1 + cos)^p. */
AW_FN real aw_naff_window(real cosine, int p) {
  const real b = AW_R(1.0) + cosine;
  real w = AW_R(1.0);
  for (int i = 0; i < p; ++i) w = w * b;
  return w;
}

/* One pass: the sums at sigma. n >= 3. */
AW_FN void aw_naff_sums_at(AW_GLOBAL const real* re, AW_GLOBAL const real* im, aw_u64 stride, int n, int p,
                           real sigma, aw_naff_sums* out) {
  const real centre = AW_R(0.5) * (real)(n - 1);
  aw_naff_rotor e, win;
  aw_naff_rotor_begin(&e, -sigma);
  aw_naff_rotor_begin(&win, AW_R(1.0) / (real)(n - 1));
  real s0r = AW_R(0.0), s0i = AW_R(0.0), s1r = AW_R(0.0), s1i = AW_R(0.0), s2r = AW_R(0.0), s2i = AW_R(0.0);
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
    s0r = s0r + ar;
    s0i = s0i + ai;
    s1r = AW_FMA(m, ar, s1r);
    s1i = AW_FMA(m, ai, s1i);
    const real mm = m * m; /* exact while |m| < 2^26 (double), 2^12 (float: n < 8192) */
    s2r = AW_FMA(mm, ar, s2r);
    s2i = AW_FMA(mm, ai, s2i);
    wsum = wsum + w;
  }
  out->s0r = s0r;
  out->s0i = s0i;
  out->s1r = s1r;
  out->s1i = s1i;
  out->s2r = s2r;
  out->s2i = s2i;
  out->wsum = wsum;
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
   * below eps (|x| + half a bin), round-off, without another pass to see it. */
  if (newton && AW_FABS(step) <= AW_NAFF_QUADRATIC * AW_SQRT(eps * (AW_FABS(q->x) + half_bin) * half_bin)) {
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

/* ------------------------------------------------------------------ lanes
 * The kernels analyse AW_LANES trajectories at once (one with AW_LANES = 1):
 * lane j's samples at re[k stride + j] (consecutive trajectories, so a
 * sample of all lanes is one vector load), already multiplied by the window
 * chi_p when they were stored (aw_naff_window_at), so a pass has no window
 * to compute. A pass gives every lane the sums of aw_naff_sums_at with p = 0
 * on its samples, bit for bit (the same operations in the same order; the
 * portable lane sin/cos gives aw_sincos2pi_1's bits); aw_naff_refine_lanes
 * then takes every lane through aw_naff_refine's steps, the lanes that have
 * stopped carried along until all have: each lane's frequency is the one
 * aw_naff_refine gives for it (tests/frequencies: "lanes"). */

/* chi_p at sample k of n (aw_naff_sums_at's window, exact at every sample). */
AW_FN real aw_naff_window_at(int k, int n, int p) {
  real s, c;
  aw_sincos2pi_1(((real)k - AW_R(0.5) * (real)(n - 1)) / (real)(n - 1), &s, &c);
  return aw_naff_window(c, p);
}

typedef struct {
  lreal s0r, s0i, s1r, s1i, s2r, s2i;
} aw_naff_lsums;

/* One pass for every lane at its own sigma; the samples prewindowed. The
 * samples are loaded AW_NAFF_BATCH at a time before they are used: a pass is
 * a chain of dependent rotations, and a GPU thread that waits for each load
 * in turn keeps one load in flight (a pass then runs at the memory's latency,
 * not its bandwidth). The arithmetic is the same in the same order. */
#ifndef AW_NAFF_BATCH
#define AW_NAFF_BATCH 8
#endif
AW_FN void aw_naff_lsums_at(AW_GLOBAL const real* re, AW_GLOBAL const real* im, aw_u64 stride, int n, lreal sigma,
                            aw_naff_lsums* out) {
  const real centre = AW_R(0.5) * (real)(n - 1);
  const lreal a = -sigma;
  lreal dc, ds, ec = AW_LSPLAT(AW_R(1.0)), es = AW_LSPLAT(AW_R(0.0));
  aw_sincos2pi(a, &ds, &dc);
  lreal s0r = AW_LSPLAT(AW_R(0.0)), s0i = s0r, s1r = s0r, s1i = s0r, s2r = s0r, s2i = s0r;
  for (int k0 = 0; k0 < n; k0 += AW_NAFF_BATCH) {
    lreal zr[AW_NAFF_BATCH], zi[AW_NAFF_BATCH];
    for (int b = 0; b < AW_NAFF_BATCH; ++b) {
      const int k = (k0 + b < n) ? k0 + b : n - 1; /* past the end: a sample loaded again, not used */
      zr[b] = AW_LOAD_LANES(re + (aw_u64)k * stride);
      zi[b] = AW_LOAD_LANES(im + (aw_u64)k * stride);
    }
    for (int b = 0; b < AW_NAFF_BATCH && k0 + b < n; ++b) {
      const int k = k0 + b;
      const real m = (real)k - centre;
      if (k % AW_NAFF_ANCHOR == 0) {
        aw_sincos2pi(a * m, &es, &ec);
      } else {
        const lreal c = AW_FMA(ec, dc, -(es * ds));
        const lreal sn = AW_FMA(es, dc, ec * ds);
        ec = c;
        es = sn;
      }
      const lreal ar = AW_FMA(zr[b], ec, -(zi[b] * es));
      const lreal ai = AW_FMA(zr[b], es, zi[b] * ec);
      s0r = s0r + ar;
      s0i = s0i + ai;
      s1r = AW_FMA(AW_LSPLAT(m), ar, s1r);
      s1i = AW_FMA(AW_LSPLAT(m), ai, s1i);
      const real mm = m * m;
      s2r = AW_FMA(AW_LSPLAT(mm), ar, s2r);
      s2i = AW_FMA(AW_LSPLAT(mm), ai, s2i);
    }
  }
  out->s0r = s0r;
  out->s0i = s0i;
  out->s1r = s1r;
  out->s1i = s1i;
  out->s2r = s2r;
  out->s2i = s2i;
}

/* aw_naff_refine for every lane whose active[j] is set, from sigma0 (lanes):
 * freq[j] its frequency (cycles per sample), ok[j] as aw_naff_refine's ok
 * (freq[j] = sigma0 where 0). Lanes not active are left as they are. */
AW_FN void aw_naff_refine_lanes(AW_GLOBAL const real* re, AW_GLOBAL const real* im, aw_u64 stride, int n,
                                lreal sigma0, const int* active, real* freq, int* ok) {
  real start[AW_LANES];
  aw_naff_search q[AW_LANES];
  int running[AW_LANES];
  AW_STORE_LANES(sigma0, start);
  int left = 0;
  for (int j = 0; j < AW_LANES; ++j) {
    aw_naff_search_begin(&q[j], start[j]);
    running[j] = active[j];
    left += running[j];
  }
  for (int it = 0; it < AW_NAFF_MAX_ITER && left > 0; ++it) {
    real x[AW_LANES];
    for (int j = 0; j < AW_LANES; ++j) x[j] = q[j].x;
    aw_naff_lsums ls;
    aw_naff_lsums_at(re, im, stride, n, AW_LOAD_LANES(x), &ls);
    real s0r[AW_LANES], s0i[AW_LANES], s1r[AW_LANES], s1i[AW_LANES], s2r[AW_LANES], s2i[AW_LANES];
    AW_STORE_LANES(ls.s0r, s0r);
    AW_STORE_LANES(ls.s0i, s0i);
    AW_STORE_LANES(ls.s1r, s1r);
    AW_STORE_LANES(ls.s1i, s1i);
    AW_STORE_LANES(ls.s2r, s2r);
    AW_STORE_LANES(ls.s2i, s2i);
    left = 0;
    for (int j = 0; j < AW_LANES; ++j) {
      if (!running[j]) continue;
      const aw_naff_sums s = {s0r[j], s0i[j], s1r[j], s1i[j], s2r[j], s2i[j], AW_R(1.0)};
      running[j] = aw_naff_search_step(&q[j], &s, n);
      left += running[j];
    }
  }
  for (int j = 0; j < AW_LANES; ++j) {
    if (!active[j]) continue;
    ok[j] = q[j].done;
    freq[j] = q[j].done ? q[j].x : start[j];
  }
}

#endif /* AW_NAFF_H */
