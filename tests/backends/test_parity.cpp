// Parity: every backend produces the same bits, for any chunking. The
// reference is the scalar core (tests/support/scalar_core.hpp): the device
// core compiled into this test binary without vectors, run one trajectory at a
// time on one thread, counts folded by the test, so that the cpu backend (the
// same source vectorised, 8 or 16 lanes over OpenMP blocks) is checked against
// something other than itself. Runs on every device present (ctest entries
// parity.cpu, parity.opencl, parity.cuda).
#include <doctest/doctest.h>

#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "aw_params.h"
#include "physics/model_table.hpp"
#include "scalar_core.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

// 10000 trajectories x 1000 steps, every output; `sets` change it.
Scene parity_scene(Precision precision, MathMode math, const std::vector<std::string>& sets = {}) {
  std::vector<std::string> all = {awtest::set("integrator.precision", to_string(precision)),
                                  awtest::set("integrator.math", to_string(math))};
  all.insert(all.end(), sets.begin(), sets.end());
  return awtest::scene_from(R"(
    [model]
    energy = 15
    [ensemble]
    trajectories = 10000
    seed = 2024
    [integrator]
    step = 0.01
    [run]
    average = 10  # 1000 steps
    duration = 10
    [observe]
    velocity_map = { nside = 16 }
    energy_error = { every = 1 }
    initial_states = true
    final_states = true
    trajectories = { ids = [0, 17, 511], every = 1 }  # within the smallest ensemble and duration below
  )", all, "<parity>");
}

const Result& scalar_reference(Precision p) {
  static std::map<Precision, Result> cache;
  auto it = cache.find(p);
  if (it == cache.end())
    it = cache.emplace(p, awtest::run_scalar_core(make_plan(parity_scene(p, MathMode::Portable)))).first;
  return it->second;
}

}  // namespace

