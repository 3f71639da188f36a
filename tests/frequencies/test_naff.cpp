// The frequency analysis (lib/device/aw_naff.h) on the host, in double: a
// pure tone to round-off, the terms of a quasi-periodic signal with their
// amplitudes, the fall of the error with the window's length (1/T^4 for the
// Hanning window, 1/T^6 for chi_2: Laskar's 1/T^(2p+2)), the coarse search
// without a buffer, and a broken signal reported as such.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "aw_cpp_std.h"
#include "naff_cases.hpp"

namespace naff_d {
#include "aw_naff.h"
#include "naff_driver.h"
}  // namespace naff_d

namespace naff_test {

Chunk make_chunk(const std::vector<std::vector<Term>>& signals, int n, double dt) {
  Chunk c;
  c.n = n;
  c.count = static_cast<int>(signals.size());
  c.dt = dt;
  c.re.assign(static_cast<std::size_t>(n) * c.count, 0.0);
  c.im.assign(c.re.size(), 0.0);
  for (int j = 0; j < c.count; ++j)
    for (int k = 0; k < n; ++k) {
      long double zr = 0, zi = 0;
      for (const Term& t : signals[j]) {
        // the phase in turns, reduced exactly before the multiplication by 2 pi
        const long double turns = fmodl(static_cast<long double>(t.freq) * dt * k, 1.0L);
        const long double a = 6.283185307179586476925286766559005768L * turns;
        const long double c_ = cosl(a), s_ = sinl(a);
        zr += t.amp.real() * c_ - t.amp.imag() * s_;
        zi += t.amp.real() * s_ + t.amp.imag() * c_;
      }
      c.re[static_cast<std::size_t>(k) * c.count + j] = static_cast<double>(zr);
      c.im[static_cast<std::size_t>(k) * c.count + j] = static_cast<double>(zi);
    }
  return c;
}

std::vector<double> analyse_double(Chunk c, int p, int terms, int log2m) {
  std::vector<double> wre((std::size_t{1} << log2m) * c.count), wim(wre.size());
  std::vector<double> out(static_cast<std::size_t>(c.count) * terms * 5);
  for (int j = 0; j < c.count; ++j)
    naff_d::naff_test_analyse(c.re.data(), c.im.data(), wre.data(), wim.data(), out.data(), j, c.count, c.n, p, terms,
                              log2m);
  return out;
}

int fft_log2(int n) {
  int b = 0;
  while ((1 << b) < 2 * n) ++b;
  return b;
}

}  // namespace naff_test

using naff_test::Term;

namespace {

// A quasi-periodic signal with well separated frequencies (cycles per T): a
// leading term and two smaller ones, the second at a phase `phase`.
std::vector<Term> three_terms(double phase = 0.3) {
  return {{0.3183098861837907, {1.0, 0.0}},
          {0.1234567890123457, std::polar(0.4, phase)},
          {-0.2718281828459045, std::polar(0.2, 1.1)}};
}

// The envelope of the leading frequency's error (cycles per T) over a window
// of about n samples dt apart, for a leading term and one of 0.4 at 0.195
// cycles per T from it: the error oscillates like cos(pi dnu n dt) (the
// derivative of the window's transform at dnu, Laskar 2003), so the largest
// of 22 consecutive lengths n' = n .. n + 21 (more than one period, 1 / (dnu
// dt) = 20.5 samples) follows its envelope.
double leading_error(int n, double dt, int p) {
  const std::vector<Term> terms = {{0.3183098861837907, {1.0, 0.0}}, {0.1234567890123457, std::polar(0.4, 0.3)}};
  double worst = 0;
  for (int extra = 0; extra < 22; ++extra) {
    const naff_test::Chunk c = naff_test::make_chunk({terms}, n + extra, dt);
    const std::vector<double> out = naff_test::analyse_double(c, p, 1, naff_test::fft_log2(n + extra));
    worst = std::max(worst, std::fabs(out[0] / dt - terms[0].freq));
  }
  return worst;
}

// Least-squares slope of log e against log n.
double loglog_slope(const std::vector<int>& ns, const std::vector<double>& es) {
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < ns.size(); ++i) {
    mx += std::log(ns[i]);
    my += std::log(es[i]);
  }
  mx /= ns.size();
  my /= ns.size();
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < ns.size(); ++i) {
    sxy += (std::log(ns[i]) - mx) * (std::log(es[i]) - my);
    sxx += (std::log(ns[i]) - mx) * (std::log(ns[i]) - mx);
  }
  return sxy / sxx;
}

}  // namespace

