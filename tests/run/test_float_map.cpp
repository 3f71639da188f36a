// Issue 16: a float run keeps the map statistically identical to double.
// The default scene (E = 15, yoshida6a, h = 0.02, one 50 T window) at CI
// size on the cpu backend: the map of a float run against the map of a
// double run of independent initial states (another seed), by the
// two-sample chi-square test (compare_maps). The test has teeth: a double
// run at E = 13 is rejected at the same size, and the null (double against
// double, two seeds) passes.
#include <doctest/doctest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "support.hpp"

using namespace arnoldweb;

namespace {

// The default scene at CI size: nside 8 (768 pixels, ~65 counts each on
// average) and 50,000 trajectories.
Result run_default(double energy, int seed, const char* precision) {
  const Scene s = awtest::scene_from(R"(
    [ensemble]
    trajectories = 50000
    initial = "shell"
    [integrator]
    method = "yoshida6a"
    step = 0.02
    [run]
    average = 50
    duration = 50
    [observe]
    velocity_map = { nside = 8 }
    energy_error = false
  )",
                                     {awtest::set("model.energy", energy), awtest::set("ensemble.seed", seed),
                                      awtest::set("integrator.precision", std::string(precision))},
                                     "<float map>");
  return awtest::run_on("cpu", make_plan(s));
}

MapComparison compared(const char* what, const Result& a, const Result& b) {
  REQUIRE(a.binned == 50000);
  REQUIRE(b.binned == 50000);
  const MapComparison c = compare_maps(a.map, b.map);
  std::printf("%s: chi2 %.1f, dof %.0f, chi2/dof %.3f, p %.3g (%zu bins pooled)\n", what, c.chi2, c.dof,
              c.chi2_per_dof(), c.p_value, c.pooled_bins);
  return c;
}

}  // namespace

TEST_SUITE("compare-float") {
  TEST_CASE("a float run's map is statistically the double run's (chi-square test, E = 15)") {
    const Result d1 = run_default(15, 1, "double");
    const Result f2 = run_default(15, 2, "float");
    const Result d2 = run_default(15, 2, "double");
    const Result e13 = run_default(13, 3, "double");
    // the float run is one: same initial directions as d2 (seed 2), other trajectories
    CHECK(f2.map != d2.map);
    CHECK(compared("float seed 2 vs double seed 1", f2, d1).p_value > 1e-3);
    CHECK(compared("double seed 2 vs double seed 1 (the null)", d2, d1).p_value > 1e-3);
    // teeth: E = 13 (eps_eff = 2/13 instead of 2/15: wider resonance lines) is
    // seen at this size (E = 14 gives p ~ 4e-5 with seed 7, too close to 1e-6; 2026-11-23)
    CHECK(compared("double E = 13 vs double E = 15", e13, d1).p_value < 1e-6);
  }
}
