// Order: every method reaches its nominal order of convergence on this
// Hamiltonian, on every device (ctest entries order.cpu, order.opencl,
// order.cuda); and float runs in portable math give the same bits on every
// device, the cpu backend included, as the scalar core compiled in the test
// (tests/support/scalar_core.hpp), for every method.
//
// Measurement: 256 trajectories on the shell at E = 2 (eps_eff = 1: trapped,
// rotating and chaotic orbits), integrated over 1 T with each method at four
// steps h = T/n; the error is the RMS over the ensemble of the phase-space
// distance |dX| + |dP| of the final state from a reference (Kahan-Li s15odr8,
// h = T/1000, whose own error is ~1e-18, far below round-off). The measured
// order is the least-squares slope of log(error) against log(h). The steps of
// each method put its errors between ~1e-5 and ~3e-11, in the asymptotic
// regime and 50x above the round-off floor (~7e-13, measured by the test as the
// distance between two different converged references). E = 2 rather than the
// paper's energies: slower particles reach the asymptotic regime of the
// high-order compositions at errors well above round-off (at E = 15 the 8th-order
// methods are only asymptotic below ~1e-11; docs/methods.md).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "aw_params.h"
#include "scalar_core.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

constexpr double kEnergy = 2.0;
constexpr std::uint64_t kTrajectories = 256;
constexpr double kHorizon = 1.0;  // in T
constexpr int kReferenceSteps = 1000;

// Steps per T for each method, chosen once (the results are the same bits on
// every device). A method without a row fails the test. The near-integrable
// families have no single order at E = 2 (eps_eff = 1): their orders in h and in
// eps are checked by tests/physics/test_order_eps.cpp.
const std::map<std::string, std::vector<int>>& order_steps() {
  static const std::map<std::string, std::vector<int>> steps = {
      {"leapfrog", {200, 400, 800, 1600}},   {"forest-ruth", {100, 200, 400, 800}},
      {"pefrl", {100, 200, 400, 800}},       {"srkn6b", {100, 200, 400, 800}},
      {"yoshida6a", {64, 128, 256, 512}},    {"kahan-li-s9", {50, 100, 200, 400}},
      {"srkn11b", {40, 57, 80, 113}},        {"kahan-li-s15", {50, 63, 80, 101}},
      {"yoshida8d", {64, 91, 128, 181}},     {"chin4a", {50, 100, 200, 400}},
      {"omf6v", {45, 64, 90, 128}},
  };
  return steps;
}

// The ensemble at kEnergy over kHorizon, final states only; `sets` change it.
Scene order_scene(const std::string& method, int steps_per_t, const std::vector<std::string>& sets = {}) {
  std::vector<std::string> all = {awtest::set("model.energy", kEnergy),
                                  awtest::set("ensemble.trajectories", kTrajectories),
                                  awtest::set("integrator.method", method),
                                  awtest::set("integrator.step", 1.0 / steps_per_t),
                                  awtest::set("run.average", kHorizon),
                                  awtest::set("run.duration", kHorizon)};
  all.insert(all.end(), sets.begin(), sets.end());
  return awtest::scene_from(R"(
    [ensemble]
    seed = 7
    [observe]
    velocity_map = false
    energy_error = false
    final_states = true
  )", all, "<order>");
}

Result run_order(const std::string& device, const std::string& method, int steps_per_t) {
  const Result r = awtest::run_on(device, make_plan(order_scene(method, steps_per_t)));
  REQUIRE(r.reals("final_states").size() == kTrajectories * AW_STATE_REALS);
  REQUIRE(r.ints("final_states").size() == kTrajectories * AW_STATE_INTS);
  return r;
}

// RMS over the ensemble of the phase-space distance between two final states
// (positions in radians from winding + wrapped turns, momenta).
double rms_distance(const Result& a, const Result& b) {
  double sum = 0;
  for (std::size_t i = 0; i < kTrajectories; ++i) {
    REQUIRE(a.ints("final_states")[i * AW_STATE_INTS + 3] == AW_STATUS_OK);
    double d2 = 0;
    for (int c = 0; c < 3; ++c) {
      const double turns =
          static_cast<double>(a.ints("final_states")[i * AW_STATE_INTS + c] - b.ints("final_states")[i * AW_STATE_INTS + c]) +
          (a.reals("final_states")[i * AW_STATE_REALS + c] - b.reals("final_states")[i * AW_STATE_REALS + c]);
      const double dx = 2 * M_PI * turns;
      const double dp = a.reals("final_states")[i * AW_STATE_REALS + 3 + c] - b.reals("final_states")[i * AW_STATE_REALS + 3 + c];
      d2 += dx * dx + dp * dp;
    }
    sum += d2;
  }
  return std::sqrt(sum / kTrajectories);
}

