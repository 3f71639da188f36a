// The portable exp (lib/device/aw_exp.h, float) against expl.
#include <doctest/doctest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <random>

#include "aw_cpp_std.h"
#include "ulp.hpp"

#define AW_FLOAT 1
namespace exp_f {
#include "aw_exp.h"
}  // namespace exp_f

TEST_SUITE("math") {
  TEST_CASE("exp (float) is within 1 ulp of expl on [-87, 88]") {
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<float> wide(-87.0f, 88.0f), narrow(-2.0f, 2.0f);
    double worst = 0;
    for (int i = 0; i < 2000000; ++i) {
      const float x = (i % 2) ? wide(rng) : narrow(rng);
      worst = std::max(worst, awtest::ulp_error(exp_f::aw_exp(x), expl(static_cast<long double>(x))));
    }
    std::printf("exp float: max error %.3f ulp\n", worst);
    CHECK(worst <= 1.0);
    CHECK(exp_f::aw_exp(0.0f) == 1.0f);
    CHECK(exp_f::aw_exp(200.0f) == exp_f::aw_exp(88.0f));
    CHECK(std::isfinite(exp_f::aw_exp(88.0f)));
    CHECK(exp_f::aw_exp(-87.0f) >= FLT_MIN);
  }
}
