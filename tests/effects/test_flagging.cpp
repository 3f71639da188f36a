// Broken values: a trajectory that becomes NaN or Inf (injected by the test
// hook AW_F_TEST_INJECT) or exceeds observe.max_energy_error is flagged,
// counted by reason, and never binned; the run completes. On every device.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "aw_params.h"
#include "plan/plan_params.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

Scene flag_scene(std::uint64_t n, const std::vector<std::string>& sets = {}) {
  std::vector<std::string> all = {awtest::set("ensemble.trajectories", n)};
  all.insert(all.end(), sets.begin(), sets.end());
  return awtest::scene_from(R"(
    [model]
    energy = 15
    [integrator]
    step = 0.01
    [run]
    average = 2
    duration = 4  # two windows
    [observe]
    velocity_map = { nside = 8 }
    final_states = true
  )", all, "<flagging>");
}

std::uint64_t total(const std::vector<std::uint64_t>& m) {
  return std::accumulate(m.begin(), m.end(), std::uint64_t{0});
}

}  // namespace

TEST_SUITE("parity") {
  TEST_CASE("an injected NaN or Inf is flagged as non-finite and never binned") {
    for (const auto& dev : awtest::devices_under_test()) {
      for (double poison : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        CAPTURE(dev.id);
        CAPTURE(poison);
        Plan p = make_plan(flag_scene(1000));
        p.kernel.features |= AW_F_TEST_INJECT;
        arnoldweb::detail::KernelParams& kp = arnoldweb::detail::edit_params(p);
        kp.reals.inject_value = poison;
        kp.ints.inject_index = 417;
        const Result r = awtest::run_on(dev.id, p);
        CHECK(r.flagged_nonfinite == 1);
        CHECK(r.flagged_energy == 0);
        CHECK(r.binned == 999);
        CHECK(r.binned + r.flagged() == r.trajectories);
        CHECK(total(r.map) == 999 * 2);  // two windows each
        CHECK(r.ints("final_states")[417 * AW_STATE_INTS + 3] == AW_STATUS_NONFINITE);
        CHECK(r.ints("final_states")[416 * AW_STATE_INTS + 3] == AW_STATUS_OK);
        CHECK(std::isfinite(r.energy.max));
      }
    }
  }

  TEST_CASE("observe.max_energy_error flags and excludes trajectories above it") {
    for (const auto& dev : awtest::devices_under_test()) {
      CAPTURE(dev.id);
      // about the median max|dE| at h = 0.01 T, E = 15
      const Scene s = flag_scene(2000, {"observe.max_energy_error=3e-7"});
      const Result r = awtest::run_on(dev.id, make_plan(s));
      CHECK(r.flagged_energy > 100);
      CHECK(r.binned > 100);
      CHECK(r.binned + r.flagged() == r.trajectories);
      CHECK(r.energy.max <= 3e-7);  // statistics are over binned trajectories
      std::uint64_t windows_binned = total(r.map);
      CHECK(windows_binned >= 2 * r.binned);        // flagged in window 2 still binned window 1
      CHECK(windows_binned < 2 * r.trajectories);
    }
  }
}
