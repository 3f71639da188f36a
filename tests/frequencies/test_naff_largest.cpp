// NAFF's frequency is that of the largest term (aw_naff.h,
// aw_naff_largest_team), checked against an independent NAFF written here:
// long double, the window and the transform summed directly, |phi| on a grid
// of an eighth of a bin over the whole spectrum, its largest local maxima
// refined by bisection on the sign of the slope. Librating angles (their
// terms at the centre's rate + k f, the largest at k != 0) are found where the
// search from the mean rate alone (aw_naff_refine_team, what the analysis did
// before) stops at the term nearest the mean rate; rotating angles, whose
// leading term holds nearly all of the power, keep that search's bits.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <cstring>
#include <random>
#include <vector>

#include "aw_cpp_std.h"
#include "naff_team_signals.hpp"

namespace naff_largest {
#include "aw_naff.h"
}  // namespace naff_largest

namespace {

using cld = std::complex<long double>;
const long double kTwoPi = 6.283185307179586476925286766559005768L;

// The independent NAFF: raw samples (re, im in turn), Laskar's window chi_p in
// long double, phi(sigma) and the slope's sign by direct sums.
struct ReferenceNaff {
  int n, p;
  std::vector<cld> z;           // chi_p(k) z_k
  std::vector<long double> m;   // k - (n - 1)/2

  ReferenceNaff(const std::vector<double>& raw, int n_, int p_) : n(n_), p(p_), z(n_), m(n_) {
    for (int k = 0; k < n; ++k) {
      m[k] = k - 0.5L * (n - 1);
      const long double w = std::pow(1 + std::cos(kTwoPi * m[k] / (n - 1)), static_cast<long double>(p));
      z[k] = w * cld(raw[2 * static_cast<std::size_t>(k)], raw[2 * static_cast<std::size_t>(k) + 1]);
    }
  }
  // S_0 and S_1 at sigma (cycles per sample)
  void sums(long double sigma, cld* s0, cld* s1) const {
    *s0 = *s1 = 0;
    for (int k = 0; k < n; ++k) {
      const cld e = std::polar(1.0L, -kTwoPi * sigma * m[k]);
      *s0 += z[k] * e;
      *s1 += m[k] * z[k] * e;
    }
  }
  long double power(long double sigma) const {
    cld s0, s1;
    sums(sigma, &s0, &s1);
    return std::norm(s0);
  }
  // d|S_0|^2 / dsigma = 4 pi Im(conj(S_0) S_1): its sign
  bool rising(long double sigma) const {
    cld s0, s1;
    sums(sigma, &s0, &s1);
    return std::imag(std::conj(s0) * s1) > 0;
  }
  // The frequency of the largest |phi| over [-1/2, 1/2): the grid of 8 n
  // points (one rotation per point, a product per sample), its 4 largest
  // local maxima bisected to the top of their peak, the highest of them.
  long double largest() const {
    const int points = 8 * n;
    std::vector<long double> pw(points);
    for (int j = 0; j < points; ++j) {
      const long double sigma = -0.5L + static_cast<long double>(j) / points;
      const cld step = std::polar(1.0L, -kTwoPi * sigma);
      cld e = std::polar(1.0L, -kTwoPi * sigma * m[0]), s0 = 0;
      for (int k = 0; k < n; ++k, e *= step) s0 += z[k] * e;
      pw[j] = std::norm(s0);
    }
    std::vector<int> peaks;
    for (int j = 0; j < points; ++j)
      if (pw[j] >= pw[(j + points - 1) % points] && pw[j] >= pw[(j + 1) % points]) peaks.push_back(j);
    std::sort(peaks.begin(), peaks.end(), [&](int a, int b) { return pw[a] > pw[b]; });
    if (peaks.size() > 4) peaks.resize(4);
    long double best = 0, best_power = -1;
    for (int j : peaks) {
      long double lo = -0.5L + (j - 1.0L) / points, hi = -0.5L + (j + 1.0L) / points;
      for (int it = 0; it < 64; ++it) {
        const long double mid = 0.5L * (lo + hi);
        (rising(mid) ? lo : hi) = mid;
      }
      const long double sigma = 0.5L * (lo + hi), power_there = power(sigma);
      if (power_there > best_power) best = sigma, best_power = power_there;
    }
    return best;
  }
};

// The distance of two frequencies in cycles per sample, modulo whole cycles.
double cyclic_distance(long double a, long double b) {
  const long double d = a - b;
  return static_cast<double>(std::fabs(d - std::nearbyint(d)));
}

}  // namespace

