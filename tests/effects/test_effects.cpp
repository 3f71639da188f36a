// The effects a scene can ask for: initial caps, boxes and Gaussian momenta,
// region confinement, zoom histograms, time-series frames. Checked against
// independent host computations, and bit for bit across every device.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "aw_params.h"
#include "plan/plan_params.hpp"
#include "scalar_core.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

constexpr double kDeg = M_PI / 180;

// A small ensemble with its states recorded; `sets` add the effect under test.
Scene effects_scene(const std::vector<std::string>& sets = {}) {
  return awtest::scene_from(R"(
    [model]
    energy = 15
    [ensemble]
    trajectories = 3000
    seed = 77
    [integrator]
    step = 0.01
    [run]
    average = 2
    duration = 2
    [observe]
    velocity_map = { nside = 16 }
    energy_error = { every = 0.5 }
    initial_states = true
    final_states = true
  )", sets, "<effects>");
}

// p_x = p_y = sqrt(15): the injection point W of the paper's Figure 4
const std::string kMeanAtW =
    awtest::set("ensemble.gaussian.mean", std::array<double, 2>{std::sqrt(15.0), std::sqrt(15.0)});

Vec3 unit(double x, double y, double z) {
  const double n = std::sqrt(x * x + y * y + z * z);
  return {x / n, y / n, z / n};
}

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Vec3 momentum(const std::vector<double>& states, std::size_t t) {
  return {states[t * AW_STATE_REALS + 3], states[t * AW_STATE_REALS + 4], states[t * AW_STATE_REALS + 5]};
}

std::uint64_t total(const std::vector<std::uint64_t>& v) {
  return std::accumulate(v.begin(), v.end(), std::uint64_t{0});
}

}  // namespace

TEST_SUITE("math") {
  TEST_CASE("pixel centres map back to their own pixel") {
    for (int nside : {1, 2, 4, 32, 256}) {
      const std::uint64_t npix = 12ull * nside * nside;
      const std::uint64_t stride = std::max<std::uint64_t>(1, npix / 50000);
      long bad = 0;
      for (std::uint64_t p = 0; p < npix; p += stride) {
        const Vec3 v = pix2vec_ring(nside, p);
        CHECK(std::fabs(dot(v, v) - 1) < 1e-14);
        bad += vec2pix_ring(nside, v) != p;
      }
      CAPTURE(nside);
      CHECK(bad == 0);
    }
  }

  TEST_CASE("resonance lists: coprime, canonical, predicted ones included") {
    const auto all = resonances(2);
    CHECK(all.size() == 3 + 6 + 4 + 36);  // order 1: 13; order 2: 36 (coprime, up to sign)
    for (const auto& r : all) {
      CHECK(std::gcd(std::gcd(std::abs(r.m[0]), std::abs(r.m[1])), std::abs(r.m[2])) == 1);
      const int first = r.m[0] ? r.m[0] : r.m[1] ? r.m[1] : r.m[2];
      CHECK(first > 0);
    }
    const auto primary = primary_resonances();
    CHECK(primary.size() == 6);
    for (const auto& r : primary) CHECK((r.order == 1 || r.order == 2));
    CHECK(distance_to_circle(Resonance{{1, 0, 0}, 1}, direction(45, 0)) == doctest::Approx(M_PI / 4));
    CHECK(distance_to_circle(Resonance{{1, -1, 0}, 1}, direction(45, 0)) == doctest::Approx(0).epsilon(1e-15));
  }
}

