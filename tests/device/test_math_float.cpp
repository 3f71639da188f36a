// The single-precision portable functions against long-double references.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core_float.hpp"
#include "ulp.hpp"

TEST_SUITE("math") {
  TEST_CASE("sincos2pi (float) is within 2 ulp over the range the stepper uses") {
    std::mt19937_64 rng(43);
    std::uniform_real_distribution<float> wide(-2.0f, 2.0f);
    double worst_s = 0, worst_c = 0;
    for (int i = 0; i < 2000000; ++i) {
      const float u = wide(rng);
      float s, c;
      core_f::aw_sincos2pi(u, &s, &c);
      long double rs, rc;
      awtest::sincos2pi_reference(u, &rs, &rc);
      worst_s = std::max(worst_s, awtest::ulp_error(s, rs));
      worst_c = std::max(worst_c, awtest::ulp_error(c, rc));
    }
    std::printf("sincos2pi float: max error sin %.3f ulp, cos %.3f ulp\n", worst_s, worst_c);
    CHECK(worst_s <= 2.0);
    CHECK(worst_c <= 2.0);
  }

  TEST_CASE("atan2 (float) is within 3.5 ulp of atan2l") {
    std::mt19937_64 rng(8);
    std::normal_distribution<float> n01;
    double worst = 0;
    for (int i = 0; i < 1000000; ++i) {
      const float y = n01(rng), x = n01(rng);
      worst = std::max(worst, awtest::ulp_error(core_f::aw_atan2(y, x), atan2l(y, x)));
    }
    std::printf("atan2 float: max error %.3f ulp\n", worst);
    CHECK(worst <= 3.5);
  }
}