// Least-squares slope of log(error) against log(h).
double fitted_order(const std::vector<int>& steps_per_t, const std::vector<double>& errors) {
  const std::size_t n = errors.size();
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) {
    mx += std::log(1.0 / steps_per_t[i]);
    my += std::log(errors[i]);
  }
  mx /= n;
  my /= n;
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = std::log(1.0 / steps_per_t[i]) - mx;
    sxy += x * (std::log(errors[i]) - my);
    sxx += x * x;
  }
  return sxy / sxx;
}

}  // namespace

TEST_SUITE("order") {
  TEST_CASE("every method converges at its nominal order on this Hamiltonian (within 0.15)") {
    for (const Method& m : methods()) {
      CAPTURE(m.name);
      CHECK(order_steps().count(m.name) == (m.family == "near-integrable" ? 0 : 1));
    }
    for (const auto& dev : awtest::devices_under_test()) {
      CAPTURE(dev.id);
      const Result ref = run_order(dev.id, "kahan-li-s15", kReferenceSteps);
      // a second, independent converged solution: their distance is the
      // round-off floor every measured error must stay well above
      const Result ref2 = run_order(dev.id, "yoshida8d", kReferenceSteps);
      const double floor = rms_distance(ref, ref2);
      std::printf("order on %s (E = %g, %llu trajectories, %g T; round-off floor %.2e):\n", dev.id.c_str(),
                  kEnergy, static_cast<unsigned long long>(kTrajectories), kHorizon, floor);
      CHECK(floor < 1e-11);
      for (const Method& m : methods()) {
        CAPTURE(m.name);
        const auto it = order_steps().find(m.name);
        if (it == order_steps().end()) continue;
        const std::vector<int>& steps = it->second;
        std::vector<double> errors;
        std::printf("  %-13s", m.name.c_str());
        for (int n : steps) {
          errors.push_back(rms_distance(run_order(dev.id, m.name, n), ref));
          std::printf("  T/%-4d %.2e", n, errors.back());
        }
        const double order = fitted_order(steps, errors);
        std::printf("  -> order %.3f (nominal %d); pairs", order, m.order);
        for (std::size_t i = 0; i + 1 < steps.size(); ++i) {
          // asymptotic regime: every pair of neighbouring steps agrees on the order
          const double local = std::log(errors[i] / errors[i + 1]) / std::log(double(steps[i + 1]) / steps[i]);
          std::printf(" %.2f", local);
          CHECK(std::fabs(local - m.order) <= 0.3);
        }
        std::printf("\n");
        for (double e : errors) CHECK(e > 30 * floor);  // measured above round-off
        CHECK(std::fabs(order - m.order) <= 0.15);
      }
    }
  }

  TEST_CASE("float, portable math: every method gives the bits of the scalar core on every device, cpu included") {
    for (const Method& m : methods()) {
      CAPTURE(m.name);
      const Scene s = order_scene(m.name, 100,
                                  {"integrator.precision=\"float\"", "model.energy=15", "run.average=2",
                                   "run.duration=2",  // 200 steps
                                   "observe.energy_error={ every = 0.5 }", "observe.velocity_map={ nside = 8 }"});
      const Plan plan = make_plan(s);
      // the reference: the core compiled in this test without vectors (tests/support/scalar_core.hpp)
      const Result ref = awtest::run_scalar_core(plan);
      REQUIRE(ref.reals("final_states").size() == kTrajectories * AW_STATE_REALS);
      REQUIRE_FALSE(awtest::devices_under_test().empty());
      for (const auto& dev : awtest::devices_under_test()) {
        CAPTURE(dev.id);
        const Result r = awtest::run_on(dev.id, plan);
        const long d = awtest::first_difference(r.reals("final_states"), ref.reals("final_states"));
        CHECK_MESSAGE(d == -1, "first differing state value at trajectory " << d / AW_STATE_REALS);
        CHECK(awtest::first_difference(r.ints("final_states"), ref.ints("final_states")) == -1);
        CHECK(r.energy.max == ref.energy.max);
        CHECK(r.energy.log_hist == ref.energy.log_hist);
        CHECK(digest_map(r) == digest_map(ref));
      }
    }
  }
}
