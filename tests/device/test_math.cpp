// The portable elementary functions against long-double references, and the
// HEALPix pixel index against Debian's HEALPix C++ library.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core_double.hpp"
#include "support.hpp"
#include "ulp.hpp"

#ifdef ARNOLDWEB_HAVE_HEALPIX_CXX
#include <healpix_cxx/healpix_base.h>
#endif

TEST_SUITE("math") {
  TEST_CASE("sincos2pi (double) is within 1.5 ulp of sin/cos(2 pi u) over the range the stepper uses") {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> wide(-2.0, 2.0);  // wrapped angle plus one step's drift
    double worst_s = 0, worst_c = 0;
    for (int i = 0; i < 2000000; ++i) {
      const double u = (i < 1000) ? (i - 500) / 250.0 : wide(rng);  // includes quadrant edges
      double s, c;
      core_d::aw_sincos2pi(u, &s, &c);
      long double rs, rc;
      awtest::sincos2pi_reference(u, &rs, &rc);
      worst_s = std::max(worst_s, awtest::ulp_error(s, rs));
      worst_c = std::max(worst_c, awtest::ulp_error(c, rc));
    }
    std::printf("sincos2pi double: max error sin %.3f ulp, cos %.3f ulp\n", worst_s, worst_c);
    CHECK(worst_s <= 1.5);
    CHECK(worst_c <= 1.5);
  }

  TEST_CASE("sincos2pi is exact at multiples of a quarter turn") {
    for (int k = -8; k <= 8; ++k) {
      double s, c;
      core_d::aw_sincos2pi(k * 0.25, &s, &c);
      const int q = ((k % 4) + 4) % 4;
      CHECK(s == (q == 1 ? 1.0 : q == 3 ? -1.0 : 0.0));
      CHECK(c == (q == 0 ? 1.0 : q == 2 ? -1.0 : 0.0));
    }
  }

  TEST_CASE("atan2 (double) is within 2 ulp of atan2l") {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> n01;
    double worst = 0;
    for (int i = 0; i < 1000000; ++i) {
      const double y = n01(rng), x = n01(rng);
      const double a = core_d::aw_atan2(y, x);
      worst = std::max(worst, awtest::ulp_error(a, atan2l(y, x)));
    }
    std::printf("atan2 double: max error %.3f ulp\n", worst);
    CHECK(worst <= 2.0);
    CHECK(core_d::aw_atan2(0.0, 0.0) == 0.0);
    CHECK(core_d::aw_atan2(0.0, -1.0) == doctest::Approx(M_PI).epsilon(1e-16));
    CHECK(core_d::aw_atan2(-1.0, 0.0) == doctest::Approx(-M_PI / 2).epsilon(1e-16));
  }

  TEST_CASE("HEALPix ring pixels cover the sphere evenly") {
    std::mt19937_64 rng(3);
    std::normal_distribution<double> n01;
    for (long nside : {1L, 2L, 8L}) {
      const long npix = 12 * nside * nside;
      std::vector<long> count(static_cast<std::size_t>(npix), 0);
      const long n = 4000 * npix;
      for (long i = 0; i < n; ++i) {
        const long p = core_d::aw_vec2pix_ring(nside, n01(rng), n01(rng), n01(rng));
        REQUIRE(p >= 0);
        REQUIRE(p < npix);
        ++count[static_cast<std::size_t>(p)];
      }
      double chi2 = 0;
      const double expect = static_cast<double>(n) / npix;
      for (long c : count) chi2 += (c - expect) * (c - expect) / expect;
      // chi-square with npix - 1 degrees of freedom: mean npix - 1, sd sqrt(2 (npix - 1))
      CAPTURE(nside);
      CHECK(chi2 < (npix - 1) + 6 * std::sqrt(2.0 * (npix - 1)));
    }
  }
}

// Against Debian's HEALPix C++ library (libhealpix-cxx-dev, a test-only
// dependency found by pkg-config at configure time): a suite of its own (ctest
// math.healpix), skipped with the reason where the build has no library.
TEST_SUITE("math-healpix") {
#ifdef ARNOLDWEB_HAVE_HEALPIX_CXX
  TEST_CASE("HEALPix ring pixel index agrees with Debian's HEALPix C++ library") {
    std::mt19937_64 rng(11);
    std::normal_distribution<double> n01;
    for (int order : {0, 1, 4, 6, 10, 13}) {
      const long nside = 1L << order;
      T_Healpix_Base<int64> base(order, RING);
      long mismatches = 0;
      for (int i = 0; i < 200000; ++i) {
        const double x = n01(rng), y = n01(rng), z = (i % 10 == 0) ? 50 * n01(rng) : n01(rng);  // include near-polar
        const long ours = core_d::aw_vec2pix_ring(nside, x, y, z);
        const long theirs = base.vec2pix(vec3(x, y, z));
        mismatches += (ours != theirs);
      }
      // every pixel centre maps back to its own pixel
      const long npix = 12 * nside * nside;
      const long stride = std::max(1L, npix / 20000);
      for (long p = 0; p < npix; p += stride) {
        const vec3 v = base.pix2vec(p);
        mismatches += (core_d::aw_vec2pix_ring(nside, v.x, v.y, v.z) != p);
      }
      CAPTURE(order);
      CHECK(mismatches == 0);
    }
  }
#else
  TEST_CASE("HEALPix ring pixel index agrees with Debian's HEALPix C++ library") {
    awtest::require(false, "math-healpix",
                    "this build has no libhealpix-cxx (pkg-config healpix_cxx not found when cmake ran): install "
                    "libhealpix-cxx-dev and configure again");
  }
#endif
}