TEST_SUITE("frequencies") {
  TEST_CASE("a pure tone's frequency and amplitude to round-off, for any window order and length") {
    for (int p : {0, 1, 2, 3})
      for (int n : {16, 100, 1000, 4096}) {
        CAPTURE(p);
        CAPTURE(n);
        const Term tone{0.3183098861837907, std::polar(0.7, -0.4)};
        const naff_test::Chunk c = naff_test::make_chunk({{tone}}, n, 0.25);
        const std::vector<double> out = naff_test::analyse_double(c, p, 1, naff_test::fft_log2(n));
        const double sigma = tone.freq * 0.25;
        // the amplitude's phase is at the window's centre, t = (n - 1) dt / 2
        const std::complex<double> amp = tone.amp * std::polar(1.0, 2 * M_PI * sigma * 0.5 * (n - 1));
        MESSAGE("p " << p << " n " << n << ": frequency error " << (out[0] - sigma) << " cycles/sample, "
                     << out[3] << " passes");
        CHECK(out[4] == 1);
        CHECK(std::fabs(out[0] - sigma) < 4e-16 / std::sqrt(n));
        CHECK(std::abs(std::complex<double>(out[1], out[2]) - amp) < 1e-13);
      }
  }

  TEST_CASE("the terms of a quasi-periodic signal, largest first, and their amplitudes") {
    const int n = 4096;
    const double dt = 0.25;  // T = 1024
    const std::vector<Term> terms = three_terms();
    const naff_test::Chunk c = naff_test::make_chunk({terms}, n, dt);
    const std::vector<double> out = naff_test::analyse_double(c, 1, 3, naff_test::fft_log2(n));
    for (int t = 0; t < 3; ++t) {
      CAPTURE(t);
      const double f = out[t * 5] / dt;
      const double sigma = terms[t].freq * dt;
      const std::complex<double> amp = terms[t].amp * std::polar(1.0, 2 * M_PI * sigma * 0.5 * (n - 1));
      const double amp_error = std::abs(std::complex<double>(out[t * 5 + 1], out[t * 5 + 2]) - amp);
      MESSAGE("term " << t << ": frequency " << f << " (error " << f - terms[t].freq << " per T), amplitude error "
                      << amp_error << ", " << out[t * 5 + 3] << " passes");
      CHECK(out[t * 5 + 4] == 1);
      CHECK(std::fabs(f - terms[t].freq) < 1e-11);
      CHECK(amp_error < 1e-7);
    }
  }

  TEST_CASE("the error falls like 1/T^(2p+2): slope -2 without a window, -4 for the Hanning window, -6 for chi_2") {
    const std::vector<int> ns = {256, 362, 512, 724, 1024, 1448};
    for (int p : {0, 1, 2}) {
      CAPTURE(p);
      std::vector<double> es;
      for (int n : ns) es.push_back(leading_error(n, 0.25, p));
      const double slope = loglog_slope(ns, es);
      MESSAGE("p = " << p << ": errors " << es.front() << " ... " << es.back() << " (n " << ns.front() << " ... "
                     << ns.back() << "), slope " << slope);
      CHECK(std::fabs(slope + (2.0 * p + 2)) < 0.05 * (2.0 * p + 2));
    }
  }

  TEST_CASE("a coarse scan without a buffer finds the maximum the FFT finds") {
    const int n = 1000;
    const naff_test::Chunk c = naff_test::make_chunk({three_terms()}, n, 0.25);
    const double guess = three_terms()[0].freq * 0.25 + 0.7 / n;  // e.g. a mean rate, within a bin
    const double coarse = naff_d::aw_naff_scan(c.re.data(), c.im.data(), 1, n, 1, guess - 2.0 / n, guess + 2.0 / n, 9);
    naff_d::aw_naff_result a, b;
    naff_d::aw_naff_refine(c.re.data(), c.im.data(), 1, n, 1, coarse, &a);
    const std::vector<double> fft = naff_test::analyse_double(c, 1, 1, naff_test::fft_log2(n));
    naff_d::aw_naff_refine(c.re.data(), c.im.data(), 1, n, 1, guess, &b);
    MESSAGE("scan " << coarse << " -> " << a.freq << "; FFT path " << fft[0] << "; from the guess " << b.freq);
    CHECK(a.ok == 1);
    CHECK(std::fabs(a.freq - fft[0]) < 1e-15);
    CHECK(std::fabs(b.freq - fft[0]) < 1e-15);
  }

  TEST_CASE("a signal with a NaN is reported as not refined, and the other signals of the chunk are unaffected") {
    const int n = 256;
    naff_test::Chunk c = naff_test::make_chunk({three_terms(), three_terms()}, n, 0.25);
    c.re[100 * 2 + 1] = std::numeric_limits<double>::quiet_NaN();
    const std::vector<double> out = naff_test::analyse_double(c, 1, 1, naff_test::fft_log2(n));
    CHECK(out[4] == 1);
    CHECK(out[5 + 4] == 0);
    const naff_test::Chunk clean = naff_test::make_chunk({three_terms()}, n, 0.25);
    CHECK(out[0] == naff_test::analyse_double(clean, 1, 1, naff_test::fft_log2(n))[0]);
  }
}
