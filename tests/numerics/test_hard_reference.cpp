// Hard cases (issue 5), part 7: an independent reference. A fixed set of hard
// orbits (test_hard.hpp: regular, chaotic, near the bottom of a well, high
// energy regular and chaotic, the saddle level, the maximum level), each one
// trajectory of a scene's ensemble, integrated by the project (the core, and
// every backend through the Backend API, which must give the core's bits) and
// by a reference computed another way: Boost.Odeint's Runge-Kutta-Fehlberg
// 7(8), adaptive, in long double, with libm's sinl/cosl, in radians without
// wrapping. The reference is itself checked against a long-double Yoshida-8
// splitting at a tiny step.
//
// The project integrates at its own step (0.01 T; 0.0025 T at E = 400), so it
// differs from the exact flow by its truncation error, which then grows like
// a perturbation of the orbit: linearly on a regular orbit, like e^(lambda t)
// on a chaotic one. Hence the statement: the phase-space distance stays below
// kTolerance up to a horizon per orbit, the Lyapunov-limited horizon
// t* = 1 T + ln(kTolerance / e(1 T)) / lambda on chaotic orbits (lambda from
// the growth of a 1e-12 perturbation, measured here). Values in
// docs/numerics.md.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

// GCC 12 sees odeint's scratch state copied before its first use (harmless)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/numeric/odeint.hpp>
#pragma GCC diagnostic pop

#include "support.hpp"
#include "test_hard.hpp"

using namespace arnoldweb;
using namespace hard;

namespace {

namespace odeint = boost::numeric::odeint;

// |X_project - X_reference| + |P_project - P_reference| (X in radians) must
// stay below this up to the horizon. Over the paper's window dt = 50 T it
// moves the averaged velocity by at most 3e-6, 1/5000 of a pixel at nside 64.
constexpr double kTolerance = 1e-3;

using OdeState = std::array<long double, 6>;

struct Rhs {
  void operator()(const OdeState& y, OdeState& dy, long double /*t*/) const {
    long double f[3];
    ld_force(y.data(), f);
    for (int c = 0; c < 3; ++c) {
      dy[c] = y[3 + c];
      dy[3 + c] = f[c];
    }
  }
};

// The reference trajectory sampled at t = 0, 1, ..., t_max T.
std::vector<LdState> rkf78_reference(const LdState& start, int t_max) {
  OdeState y;
  for (int c = 0; c < 3; ++c) {
    y[c] = start.x[c];
    y[3 + c] = start.p[c];
  }
  auto stepper = odeint::make_controlled(static_cast<long double>(1e-17L), static_cast<long double>(1e-17L),
                                         odeint::runge_kutta_fehlberg78<OdeState, long double>());
  std::vector<LdState> out(1, start);
  long double t = 0, dt = 1e-3L;
  for (int k = 1; k <= t_max; ++k) {
    const long double end = k * kTwoPiL;
    odeint::integrate_adaptive(stepper, Rhs(), y, t, end, dt);
    t = end;
    LdState s;
    for (int c = 0; c < 3; ++c) {
      s.x[c] = y[c];
      s.p[c] = y[3 + c];
    }
    out.push_back(s);
  }
  return out;
}

long double ld_distance(const LdState& a, const LdState& b) {
  long double dx2 = 0, dp2 = 0;
  for (int c = 0; c < 3; ++c) {
    dx2 += (a.x[c] - b.x[c]) * (a.x[c] - b.x[c]);
    dp2 += (a.p[c] - b.p[c]) * (a.p[c] - b.p[c]);
  }
  return sqrtl(dx2) + sqrtl(dp2);
}

struct RefCase {
  Orbit orbit;
  int horizon;     // T: the stated horizon (within the Lyapunov-limited t*)
  bool chaotic;
  double ref_step; // T: step of the long-double Yoshida-8 check of the reference
};

struct RefOutcome {
  std::vector<double> err;  // e(t), t = 0..horizon
  std::vector<double> growth;
  double lambda = 0;        // ln G(horizon) / horizon, per T
  double t_star = 0;        // Lyapunov-limited horizon estimated from e(1 T) and G
  double ref_check = 0;     // |RKF78 - Yoshida-8 (long double)| at min(horizon, 10 T)
  double ref_energy = 0;    // max |E_ref(t) - E_ref(0)|
  core_d::aw_lstate end{};  // the core's state at the horizon
};

RefOutcome compare(const RefCase& c) {
  RefOutcome out;
  const Orbit& o = c.orbit;
  const Plan plan = make_plan(orbit_scene(o, c.horizon));
  const core_d::aw_lstate start = orbit_start(plan, o.index);
  const std::vector<LdState> ref = rkf78_reference(to_ld(start), c.horizon);
  core_d::aw_lstate s = start;
  out.err.push_back(distance(s, ref[0]));
  const long double e0 = ld_energy(ref[0]);
  for (int t = 1; t <= c.horizon; ++t) {
    advance(&s, plan, 1, plan.steps_per_segment);  // the kernels' segmentation (|dE| every 1 T)
    out.err.push_back(distance(s, ref[static_cast<std::size_t>(t)]));
    out.ref_energy = std::max(out.ref_energy, static_cast<double>(fabsl(ld_energy(ref[static_cast<std::size_t>(t)]) - e0)));
  }
  out.end = s;
  // chaos: the growth of a perturbation, and the horizon it allows
  out.growth = twin_growth(plan, start, 3 * c.horizon);
  const int th = c.horizon;
  out.lambda = std::log(out.growth[static_cast<std::size_t>(th)]) / th;
  out.t_star = 3.0 * th;
  for (int t = 1; t <= 3 * th; ++t)
    if (out.err[1] * out.growth[static_cast<std::size_t>(t)] / out.growth[1] > kTolerance) {
      out.t_star = t - 1;
      break;
    }
  // the reference against a different long-double integrator
  Scene s8 = orbit_scene(o, 1.0);
  s8.method = "yoshida8d";
  s8.step = c.ref_step;
  const Plan p8 = make_plan(s8);
  const LdSplitting y8(p8);
  LdState l = to_ld(start);
  const int tc = std::min(c.horizon, 10);
  const std::int64_t n8 = static_cast<std::int64_t>(tc) * steps_per_t(p8);
  for (std::int64_t n = 0; n < n8; ++n) y8.step(l);
  out.ref_check = static_cast<double>(ld_distance(l, ref[static_cast<std::size_t>(tc)]));
  return out;
}

}  // namespace

