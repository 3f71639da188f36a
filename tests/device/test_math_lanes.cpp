// The scalar and lane forms of the portable functions give the same bits
// (double; test_math_lanes_float.cpp: float): aw_log_lanes (MEGNO's per-step
// logarithm) against aw_log, and aw_sincos2pi_1 (the frequency analysis's
// scalar sin/cos) against the lane aw_sincos2pi, compiled with 8 lanes of GCC
// vectors as the cpu backend compiles the core.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "aw_cpp_std.h"
#include "lane_parity.hpp"

#define AW_LANES 8
namespace lanes_d {
#include "aw_math.h"
}  // namespace lanes_d

TEST_SUITE("math") {
  TEST_CASE("lane and scalar forms agree bit for bit (double): aw_log_lanes = aw_log, aw_sincos2pi = aw_sincos2pi_1") {
    std::mt19937_64 rng(26);
    std::uniform_real_distribution<double> expo(-300, 300), ratio(0.25, 4.0), turns(-70.0, 70.0);
    // positive normal numbers over the whole range, and ratios of norms near 1 (MEGNO's arguments)
    CHECK(awtest::log_mismatches<double>([&] { return std::pow(10.0, expo(rng)); }, lanes_d::aw_log_lanes,
                                         lanes_d::aw_log) == 0);
    CHECK(awtest::log_mismatches<double>([&] { return ratio(rng); }, lanes_d::aw_log_lanes, lanes_d::aw_log) == 0);
    CHECK(awtest::sincos_mismatches<double>([&] { return turns(rng); }, lanes_d::aw_sincos2pi,
                                            lanes_d::aw_sincos2pi_1) == 0);
    // and the logarithm is a logarithm: exact at 1 and 1/2, within an ulp of std::log at 3
    CHECK(lanes_d::aw_log(1.0) == 0.0);
    CHECK(lanes_d::aw_log(0.5) == -std::log(2.0));
    CHECK(std::fabs(lanes_d::aw_log(3.0) - std::log(3.0)) < 4.5e-16);
  }
}
