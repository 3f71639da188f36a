// test_math_lanes.cpp in float: aw_log_lanes = aw_log and aw_sincos2pi =
// aw_sincos2pi_1 bit for bit, 8 lanes of GCC vectors.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "aw_cpp_std.h"
#include "lane_parity.hpp"

#define AW_LANES 8
#define AW_FLOAT 1
namespace lanes_f {
#include "aw_math.h"
}  // namespace lanes_f

using L = lanes_f::lreal;

TEST_SUITE("math") {
  TEST_CASE("lane and scalar forms agree bit for bit (float): aw_log_lanes = aw_log, aw_sincos2pi = aw_sincos2pi_1") {
    std::mt19937_64 rng(27);
    std::uniform_real_distribution<double> expo(-30, 30), ratio(0.25, 4.0), turns(-70.0, 70.0);
    auto log_lanes = [](const float* x, float* y) {
      L v;
      std::memcpy(&v, x, sizeof v);
      const L r = lanes_f::aw_log_lanes(v);
      std::memcpy(y, &r, sizeof r);
    };
    auto log_one = [](float x) { return lanes_f::aw_log(x); };
    auto sin_lanes = [](const float* x, float* y) {
      L u, s, c;
      std::memcpy(&u, x, sizeof u);
      lanes_f::aw_sincos2pi(u, &s, &c);
      std::memcpy(y, &s, sizeof s);
    };
    auto cos_lanes = [](const float* x, float* y) {
      L u, s, c;
      std::memcpy(&u, x, sizeof u);
      lanes_f::aw_sincos2pi(u, &s, &c);
      std::memcpy(y, &c, sizeof c);
    };
    auto sin_one = [](float u) { float s, c; lanes_f::aw_sincos2pi_1(u, &s, &c); return s; };
    auto cos_one = [](float u) { float s, c; lanes_f::aw_sincos2pi_1(u, &s, &c); return c; };
    auto f = [](double x) { return static_cast<float>(x); };
    CHECK(awtest::lane_mismatches<float>([&] { return f(std::pow(10.0, expo(rng))); }, log_lanes, log_one) == 0);
    CHECK(awtest::lane_mismatches<float>([&] { return f(ratio(rng)); }, log_lanes, log_one) == 0);
    CHECK(awtest::lane_mismatches<float>([&] { return f(turns(rng)); }, sin_lanes, sin_one) == 0);
    CHECK(awtest::lane_mismatches<float>([&] { return f(turns(rng)); }, cos_lanes, cos_one) == 0);
  }
}
