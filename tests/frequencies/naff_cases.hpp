// arnoldweb tests: quasi-periodic test signals for the frequency analysis
// (lib/device/aw_naff.h) and its runs in double and in float, shared by the
// host and OpenCL tests (tests/frequencies/).
#pragma once

#include <complex>
#include <vector>

namespace naff_test {

// One term a exp(2 pi i f t): f in cycles per unit of time.
struct Term {
  double freq;
  std::complex<double> amp;
};

// The samples of `count` signals at t_k = k dt, k < n, coalesced as a kernel
// keeps a chunk's (naff_driver.h): sample k of signal j at [k count + j].
// Computed in long double from the terms.
struct Chunk {
  int n = 0, count = 0;
  double dt = 0;
  std::vector<double> re, im;
};
Chunk make_chunk(const std::vector<std::vector<Term>>& signals, int n, double dt);

// What naff_driver.h writes per signal and term: frequency (cycles per
// sample), amplitude (re, im), passes, ok; `terms` per signal.
std::vector<double> analyse_double(Chunk chunk, int p, int terms, int log2m);
// The same in float, from the samples rounded to float.
std::vector<float> analyse_float(const Chunk& chunk, int p, int terms, int log2m);

// The smallest log2 m with 2^m >= 2 n (the FFT zero-padded twice).
int fft_log2(int n);

}  // namespace naff_test