TEST_SUITE("hard") {
  TEST_CASE("independent reference: hard orbits agree with long-double RKF78 up to their Lyapunov-limited horizon") {
    const RefCase cases[] = {
        {kRegular15, 100, false, 0.001},  {kChaotic15, 4, true, 0.001},   {kWell, 100, false, 0.001},
        {kRegular400, 100, false, 0.00025}, {kChaotic400, 7, true, 0.00025}, {kSaddle, 20, true, 0.001},
        {kTop, 4, true, 0.001},
    };
    constexpr int n = sizeof(cases) / sizeof(cases[0]);
    RefOutcome out[n];
#pragma omp parallel for num_threads(2) schedule(dynamic, 1)
    for (int k = 0; k < n; ++k) out[k] = compare(cases[k]);

    for (int k = 0; k < n; ++k) {
      const RefCase& c = cases[k];
      const RefOutcome& r = out[k];
      CAPTURE(c.orbit.name);
      double worst = 0;
      for (double e : r.err) worst = std::max(worst, e);
      std::printf("reference, %s, h = %g T: e(1 T) %.2e, e(%d T) %.2e, max %.2e (tolerance %.0e); growth G(%d T) "
                  "%.2e, ln G / t %.3f/T, estimated horizon t* %s%.0f T; reference vs Yoshida-8 %.1e, reference |dE| %.1e\n",
                  c.orbit.name, c.orbit.step, r.err[1], c.horizon, r.err.back(), worst, kTolerance, c.horizon,
                  r.growth[static_cast<std::size_t>(c.horizon)], r.lambda, r.t_star >= 3 * c.horizon ? ">= " : "",
                  r.t_star, r.ref_check, r.ref_energy);
      // the reference is good to far better than the tolerance
      CHECK(r.ref_check < kTolerance / 100);
      CHECK(r.ref_energy < 1e-10);
      // the orbit is what its name says, so the horizon is what it should be
      if (c.chaotic)
        CHECK(r.lambda > 0.2);
      else
        CHECK(r.growth[static_cast<std::size_t>(c.horizon)] < 20.0 * c.horizon);  // ~linear growth
      CHECK(c.horizon <= r.t_star);
      // the project agrees with the reference up to the horizon
      CHECK(worst <= kTolerance);
    }

    // Every backend runs the same orbits to the core's bits.
    for (const auto& dev : awtest::devices_under_test()) {
      CAPTURE(dev.id);
      for (int k = 0; k < n; ++k) {
        const RefCase& c = cases[k];
        CAPTURE(c.orbit.name);
        const Plan plan = make_plan(orbit_scene(c.orbit, c.horizon));
        const Result r = awtest::run_on(dev.id, plan);
        REQUIRE(r.reals("final_states").size() == (c.orbit.index + 1) * AW_STATE_REALS);
        const std::size_t i = c.orbit.index;
        const double got[6] = {r.reals("final_states")[i * AW_STATE_REALS + 0], r.reals("final_states")[i * AW_STATE_REALS + 1],
                               r.reals("final_states")[i * AW_STATE_REALS + 2], r.reals("final_states")[i * AW_STATE_REALS + 3],
                               r.reals("final_states")[i * AW_STATE_REALS + 4], r.reals("final_states")[i * AW_STATE_REALS + 5]};
        const double want[6] = {out[k].end.ux, out[k].end.uy, out[k].end.uz,
                                out[k].end.px, out[k].end.py, out[k].end.pz};
        CHECK(std::memcmp(got, want, sizeof got) == 0);
        CHECK(r.ints("final_states")[i * AW_STATE_INTS + 0] == out[k].end.wx);
        CHECK(r.ints("final_states")[i * AW_STATE_INTS + 1] == out[k].end.wy);
        CHECK(r.ints("final_states")[i * AW_STATE_INTS + 2] == out[k].end.wz);
        CHECK(r.ints("final_states")[i * AW_STATE_INTS + 3] == AW_STATUS_OK);
      }
    }
  }
}