TEST_SUITE("frequencies") {
  TEST_CASE("the largest term of a librating angle: an independent NAFF's, where the search from the mean rate "
            "stops short") {
    using namespace naff_largest;
    const auto window = [](int k, int nn, int pp) { return aw_naff_window_at(k, nn, pp); };
    // 2 pi a = 1.8, 3.0, 4.5 radians: the largest terms near k = 1, 2, 3 (J_k(2 pi a)); the
    // libration 3.3 to 9.1 periods per window; its centre at rest or moving; a second harmonic
    const naff_team_test::Libration cases[] = {
        {0.0, 1.8 / 6.283185307179586, 4.3, 0.4, 0.02, 1.0},   {0.0, 3.0 / 6.283185307179586, 6.1, 2.1, 0.03, 0.2},
        {0.0, 4.5 / 6.283185307179586, 9.1, 5.0, 0.01, 2.9},   {0.013, 1.8 / 6.283185307179586, 5.2, 1.3, 0.04, 0.7},
        {-0.021, 3.0 / 6.283185307179586, 3.3, 0.9, 0.02, 4.0}, {0.004, 4.5 / 6.283185307179586, 7.7, 3.3, 0.05, 5.5}};
    int stops_short = 0, count = 0;
    for (int n : {256, 512, 1000})
      for (int p : {1, 2})
        for (const naff_team_test::Libration& c : cases) {
          naff_team_test::Libration l = c;
          l.f = c.f / n;  // periods per window -> cycles per sample
          CAPTURE(n);
          CAPTURE(p);
          CAPTURE(l.rate);
          CAPTURE(l.a * 6.283185307179586);
          std::vector<double> raw;
          const naff_team_test::Signal s = naff_team_test::make_libration(l, n, AW_NAFF_PADDED(n), p, window, &raw);
          const ReferenceNaff ref(raw, n, p);
          const long double want = ref.largest();
          const aw_naff_team team = {0, nullptr};
          double f = -7, f_mean = -8, power;
          int ok = -7, ok_mean = -8;
          aw_naff_largest_team(s.z.data(), 2 * AW_NAFF_GROUP, n, p, s.start, team, &f, &ok);
          aw_naff_refine_team(s.z.data(), 2 * AW_NAFF_GROUP, n, s.start, team, &f_mean, &power, &ok_mean);
          const double k = static_cast<double>((want - l.rate) / l.f);  // which term: rate + k f
          CAPTURE(k);
          CHECK(ok == 1);
          CHECK(cyclic_distance(f, want) < 1e-12);
          // the search from the mean rate alone found another term: more than a bin away
          stops_short += cyclic_distance(f_mean, want) > 1.0 / n ? 1 : 0;
          ++count;
        }
    MESSAGE("the search from the mean rate alone stopped at another term in " << stops_short << " of " << count);
    CHECK(stops_short == count);
  }

  TEST_CASE("a rotating angle: the largest term is the one at its mean rate, with that search's bits") {
    using namespace naff_largest;
    const auto window = [](int k, int nn, int pp) { return aw_naff_window_at(k, nn, pp); };
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> uni(0, 1);
    for (int n : {100, 512})
      for (int p : {0, 1, 2})
        for (int trial = 0; trial < 4; ++trial) {
          CAPTURE(n);
          CAPTURE(p);
          CAPTURE(trial);
          // a rotation at 0.05 to 0.45 cycles per sample, modulated by 2 pi a < 0.4 radians
          const naff_team_test::Libration l = {0.05 + 0.4 * uni(rng), 0.4 * uni(rng) / 6.283185307179586,
                                               (2 + 20 * uni(rng)) / n, 6.283 * uni(rng), 0.01 * uni(rng),
                                               6.283 * uni(rng)};
          std::vector<double> raw;
          const naff_team_test::Signal s = naff_team_test::make_libration(l, n, AW_NAFF_PADDED(n), p, window, &raw);
          const aw_naff_team team = {0, nullptr};
          double f = -7, f_mean = -8, power;
          int ok = -7, ok_mean = -8;
          aw_naff_largest_team(s.z.data(), 2 * AW_NAFF_GROUP, n, p, s.start, team, &f, &ok);
          aw_naff_refine_team(s.z.data(), 2 * AW_NAFF_GROUP, n, s.start, team, &f_mean, &power, &ok_mean);
          CHECK(ok == 1);
          CHECK(std::memcmp(&f, &f_mean, sizeof f) == 0);
          CHECK(power >= AW_NAFF_SURE * aw_naff_window_sum(n, p) * aw_naff_window_sum(n, p));
          CHECK(cyclic_distance(f, ReferenceNaff(raw, n, p).largest()) < 1e-12);
        }
  }

  TEST_CASE("the window's sum: the closed form against the weights summed") {
    using namespace naff_largest;
    for (int p = 0; p <= 4; ++p)
      for (int n : {16, 17, 100, 4096}) {
        double sum = 0;
        for (int k = 0; k < n; ++k) sum += aw_naff_window_at(k, n, p);
        CAPTURE(p);
        CAPTURE(n);
        CHECK(std::fabs(aw_naff_window_sum(n, p) - sum) < 1e-12 * sum);
      }
  }
}
