// test_math_lanes.cpp in float: aw_log_lanes = aw_log and aw_sincos2pi =
// aw_sincos2pi_1 bit for bit, 8 lanes of GCC vectors.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "aw_cpp_std.h"
#include "lane_parity.hpp"

#define AW_LANES 8
#define AW_FLOAT 1
namespace lanes_f {
#include "aw_math.h"
}  // namespace lanes_f

TEST_SUITE("math") {
  TEST_CASE("lane and scalar forms agree bit for bit (float): aw_log_lanes = aw_log, aw_sincos2pi = aw_sincos2pi_1") {
    std::mt19937_64 rng(27);
    std::uniform_real_distribution<double> expo(-30, 30), ratio(0.25, 4.0), turns(-70.0, 70.0);
    auto f = [](double x) { return static_cast<float>(x); };
    CHECK(awtest::log_mismatches<float>([&] { return f(std::pow(10.0, expo(rng))); }, lanes_f::aw_log_lanes,
                                        lanes_f::aw_log) == 0);
    CHECK(awtest::log_mismatches<float>([&] { return f(ratio(rng)); }, lanes_f::aw_log_lanes, lanes_f::aw_log) == 0);
    CHECK(awtest::sincos_mismatches<float>([&] { return f(turns(rng)); }, lanes_f::aw_sincos2pi,
                                           lanes_f::aw_sincos2pi_1) == 0);
  }
}
