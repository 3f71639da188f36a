// The device core as C++: initial conditions on the energy shell, energy
// conservation of a regular orbit, exact winding bookkeeping.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "arnoldweb/plan.hpp"
#include "core_double.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

Plan plan_for(double energy, double step = 0.01) {
  return make_plan(awtest::scene_from("[run]\naverage = 10\nduration = 10\n",
                                      {awtest::set("model.energy", energy), awtest::set("integrator.step", step)},
                                      "<core>"));
}

core_d::aw_lstate initial(const Plan& p, std::uint64_t index, bool* ok) {
  core_d::aw_lstate st;
  *ok = core_d::aw_initial_state(&st, AW_INITIAL_SHELL, index, core_d::rp_of(p), core_d::ip_of(p)) != 0.0;
  return st;
}

}  // namespace

TEST_SUITE("core") {
  TEST_CASE("every initial state lies on the energy shell to a few ulps") {
    for (double energy : {-1.8, 0.0, 15.0, 400.0}) {
      const Plan p = plan_for(energy, 0.001);
      double worst = 0;
      for (std::uint64_t i = 0; i < 20000; ++i) {
        bool ok;
        core_d::aw_lstate st = initial(p, i, &ok);
        REQUIRE(ok);
        const double e = core_d::aw_energy(&st);
        const double ulp = std::nextafter(std::fabs(energy) + 2.0, INFINITY) - (std::fabs(energy) + 2.0);
        worst = std::max(worst, std::fabs(e - energy) / ulp);
        CHECK(std::fabs(st.ux) <= 0.5);
      }
      CAPTURE(energy);
      std::printf("initial energy at E = %g: max error %.2f ulp of |E| + 2\n", energy, worst);
      CHECK(worst <= 4.0);
    }
  }

  TEST_CASE("initial directions are uniform on the sphere (chi-square over HEALPix pixels)") {
    const Plan p = plan_for(15.0);
    const long nside = 4, npix = 12 * nside * nside, n = 200000;
    std::vector<long> count(npix, 0);
    for (long i = 0; i < n; ++i) {
      bool ok;
      core_d::aw_lstate st = initial(p, static_cast<std::uint64_t>(i), &ok);
      REQUIRE(ok);
      ++count[core_d::aw_vec2pix_ring(nside, st.px, st.py, st.pz)];
    }
    double chi2 = 0;
    const double expect = static_cast<double>(n) / npix;
    for (long c : count) chi2 += (c - expect) * (c - expect) / expect;
    std::printf("direction chi-square: %.1f for %ld degrees of freedom\n", chi2, npix - 1);
    // 5 standard deviations above the mean of chi-square(npix - 1)
    CHECK(chi2 < (npix - 1) + 5 * std::sqrt(2.0 * (npix - 1)));
    CHECK(chi2 > (npix - 1) - 5 * std::sqrt(2.0 * (npix - 1)));
  }

  TEST_CASE("positions are uniform over the accessible part of the torus") {
    // At E = 0 the accessible set is V(X) < 0; its fraction sets the acceptance rate.
    const Plan p = plan_for(0.0);
    std::vector<long> xbins(8, 0);
    for (std::uint64_t i = 0; i < 80000; ++i) {
      bool ok;
      core_d::aw_lstate st = initial(p, i, &ok);
      REQUIRE(ok);
      CHECK(core_d::aw_potential(st.ux, st.uy, st.uz) < 0.0);
      ++xbins[static_cast<std::size_t>((st.uz + 0.5) * 8) % 8];
    }
    // V is even in z about 0 and symmetric under z -> z + 1/2: equal mass in mirrored bins
    for (int b = 0; b < 4; ++b) CHECK(std::abs(xbins[b] - xbins[7 - b]) < 5 * std::sqrt(2.0 * xbins[b]));
  }

  TEST_CASE("an orbit keeps its energy error bounded over 10^6 steps, with no drift") {
    const Plan p = plan_for(15.0);  // yoshida6a, h = 0.01 T
    core_d::aw_lstate s{};
    s.ux = 0.1;
    s.uy = 0.2;
    s.uz = 0.3;
    const double v = core_d::aw_potential(s.ux, s.uy, s.uz);
    const double pm = std::sqrt(2 * (15.0 - v));
    const double d[3] = {1.0, std::sqrt(2.0), std::sqrt(3.0)};  // (chaotic within ~10^4 steps: test_hard covers regular ones)
    const double norm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    s.px = pm * d[0] / norm;
    s.py = pm * d[1] / norm;
    s.pz = pm * d[2] / norm;
    core_d::aw_force(&s);
    const double e0 = core_d::aw_energy(&s);
    double max_first = 0, max_second = 0;
    const int segments = 1000, steps = 1000;
    for (int g = 0; g < segments; ++g) {
      core_d::aw_segment(&s, steps, core_d::rp_of(p), p.method.stages, p.method.kick_first, p.method.force_gradient());
      const double de = std::fabs(core_d::aw_energy(&s) - e0);
      (g < segments / 2 ? max_first : max_second) = std::max(g < segments / 2 ? max_first : max_second, de);
    }
    std::printf("orbit, 10^6 steps: max |dE| first half %.3g, second half %.3g\n", max_first, max_second);
    CHECK(max_first < 5e-6);
    CHECK(max_second < 5e-6);
    CHECK(max_second < 2.0 * max_first + 1e-15);  // bounded, not growing
  }

  TEST_CASE("wrapping keeps angles in [-1/2, 1/2] turns and windings integral") {
    const Plan p = plan_for(400.0, 0.001);
    bool ok;
    core_d::aw_lstate s = initial(p, 7, &ok);
    REQUIRE(ok);
    core_d::aw_force(&s);
    const double x0 = s.ux, px0 = s.px;
    core_d::aw_segment(&s, 5000, core_d::rp_of(p), p.method.stages, p.method.kick_first, p.method.force_gradient());
    CHECK(std::fabs(s.ux) <= 0.5);
    CHECK(std::fabs(s.uy) <= 0.5);
    CHECK(std::fabs(s.uz) <= 0.5);
    // 5 T at |p| ~ 28: about 140 turns; the total displacement follows p
    const double turns = static_cast<double>(s.wx) + s.ux - x0;
    CHECK(turns == doctest::Approx(px0 * 5.0).epsilon(0.05));
  }
}
