// compare_maps (analysis.hpp): the two-sample chi-square test of two maps.
// Under the null (both maps sample one distribution) its p-values are
// uniform; against a real difference they vanish; bins too sparse for the
// asymptotic distribution are pooled into one.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

#include "arnoldweb/analysis.hpp"

using namespace arnoldweb;

namespace {

// `draws` samples of the distribution `p` (weights), as counts per bin.
std::vector<std::uint64_t> multinomial(const std::vector<double>& p, std::uint64_t draws, std::mt19937_64& rng) {
  std::discrete_distribution<std::size_t> pick(p.begin(), p.end());
  std::vector<std::uint64_t> counts(p.size(), 0);
  for (std::uint64_t k = 0; k < draws; ++k) ++counts[pick(rng)];
  return counts;
}

// 3000 bins, weights from 0.05 to 1.95 (a smooth profile, like a map's),
// so that the sparsest bins fall below min_count now and then.
std::vector<double> profile() {
  std::vector<double> p(3000);
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = 1 + 0.95 * std::sin(0.0021 * static_cast<double>(i * i % 7919));
  return p;
}

}  // namespace

TEST_SUITE("compare") {
  TEST_CASE("the statistic is the two-sample chi-square: hand-computed cases") {
    // proportional maps (totals 60 and 120): chi2 = 0, p = 1
    MapComparison c = compare_maps({10, 20, 30}, {20, 40, 60});
    CHECK(c.chi2 == doctest::Approx(0).epsilon(1e-12));
    CHECK(c.dof == 2);
    CHECK(c.p_value == doctest::Approx(1));
    CHECK(c.total_a == 60);
    CHECK(c.total_b == 120);
    // A = B = 40: chi2 = 20^2/40 + 20^2/40 = 20 on 1 dof, p = erfc(sqrt(10))
    c = compare_maps({30, 10}, {10, 30});
    CHECK(c.chi2 == doctest::Approx(20));
    CHECK(c.dof == 1);
    CHECK(c.p_value == doctest::Approx(std::erfc(std::sqrt(10.0))).epsilon(1e-10));
    // unequal totals A = 40, B = 160: sqrt(B/A) = 2, sqrt(A/B) = 1/2
    // bin 0: (2*30 - 0.5*40)^2 / 70 = 1600/70, bin 1: (2*10 - 0.5*120)^2 / 130 = 1600/130
    c = compare_maps({30, 10}, {40, 120});
    CHECK(c.chi2 == doctest::Approx(1600.0 / 70 + 1600.0 / 130));
    // a single bin used: nothing to compare
    c = compare_maps({0, 7, 0}, {0, 9, 0});
    CHECK(c.used_bins == 1);
    CHECK(c.dof == 0);
    CHECK(c.p_value == 1);
  }

  TEST_CASE("bad input throws: sizes differ, no bins, no counts, a bad min_count") {
    CHECK_THROWS_WITH_AS(compare_maps({1, 2, 3}, {1, 2}), doctest::Contains("different sizes (3 and 2 bins)"),
                         std::invalid_argument);
    CHECK_THROWS_WITH_AS(compare_maps({}, {}), doctest::Contains("empty"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(compare_maps({0, 0}, {1, 2}), doctest::Contains("map A has no counts"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(compare_maps({1, 2}, {0, 0}), doctest::Contains("map B has no counts"), std::invalid_argument);
    CHECK_THROWS_AS(compare_maps({1, 2}, {1, 2}, -1), std::invalid_argument);
    CHECK_THROWS_AS(compare_maps({1, 2}, {1, 2}, NAN), std::invalid_argument);
  }

  TEST_CASE("two samples of one distribution: the p-values are uniform, not tiny") {
    const std::vector<double> p = profile();
    int tiny = 0;
    double sum_p = 0, sum_r = 0;
    for (int pair = 0; pair < 20; ++pair) {
      std::mt19937_64 rng_a(1000 + pair), rng_b(5000 + pair);
      const MapComparison c = compare_maps(multinomial(p, 200000, rng_a), multinomial(p, 300000, rng_b));
      CHECK(c.total_a == 200000);
      CHECK(c.total_b == 300000);
      CHECK(c.dof == static_cast<double>(c.used_bins) - 1);
      tiny += c.p_value < 0.01;
      sum_p += c.p_value;
      sum_r += c.chi2_per_dof();
    }
    std::printf("null, 20 pairs of 2e5 and 3e5 draws in 3000 bins: mean p %.3f, mean chi2/dof %.4f, %d below 0.01\n",
                sum_p / 20, sum_r / 20, tiny);
    CHECK(tiny <= 2);
    CHECK(sum_p / 20 > 0.3);
    CHECK(sum_p / 20 < 0.7);
    CHECK(std::abs(sum_r / 20 - 1) < 0.03);  // sd of the mean: sqrt(2/3000/20) = 0.006
  }

  TEST_CASE("two samples of distributions that differ in a band of bins: p vanishes") {
    // B's weights 20% higher in bins 1000..1899 (30% of the bins). The
    // expected excess of chi2 over its dof is N_eff * sum_i p_i d_i^2
    // ~ 1.2e5 * 0.2^2 * 0.3 * 0.7 ~ 1000 (N_eff = A B / (A + B), d_i the
    // relative difference after normalising) against a spread of sqrt(2 * 3000)
    // ~ 77: about 13 sigma. (A 3% band would give ~ 23, below the noise: at
    // these sizes the test sees differences of ~ 10% in a large region, or
    // larger ones in a small region.)
    const std::vector<double> pa = profile();
    std::vector<double> pb = pa;
    for (std::size_t i = 1000; i < 1900; ++i) pb[i] *= 1.2;
    std::mt19937_64 rng_a(11), rng_b(12);
    const MapComparison c = compare_maps(multinomial(pa, 200000, rng_a), multinomial(pb, 300000, rng_b));
    std::printf("20%% band: chi2 %.1f, dof %.0f, chi2/dof %.4f, p %.3g\n", c.chi2, c.dof, c.chi2_per_dof(),
                c.p_value);
    CHECK(c.p_value < 1e-6);
    // the same sizes, the same distribution (seeds 11 and 13): consistent
    std::mt19937_64 rng_c(11), rng_d(13);
    const MapComparison n = compare_maps(multinomial(pa, 200000, rng_c), multinomial(pa, 300000, rng_d));
    CHECK(n.p_value > 1e-3);
  }

  TEST_CASE("sparse maps: bins below min_count are pooled into one, empty bins left out") {
    // 100 well-filled bins (40 and 60 counts), 300 sparse ones (0 to 2 each: below 5 together), the rest empty
    std::vector<std::uint64_t> a(1000, 0), b(1000, 0);
    std::mt19937_64 rng(7);
    std::size_t sparse = 0, empty = 0;
    for (std::size_t i = 0; i < 1000; ++i) {
      if (i < 100) {
        a[i] = 40 + rng() % 5;
        b[i] = 60 + rng() % 5;
      } else if (i < 400) {
        a[i] = rng() % 3;
        b[i] = rng() % 3;
      }
      if (i >= 100) (a[i] + b[i] == 0 ? empty : sparse) += 1;
    }
    const MapComparison c = compare_maps(a, b);
    CHECK(c.bins == 1000);
    CHECK(c.pooled_bins == sparse);
    CHECK(c.empty_bins == empty);
    CHECK(c.used_bins == 100 + 1);
    CHECK(c.dof == 100);
    CHECK(std::isfinite(c.chi2));
    CHECK(c.p_value >= 0);
    CHECK(c.p_value <= 1);
    std::printf("sparse: %zu used, %zu pooled, %zu empty, chi2/dof %.3f, p %.3g\n", c.used_bins, c.pooled_bins,
                c.empty_bins, c.chi2_per_dof(), c.p_value);
    // min_count = 0: nothing pooled, every non-empty bin a term of its own
    const MapComparison raw = compare_maps(a, b, 0);
    CHECK(raw.pooled_bins == 0);
    CHECK(raw.used_bins == 100 + sparse);
    CHECK(raw.dof == static_cast<double>(100 + sparse) - 1);
  }
}