TEST_SUITE("parity") {
  TEST_CASE("portable math: states, map and counters of every device, cpu included, match the scalar core bit for bit") {
    for (Precision p : {Precision::Double, Precision::Float}) {
      const Result& ref = scalar_reference(p);
      REQUIRE(ref.reals("final_states").size() == 10000 * AW_STATE_REALS);
      REQUIRE(ref.reals("trajectories").size() == 3 * 11 * AW_PICK_REALS);
      REQUIRE(ref.binned > 9000);  // a reference that binned nothing would prove little
      REQUIRE_FALSE(awtest::devices_under_test().empty());
      for (const auto& dev : awtest::devices_under_test()) {
        CAPTURE(dev.id);
        CAPTURE(to_string(p));
        const Result r = awtest::run_on(dev.id, make_plan(parity_scene(p, MathMode::Portable)));
        CHECK(awtest::first_difference(r.reals("initial_states"), ref.reals("initial_states")) == -1);
        const long d = awtest::first_difference(r.reals("final_states"), ref.reals("final_states"));
        CHECK_MESSAGE(d == -1, "first differing state value at trajectory " << d / AW_STATE_REALS);
        CHECK(awtest::first_difference(r.ints("final_states"), ref.ints("final_states")) == -1);
        CHECK(awtest::first_difference(r.reals("trajectories"), ref.reals("trajectories")) == -1);
        CHECK(awtest::first_difference(r.ints("trajectories"), ref.ints("trajectories")) == -1);
        CHECK(digest_map(r) == digest_map(ref));
        CHECK(r.binned == ref.binned);
        CHECK(r.flagged() == ref.flagged());
        CHECK(r.energy.max == ref.energy.max);
        CHECK(r.energy.log_hist == ref.energy.log_hist);
      }
    }
  }

  TEST_CASE("every method's table, double, portable math: final states of every device match the scalar core") {
    // drift-first and kick-first tables, merged kicks, 1 to 15 stages: one segment boundary
    // (energy sample) in the middle, where kick-first methods do not merge
    for (const Method& m : methods()) {
      CAPTURE(m.name);
      const Scene s = parity_scene(Precision::Double, MathMode::Portable,
                                   {"ensemble.trajectories=512", awtest::set("integrator.method", m.name),
                                    "run.average=1", "run.duration=1",  // 100 steps
                                    "observe.energy_error.every=0.5", "observe.velocity_map=false",
                                    "observe.initial_states=false"});
      const Plan plan = make_plan(s);
      const Result ref = awtest::run_scalar_core(plan);
      REQUIRE(ref.reals("final_states").size() == 512 * AW_STATE_REALS);
      REQUIRE_FALSE(awtest::devices_under_test().empty());
      for (const auto& dev : awtest::devices_under_test()) {
        CAPTURE(dev.id);
        const Result r = awtest::run_on(dev.id, plan);
        const long d = awtest::first_difference(r.reals("final_states"), ref.reals("final_states"));
        CHECK_MESSAGE(d == -1, "first differing state value at trajectory " << d / AW_STATE_REALS);
        CHECK(awtest::first_difference(r.ints("final_states"), ref.ints("final_states")) == -1);
        CHECK(r.energy.max == ref.energy.max);
      }
    }
  }

  TEST_CASE("every model of the table (portable math, double and float): every device matches the cpu backend bit for bit") {
    // the scalar core holds seibert2011 only: the models are checked against the cpu backend
    // (itself checked against the scalar core above): every built-in model of the table at its
    // defaults on the shell (a new model is checked as it is added), then the kinetic forms and
    // initial kinds of the models that have them, on a box and a cap
    std::vector<std::vector<std::string>> models;
    for (const detail::ModelDescriptor& m : detail::models())
      if (m.host)  // a built-in (the expression kind is a scene's own row: tests/backends/test_expression_*.cpp)
        models.push_back({awtest::set("model.kind", m.name), "model.energy=2", "integrator.allow_unsafe_step=true"});
    const std::vector<std::vector<std::string>> variants = {
        {"model.kind=\"fgl\"", "model.epsilon=0.04", "model.energy=0.5", "ensemble.initial=\"box\"",
         "ensemble.box={ lon = [0, 360], lat = [-42, 90] }"},
        {"model.kind=\"fgl\"", "model.epsilon=0.01", "model.energy=-0.2", "ensemble.initial=\"cap\"",
         "ensemble.cap={ center = [45, -60], radius = 20 }"},
        {"model.kind=\"fourier\"", "model.energy=3",
         "model.harmonics=[[1, 0, 0, 0.7, 0.3], [2, -1, 3, -0.2, 1.1], [0, 1, 1, 0.45, -2]]",
         "model.kinetic_a=[1, 0.5, 0]", "model.kinetic_b=[0, 0.25, 1]", "ensemble.initial=\"box\"",
         "ensemble.box={ lon = [0, 360], lat = [-30, 30] }"},  // away from z, where p_z would be unbounded
    };
    models.insert(models.end(), variants.begin(), variants.end());
    for (const auto& model : models) {
      for (Precision p : {Precision::Double, Precision::Float}) {
        std::vector<std::string> sets = {"ensemble.trajectories=2000", "run.average=2", "run.duration=2",
                                         "observe.energy_error.every=1"};
        sets.insert(sets.end(), model.begin(), model.end());
        const Plan plan = make_plan(parity_scene(p, MathMode::Portable, sets));
        CAPTURE(model.front());
        CAPTURE(model.back());
        CAPTURE(to_string(p));
        const Result ref = awtest::run_on("cpu", plan);
        REQUIRE(ref.reals("final_states").size() == 2000 * AW_STATE_REALS);
        REQUIRE(ref.binned > 1900);
        for (const auto& dev : awtest::devices_under_test()) {
          CAPTURE(dev.id);
          const Result r = awtest::run_on(dev.id, plan);
          CHECK(awtest::first_difference(r.reals("initial_states"), ref.reals("initial_states")) == -1);
          const long d = awtest::first_difference(r.reals("final_states"), ref.reals("final_states"));
          CHECK_MESSAGE(d == -1, "first differing state value at trajectory " << d / AW_STATE_REALS);
          CHECK(awtest::first_difference(r.ints("final_states"), ref.ints("final_states")) == -1);
          CHECK(digest_map(r) == digest_map(ref));
          CHECK(r.energy.max == ref.energy.max);
        }
      }
    }
  }

  TEST_CASE("the map digest does not depend on the chunk size") {
    for (const auto& dev : awtest::devices_under_test()) {
      CAPTURE(dev.id);
      std::string first;
      for (std::uint64_t chunk : {3000u, 1000u, 777u, 64u}) {
        const Scene s = parity_scene(Precision::Double, MathMode::Portable,
                                     {"observe.initial_states=false", "observe.final_states=false",
                                      "ensemble.trajectories=3000", awtest::set("ensemble.chunk", chunk)});
        const Result r = awtest::run_on(dev.id, make_plan(s));
        CHECK(r.chunks.size() == (3000 + chunk - 1) / chunk);
        if (first.empty()) first = digest_map(r);
        CHECK(digest_map(r) == first);
        CHECK(r.binned + r.flagged() == r.trajectories);
      }
    }
  }
}
