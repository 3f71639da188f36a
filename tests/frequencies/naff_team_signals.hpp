// Test signals for the team form of the frequency refinement (aw_naff.h,
// "teams"): a leading term and two smaller ones, prewindowed, stored as the
// analysis reads them (re and im of each sample in turn, the groups of
// AW_NAFF_GROUP samples one after another; zero past n up to whole teams),
// and a start a fraction of a bin off the leading frequency.
#pragma once

#include <cmath>
#include <random>
#include <vector>

namespace naff_team_test {

struct Signal {
  std::vector<double> z;  // 2 AW_NAFF_PADDED(n) reals
  double sigma = 0, start = 0;
};

// chi_p at sample k of n, as the sampler multiplies the samples by it
// (aw_naff_window_at): passed in so that the signals are the kernels' bits.
template <class Window>
Signal make_signal(std::mt19937_64& rng, int n, int padded, int p, Window window) {
  std::uniform_real_distribution<double> uni(-0.45, 0.45), amp(0.05, 0.4), phase(0, 6.283185307179586);
  Signal s;
  s.z.assign(2 * static_cast<std::size_t>(padded), 0.0);
  s.sigma = uni(rng);
  const double s2 = uni(rng), s3 = uni(rng), a2 = amp(rng), a3 = amp(rng), f2 = phase(rng), f3 = phase(rng);
  s.start = s.sigma + (uni(rng) / 0.45) * 0.4 / n;
  for (int k = 0; k < n; ++k) {
    const double w = window(k, n, p);
    const double t = k, a = 6.283185307179586 * s.sigma * t;
    const double b = 6.283185307179586 * s2 * t + f2, c = 6.283185307179586 * s3 * t + f3;
    s.z[2 * static_cast<std::size_t>(k)] = w * (std::cos(a) + a2 * std::cos(b) + a3 * std::cos(c));
    s.z[2 * static_cast<std::size_t>(k) + 1] = w * (std::sin(a) + a2 * std::sin(b) + a3 * std::sin(c));
  }
  return s;
}

// An angle that librates about a centre moving at `rate` (cycles per sample):
// u_k = rate k + a sin(2 pi f k + phase) + b sin(4 pi f k + phase2) turns, its
// signal exp(2 pi i u_k) (the raw samples, `raw`, re and im in turn) and the
// same prewindowed as the analysis reads it (`z`); `start` the mean rate over
// the window, as the sampler gives it, less its whole cycles. The terms lie at
// rate + k f with amplitudes near J_k(2 pi a): for 2 pi a > 1.44 the largest
// is not the one at the centre, nearest the mean rate.
struct Libration {
  double rate, a, f, phase, b, phase2;
};
template <class Window>
Signal make_libration(const Libration& l, int n, int padded, int p, Window window, std::vector<double>* raw) {
  Signal s;
  s.z.assign(2 * static_cast<std::size_t>(padded), 0.0);
  raw->assign(2 * static_cast<std::size_t>(n), 0.0);
  const long double two_pi = 6.283185307179586476925286766559005768L;
  auto u = [&](int k) {
    return l.rate * k + l.a * std::sin(static_cast<double>(two_pi * l.f * k) + l.phase) +
           l.b * std::sin(static_cast<double>(2 * two_pi * l.f * k) + l.phase2);
  };
  for (int k = 0; k < n; ++k) {
    const double turns = u(k) - std::floor(u(k));
    const double c = static_cast<double>(std::cos(two_pi * turns)), sn = static_cast<double>(std::sin(two_pi * turns));
    (*raw)[2 * static_cast<std::size_t>(k)] = c;
    (*raw)[2 * static_cast<std::size_t>(k) + 1] = sn;
    const double w = window(k, n, p);
    s.z[2 * static_cast<std::size_t>(k)] = w * c;
    s.z[2 * static_cast<std::size_t>(k) + 1] = w * sn;
  }
  const double mean_rate = (u(n - 1) - u(0)) / (n - 1);
  s.start = mean_rate - std::nearbyint(mean_rate);
  s.sigma = NAN;
  return s;
}

// The team refinement with one lane (test_naff_team_one_lane.cpp): the
// kernels' GPU form of a member, here every member in turn; and the search
// for the largest term (aw_naff_largest_team) in the same form.
void refine_one_lane(const double* z, int n, double sigma0, double* freq, int* ok);
void largest_one_lane(const double* z, int n, int p, double sigma0, double* freq, int* ok);

}  // namespace naff_team_test
