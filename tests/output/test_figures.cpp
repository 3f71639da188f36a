// The paper's qualitative claims as numbers (CI-size runs on the cpu backend):
//  - Figure 3 (E = 15): every primary resonance circle m.P = 0 (the Fourier
//    modes of V) is a bright line: its density exceeds its dark zone's.
//  - Figure 4: an ensemble injected at W = (sqrt E, sqrt E, 0) spreads in two
//    stages: fast (the spread grows ~ linearly in t), then slower.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "support.hpp"

using namespace arnoldweb;

TEST_SUITE("figures") {
  TEST_CASE("Figure 3: the primary resonance lines stand out of their dark zones") {
    const Scene s = awtest::scene_from(R"(
      [model]
      energy = 15
      [ensemble]
      trajectories = 400000
      [integrator]
      step = 0.02
      [run]
      average = 50
      duration = 50
      [observe]
      velocity_map = { nside = 128 }
      energy_error = { every = 5 }
    )", {}, "<figure 3, CI size>");
    const Result r = awtest::run_on("cpu", make_plan(s));
    const double deg = M_PI / 180;
    const auto primary = primary_resonances();
    // the circles drawn in the paper's figures: every order-1 circle and the primaries
    auto others = resonances(1);
    others.insert(others.end(), primary.begin(), primary.end());
    for (const Resonance& m : primary) {
      // line: within 0.5 deg; dark zone: 2 to 6 deg away; the neighbourhood
      // of the other circles (within 4 deg: their lines and intersections) left out
      const LineContrast c = line_contrast(r.map, s.nside, m, 0.5 * deg, 2 * deg, 4 * deg, others, 4 * deg);
      std::printf("resonance %s: line %.1f, dark zone %.1f counts/pixel, ratio %.2f\n", m.label().c_str(),
                  c.line_density, c.zone_density, c.ratio());
      CAPTURE(m.label());
      CHECK(c.line_pixels > 100);
      CHECK(c.ratio() > 1.4);
    }
  }

  TEST_CASE("Figure 4: the spread about the injection point grows fast, then slowly") {
    // injected at W: p_x = p_y = sqrt(E); frames [0, 10), [10, 20), [20, 40), ... up to 40960 T
    std::vector<double> times = {0};
    for (double t = 10; t <= 40960; t *= 2) times.push_back(t);
    const Scene s = awtest::scene_from(R"(
      [model]
      energy = 15
      [ensemble]
      trajectories = 256
      initial = "gaussian"
      gaussian = { sigma = [0.01, 0.01] }
      [integrator]
      step = 0.025
      [run]
      average = 10
      duration = 40960
      [observe]
      energy_error = { every = 10 }
    )",
        {awtest::set("ensemble.gaussian.mean", std::array<double, 2>{std::sqrt(15.0), std::sqrt(15.0)}),
         awtest::set("observe.frames.times", times)},
        "<figure 4, CI size>");
    const Result r = awtest::run_on("cpu", make_plan(s));
    const Vec3 w = direction(45, 0);
    std::vector<double> spread;  // |V/|V| - W|^2 * 2E per frame
    for (const auto& frame : r.frames) spread.push_back(2 * s.energy * direction_spread(frame, s.nside, w));
    for (std::size_t f = 0; f < spread.size(); ++f)
      std::printf("frame [%g, %g) T: spread %.3f\n", s.frame_times[f], s.frame_times[f + 1], spread[f]);
    REQUIRE(spread.size() == 13);
    // log-log slopes: frames [320, 640) -> [2560, 5120) (3 doublings), and the last doubling
    const double early = std::log2(spread[9] / spread[6]) / 3;
    const double late = std::log2(spread[12] / spread[11]);
    std::printf("slope early %.2f, late %.2f\n", early, late);
    CHECK(early > 0.8);
    CHECK(late < 0.7 * early);
    CHECK(spread[12] > 10 * spread[0]);
  }
}