TEST_SUITE("parity") {
  TEST_CASE("a cap, a box and Gaussian momenta give the initial states asked for") {
    for (const auto& dev : awtest::devices_under_test()) {
      CAPTURE(dev.id);
      std::vector<std::string> sets = {"ensemble.initial=\"cap\"", "ensemble.cap={ center = [30, 20], radius = 4 }"};
      Scene s = effects_scene(sets);
      Result r = awtest::run_on(dev.id, make_plan(s));
      const Vec3 c = direction(30, 20);
      double mean_cos = 0;
      for (std::size_t t = 0; t < s.trajectories; ++t) {
        const Vec3 p = momentum(r.reals("initial_states"), t);
        const double cosang = dot(unit(p[0], p[1], p[2]), c);
        CHECK(cosang >= std::cos(4 * kDeg) - 1e-12);
        mean_cos += cosang / static_cast<double>(s.trajectories);
      }
      // uniform in the cap: mean cos = (1 + cos r) / 2
      CHECK(mean_cos == doctest::Approx((1 + std::cos(4 * kDeg)) / 2).epsilon(2e-5));

      sets.insert(sets.end(), {"ensemble.initial=\"box\"", "ensemble.box={ lon = [100, 130], lat = [-60, -50] }"});
      s = effects_scene(sets);
      r = awtest::run_on(dev.id, make_plan(s));
      for (std::size_t t = 0; t < s.trajectories; ++t) {
        const Vec3 p = momentum(r.reals("initial_states"), t);
        const double lat = std::atan2(p[2], std::hypot(p[0], p[1])) / kDeg;
        const double lon = std::atan2(p[1], p[0]) / kDeg;
        CHECK(lat >= -60 - 1e-9);
        CHECK(lat <= -50 + 1e-9);
        CHECK(lon >= 100 - 1e-9);
        CHECK(lon <= 130 + 1e-9);
      }

      sets.insert(sets.end(), {"ensemble.initial=\"gaussian\"", kMeanAtW, "ensemble.gaussian.sigma=[0.01, 0.02]"});
      s = effects_scene(sets);
      r = awtest::run_on(dev.id, make_plan(s));
      CHECK(r.flagged_initial == 0);
      double mx = 0, my = 0, vx = 0, vy = 0;
      const double n = static_cast<double>(s.trajectories);
      for (std::size_t t = 0; t < s.trajectories; ++t) {
        const Vec3 p = momentum(r.reals("initial_states"), t);
        mx += p[0] / n;
        my += p[1] / n;
      }
      for (std::size_t t = 0; t < s.trajectories; ++t) {
        const Vec3 p = momentum(r.reals("initial_states"), t);
        vx += (p[0] - mx) * (p[0] - mx) / n;
        vy += (p[1] - my) * (p[1] - my) / n;
      }
      CHECK(std::fabs(mx - std::sqrt(15.0)) < 5 * 0.01 / std::sqrt(n));
      CHECK(std::fabs(my - std::sqrt(15.0)) < 5 * 0.02 / std::sqrt(n));
      CHECK(std::sqrt(vx) == doctest::Approx(0.01).epsilon(0.08));
      CHECK(std::sqrt(vy) == doctest::Approx(0.02).epsilon(0.08));
    }
  }

  TEST_CASE("the zoom histogram is the gnomonic binning of the averaged velocities") {
    for (const auto& dev : awtest::devices_under_test()) {
      CAPTURE(dev.id);
      const Scene s = effects_scene({"ensemble.initial=\"cap\"", "ensemble.cap={ center = [45, 0], radius = 10 }",
                                     "observe.zoom={ center = [45, 0], width = 20, resolution = 32 }"});
      const Plan plan = make_plan(s);
      const Result r = awtest::run_on(dev.id, plan);
      REQUIRE(r.zoom.size() == 32 * 32);
      // the same binning on the host, from the initial and final states
      std::vector<std::uint64_t> host(32 * 32, 0);
      const double* reg = &arnoldweb::detail::params(plan).reals.zoom.c[0];
      for (std::size_t t = 0; t < s.trajectories; ++t) {
        if (r.ints("final_states")[t * AW_STATE_INTS + 3] != AW_STATUS_OK) continue;
        double d[3];
        for (int k = 0; k < 3; ++k)
          d[k] = static_cast<double>(r.ints("final_states")[t * AW_STATE_INTS + k]) +
                 (r.reals("final_states")[t * AW_STATE_REALS + k] - r.reals("initial_states")[t * AW_STATE_REALS + k]);
        const double dc = d[0] * reg[0] + d[1] * reg[1] + d[2] * reg[2];
        const double gx = (d[0] * reg[3] + d[1] * reg[4] + d[2] * reg[5]) / dc;
        const double gy = (d[0] * reg[6] + d[1] * reg[7] + d[2] * reg[8]) / dc;
        if (dc <= 0 || std::fabs(gx) >= reg[9] || std::fabs(gy) >= reg[9]) continue;
        const int ix = std::min(31, static_cast<int>((gx / reg[9] + 1) * 0.5 * 32));
        const int iy = std::min(31, static_cast<int>((gy / reg[9] + 1) * 0.5 * 32));
        ++host[static_cast<std::size_t>(iy * 32 + ix)];
      }
      // equal up to rounding at bin edges (the kernel's fma order differs)
      std::uint64_t moved = 0;
      for (std::size_t b = 0; b < host.size(); ++b)
        moved += static_cast<std::uint64_t>(std::llabs(static_cast<long long>(host[b]) - static_cast<long long>(r.zoom[b])));
      CHECK(total(r.zoom) == total(host));
      CHECK(moved <= 2);
      CHECK(total(r.zoom) > s.trajectories / 2);
    }
  }

  TEST_CASE("a zoom without the velocity map counts the same (its histogram starts where the host put it)") {
    // the device placed the zoom after frames x 12 nside^2 pixels even when no map was planned:
    // past the end of the histogram buffer (valgrind: invalid reads in run_chunk; PoCL: a crash)
    for (const auto& dev : awtest::devices_under_test()) {
      CAPTURE(dev.id);
      const std::vector<std::string> zoom = {"ensemble.initial=\"cap\"",
                                             "ensemble.cap={ center = [45, 0], radius = 10 }",
                                             "observe.zoom={ center = [45, 0], width = 20, resolution = 32 }"};
      std::vector<std::string> without = zoom;
      without.push_back("observe.velocity_map=false");
      const Plan with_map = make_plan(effects_scene(zoom)), zoom_only = make_plan(effects_scene(without));
      REQUIRE(zoom_only.npix == 0);
      CHECK(zoom_only.hist_size == 32u * 32u);
      const Result a = awtest::run_on(dev.id, with_map), b = awtest::run_on(dev.id, zoom_only);
      REQUIRE(total(a.zoom) > 0);
      CHECK(b.zoom == a.zoom);
    }
  }

  TEST_CASE("region confinement bins only trajectories that stay inside") {
    for (const auto& dev : awtest::devices_under_test()) {
      CAPTURE(dev.id);
      // about W: the chaotic intersection of primary resonances
      const Scene s = effects_scene({"ensemble.initial=\"cap\"", "ensemble.cap={ center = [45, 0], radius = 3 }",
                                     "observe.confine={ center = [45, 0], width = 6 }", "run.average=20",
                                     "run.duration=20"});
      const Plan plan = make_plan(s);
      const Result r = awtest::run_on(dev.id, plan);
      CHECK(r.left_region > 0);
      CHECK(r.binned > 0);
      CHECK(r.binned + r.flagged() + r.left_region == r.trajectories);
      CHECK(total(r.map) == r.binned);
      const double* reg = &arnoldweb::detail::params(plan).reals.confine.c[0];
      for (std::size_t t = 0; t < s.trajectories; ++t) {
        const auto st = r.ints("final_states")[t * AW_STATE_INTS + 3];
        CHECK((st == AW_STATUS_OK || st == AW_STATUS_LEFT_REGION));
        if (st != AW_STATUS_OK) continue;
        const Vec3 p = momentum(r.reals("final_states"), t);
        const double dc = p[0] * reg[0] + p[1] * reg[1] + p[2] * reg[2];
        CHECK(std::fabs(p[0] * reg[3] + p[1] * reg[4] + p[2] * reg[5]) <= reg[9] * dc);
        CHECK(std::fabs(p[0] * reg[6] + p[1] * reg[7] + p[2] * reg[8]) <= reg[9] * dc);
      }
    }
  }

  TEST_CASE("frames split the windows of a time series") {
    for (const auto& dev : awtest::devices_under_test()) {
      CAPTURE(dev.id);
      const Scene s = effects_scene({"ensemble.trajectories=500", "run.average=1", "run.duration=8",
                                     "observe.frames={ times = [0, 1, 2, 4, 8] }"});
      const Result r = awtest::run_on(dev.id, make_plan(s));
      REQUIRE(r.frames.size() == 4);
      const std::uint64_t windows[4] = {1, 1, 2, 4};
      std::uint64_t sum = 0;
      for (int f = 0; f < 4; ++f) {
        CHECK(total(r.frames[f]) == windows[f] * r.binned);
        sum += total(r.frames[f]);
      }
      CHECK(total(r.map) == sum);
    }
  }

  TEST_CASE("every effect together gives the bits of the scalar core on every device, cpu included") {
    for (Precision p : {Precision::Double, Precision::Float}) {
      const Scene s = effects_scene(
          {"ensemble.initial=\"gaussian\"", kMeanAtW, "ensemble.gaussian.sigma=[0.05, 0.05]",
           "observe.zoom={ center = [45, 0], width = 30, resolution = 64 }",
           "observe.confine={ center = [45, 0], width = 40 }", "run.average=1", "run.duration=4",
           "observe.frames={ times = [0, 2, 4] }",
           // float's rounding alone exceeds 1e-6 here: at 8e-6 most are flagged and some leave the region
           p == Precision::Double ? "observe.max_energy_error=1e-6" : "observe.max_energy_error=8e-6",
           awtest::set("integrator.precision", to_string(p))});
      const Plan plan = make_plan(s);
      // the reference: the core compiled in this test without vectors (tests/support/scalar_core.hpp)
      const Result ref = awtest::run_scalar_core(plan);
      CAPTURE(to_string(p));
      // every effect shows in it: frames, zoom counts, trajectories that left the region; in double most
      // are binned, in float most are flagged (its rounding alone nearly exceeds max_energy_error = 8e-6)
      REQUIRE(ref.frames.size() == 2);
      REQUIRE(total(ref.zoom) > 0);
      REQUIRE(ref.left_region > 0);
      REQUIRE(ref.binned + ref.flagged() + ref.left_region == s.trajectories);
      REQUIRE((p == Precision::Double ? ref.binned : ref.flagged_energy) > s.trajectories / 2);
      REQUIRE_FALSE(awtest::devices_under_test().empty());
      for (const auto& dev : awtest::devices_under_test()) {
        CAPTURE(dev.id);
        const Result r = awtest::run_on(dev.id, plan);
        CHECK(r.frames == ref.frames);
        CHECK(r.zoom == ref.zoom);
        CHECK(digest_map(r) == digest_map(ref));
        CHECK(digest_records(r, "initial_states") == digest_records(ref, "initial_states"));
        CHECK(digest_records(r, "final_states") == digest_records(ref, "final_states"));
        CHECK(r.left_region == ref.left_region);
        CHECK(r.flagged_energy == ref.flagged_energy);
        CHECK(r.binned == ref.binned);
        CHECK(r.energy.max == ref.energy.max);
      }
    }
  }
}
