// The scalar and lane forms of the portable functions give the same bits
// (double; test_math_lanes_float.cpp: float): aw_log_lanes (MEGNO's per-step
// logarithm) against aw_log, and aw_sincos2pi_1 (the frequency analysis's
// scalar sin/cos) against the lane aw_sincos2pi, compiled with 8 lanes of GCC
// vectors as the cpu backend compiles the core.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "aw_cpp_std.h"
#include "lane_parity.hpp"

#define AW_LANES 8
namespace lanes_d {
#include "aw_math.h"
}  // namespace lanes_d

using L = lanes_d::lreal;

TEST_SUITE("math") {
  TEST_CASE("lane and scalar forms agree bit for bit (double): aw_log_lanes = aw_log, aw_sincos2pi = aw_sincos2pi_1") {
    std::mt19937_64 rng(26);
    std::uniform_real_distribution<double> expo(-300, 300), ratio(0.25, 4.0), turns(-70.0, 70.0);
    auto log_lanes = [](const double* x, double* y) {
      L v;
      std::memcpy(&v, x, sizeof v);
      const L r = lanes_d::aw_log_lanes(v);
      std::memcpy(y, &r, sizeof r);
    };
    auto log_one = [](double x) { return lanes_d::aw_log(x); };
    auto sin_lanes = [](const double* x, double* y) {
      L u, s, c;
      std::memcpy(&u, x, sizeof u);
      lanes_d::aw_sincos2pi(u, &s, &c);
      std::memcpy(y, &s, sizeof s);
    };
    auto cos_lanes = [](const double* x, double* y) {
      L u, s, c;
      std::memcpy(&u, x, sizeof u);
      lanes_d::aw_sincos2pi(u, &s, &c);
      std::memcpy(y, &c, sizeof c);
    };
    auto sin_one = [](double u) { double s, c; lanes_d::aw_sincos2pi_1(u, &s, &c); return s; };
    auto cos_one = [](double u) { double s, c; lanes_d::aw_sincos2pi_1(u, &s, &c); return c; };
    // positive normal numbers over the whole range, and ratios of norms near 1 (MEGNO's arguments)
    CHECK(awtest::lane_mismatches<double>([&] { return std::pow(10.0, expo(rng)); }, log_lanes, log_one) == 0);
    CHECK(awtest::lane_mismatches<double>([&] { return ratio(rng); }, log_lanes, log_one) == 0);
    CHECK(awtest::lane_mismatches<double>([&] { return turns(rng); }, sin_lanes, sin_one) == 0);
    CHECK(awtest::lane_mismatches<double>([&] { return turns(rng); }, cos_lanes, cos_one) == 0);
    // and the logarithm is a logarithm: exact at 1 and 1/2, within an ulp of std::log at 3
    CHECK(lanes_d::aw_log(1.0) == 0.0);
    CHECK(lanes_d::aw_log(0.5) == -std::log(2.0));
    CHECK(std::fabs(lanes_d::aw_log(3.0) - std::log(3.0)) < 4.5e-16);
  }
}
