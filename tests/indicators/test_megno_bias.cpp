// MEGNO without its first-order step bias (issue 26, item 4): the kernel's
// mean MEGNO of a regular orbit against an independent accumulation of the
// same definition, Y_k = (2/k) sum_j j log(|w_j| / |w_{j-1}|), from the
// tangent vectors of the core taken one step at a time and summed in long
// double. The growth rate of the step is the exact ratio of norms, so the two
// agree to round-off at every step size; the former rate h (w . w') / |w|^2
// was low by O(h) (docs/indicators.md).
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "aw_params.h"
#include "core_double.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

// One trajectory of the paper's model at P (a plane grid of one point),
// position X (radians), MEGNO on.
Scene regular_orbit(double energy, std::array<double, 3> p, std::array<double, 3> x, double duration, double step) {
  return awtest::scene_from(R"(
    [ensemble]
    initial = "grid"
    grid = { kind = "plane", resolution = [1, 1] }
    [integrator]
    allow_unsafe_step = true
    [observe]
    velocity_map = false
    initial_states = true
    fli = true
    megno = true
  )",
                            {awtest::set("model.energy", energy), awtest::set("integrator.step", step),
                             awtest::set("run.average", duration), awtest::set("run.duration", duration),
                             awtest::set("ensemble.grid.range1", std::array<double, 2>{p[0] - 1e-3, p[0] + 1e-3}),
                             awtest::set("ensemble.grid.range2", std::array<double, 2>{p[1] - 1e-3, p[1] + 1e-3}),
                             awtest::set("ensemble.grid.fixed", p[2]), awtest::set("ensemble.grid.position", x)},
                            "<megno-bias>");
}

// <Y> from the core's tangent vector one step at a time (every step ends with
// its own last kick, the synchronised w), the logarithms and sums in long
// double: log|w_k| = log2w ln 2 + log|w_stored|.
long double reference_megno(const Plan& plan, const std::vector<double>& initial, long steps) {
  const core_d::aw_rparams* rp = core_d::rp_of(plan);
  const core_d::aw_config cfg = {plan.kernel.features, plan.kernel.stages, plan.kernel.kick_first ? 1 : 0,
                                 plan.kernel.initial, plan.kernel.gradient ? 1 : 0};
  core_d::aw_lstate s{};
  s.ux = initial[0];
  s.uy = initial[1];
  s.uz = initial[2];
  s.px = initial[3];
  s.py = initial[4];
  s.pz = initial[5];
  core_d::aw_tangent t;
  core_d::aw_tangent_begin(&t, rp);
  core_d::aw_tangent_force(&s, &t, rp);
  auto log_norm = [&t] {
    const long double n2 = (long double)t.qx * t.qx + (long double)t.qy * t.qy + (long double)t.qz * t.qz +
                           (long double)t.px * t.px + (long double)t.py * t.py + (long double)t.pz * t.pz;
    return (long double)t.log2w * 0.693147180559945309417232121458176568L + 0.5L * logl(n2);
  };
  long double previous = log_norm(), s1 = 0, ysum = 0;
  for (long k = 1; k <= steps; ++k) {
    core_d::aw_segment_tangent(cfg, &s, &t, 1, rp);
    const long double now = log_norm();
    s1 += (long double)k * (now - previous);
    ysum += 2 * s1 / (long double)k;
    previous = now;
  }
  return ysum / (long double)steps;
}

}  // namespace

TEST_SUITE("indicators") {
  TEST_CASE("MEGNO has no step bias: <Y> equals the exact-ratio definition to round-off at h, h/2, h/4") {
    // E = 50 (perturbation 2/E = 0.04), P along lon 30, lat 40 degrees at X = (0.3, 0.7, 1.1): a
    // regular orbit (<Y> close to 2, FLI ~ log t); 100 T at h = 0.01, 0.005, 0.0025 T
    const double energy = 50, speed = 10;
    const double lon = 30 * M_PI / 180, lat = 40 * M_PI / 180;
    const std::array<double, 3> p = {speed * std::cos(lat) * std::cos(lon), speed * std::cos(lat) * std::sin(lon),
                                     speed * std::sin(lat)};
    for (const double h : {0.01, 0.005, 0.0025}) {
      CAPTURE(h);
      const Plan plan = make_plan(regular_orbit(energy, p, {0.3, 0.7, 1.1}, 100, h));
      const Result r = awtest::run_on("cpu", plan);
      REQUIRE(r.initial_r.size() == AW_STATE_REALS);
      const double megno = r.indicators[AW_IND_MEGNO];
      const long steps = std::lround(100 / h);
      const long double ref = reference_megno(plan, r.initial_r, steps);
      const double bias = static_cast<double>(megno - ref);
      MESSAGE("h = " << h << " T: <Y> = " << megno << ", exact-ratio reference " << static_cast<double>(ref)
                     << ", difference " << bias);
      CHECK(std::fabs(ref - 2) < 0.1);  // a regular orbit
      CHECK(std::fabs(bias) < 1e-10);   // round-off: no O(h) term left
    }
  }
}
