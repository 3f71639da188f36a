// The portable exp (lib/device/aw_exp.h, double) against expl.
#include <doctest/doctest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <random>

#include "aw_cpp_std.h"
#include "ulp.hpp"

namespace exp_d {
#include "aw_exp.h"
}  // namespace exp_d

TEST_SUITE("math") {
  TEST_CASE("exp (double) is within 1 ulp of expl on [-708, 709]") {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> wide(-708.0, 709.0), narrow(-2.0, 2.0);
    double worst = 0;
    for (int i = 0; i < 2000000; ++i) {
      const double x = (i % 2) ? wide(rng) : narrow(rng);
      worst = std::max(worst, awtest::ulp_error(exp_d::aw_exp(x), expl(static_cast<long double>(x))));
    }
    std::printf("exp double: max error %.3f ulp\n", worst);
    CHECK(worst <= 1.0);
  }

  TEST_CASE("exp (double): exact points, saturation and NaN") {
    CHECK(exp_d::aw_exp(0.0) == 1.0);
    CHECK(exp_d::aw_exp(-0.0) == 1.0);
    CHECK(exp_d::aw_exp(1.0) == doctest::Approx(M_E).epsilon(1e-16));
    CHECK(exp_d::aw_exp(1000.0) == exp_d::aw_exp(709.0));  // clamped: finite
    CHECK(std::isfinite(exp_d::aw_exp(709.0)));
    CHECK(exp_d::aw_exp(-1000.0) == exp_d::aw_exp(-708.0));
    CHECK(exp_d::aw_exp(-708.0) >= DBL_MIN);  // never subnormal
    CHECK(std::isnan(exp_d::aw_exp(std::nan(""))));
  }
}
