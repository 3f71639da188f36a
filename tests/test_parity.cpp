// Parity: every backend produces the same bits as the cpu reference, for any
// chunking. Runs on every device present (ctest entries parity.cpu,
// parity.opencl, parity.cuda).
#include <doctest/doctest.h>

#include <cstring>
#include <map>

#include "aw_params.h"
#include "support.hpp"

using namespace arnoldweb;

namespace {

Scene parity_scene(Precision precision, MathMode math) {
  Scene s;
  s.file = "<parity>";
  s.energy = 15;
  s.trajectories = 10000;
  s.seed = 2024;
  s.step = 0.01;
  s.average = 10;  // 1000 steps
  s.duration = 10;
  s.nside = 16;
  s.energy_error = true;
  s.energy_every = 1;
  s.initial_states = true;
  s.final_states = true;
  s.precision = precision;
  s.math = math;
  return s;
}

const Result& cpu_reference(Precision p) {
  static std::map<Precision, Result> cache;
  auto it = cache.find(p);
  if (it == cache.end()) it = cache.emplace(p, awtest::run_on("cpu", make_plan(parity_scene(p, MathMode::Portable)))).first;
  return it->second;
}

}  // namespace

TEST_SUITE("parity") {
  TEST_CASE("portable math: final states, map and counters match the cpu backend bit for bit") {
    for (Precision p : {Precision::Double, Precision::Float}) {
      const Result& ref = cpu_reference(p);
      REQUIRE(ref.final_r.size() == 10000 * AW_STATE_REALS);
      for (const auto& dev : awtest::devices_under_test()) {
        CAPTURE(dev.id);
        CAPTURE(to_string(p));
        const Result r = awtest::run_on(dev.id, make_plan(parity_scene(p, MathMode::Portable)));
        CHECK(awtest::first_difference(r.initial_r, ref.initial_r) == -1);
        const long d = awtest::first_difference(r.final_r, ref.final_r);
        CHECK_MESSAGE(d == -1, "first differing state value at trajectory " << d / AW_STATE_REALS);
        CHECK(awtest::first_difference(r.final_i, ref.final_i) == -1);
        CHECK(digest_map(r) == digest_map(ref));
        CHECK(r.binned == ref.binned);
        CHECK(r.flagged() == ref.flagged());
        CHECK(r.energy.max == ref.energy.max);
        CHECK(r.energy.log_hist == ref.energy.log_hist);
      }
    }
  }

  TEST_CASE("every method's table, double, portable math: final states match the cpu backend bit for bit") {
    // drift-first and kick-first tables, merged kicks, 1 to 15 stages: one segment boundary
    // (energy sample) in the middle, where kick-first methods do not merge
    for (const Method& m : methods()) {
      CAPTURE(m.name);
      Scene s = parity_scene(Precision::Double, MathMode::Portable);
      s.trajectories = 512;
      s.method = m.name;
      s.average = s.duration = 1;  // 100 steps
      s.energy_every = 0.5;
      s.velocity_map = false;
      s.initial_states = false;
      const Plan plan = make_plan(s);
      const Result ref = awtest::run_on("cpu", plan);
      REQUIRE(ref.final_r.size() == 512 * AW_STATE_REALS);
      for (const auto& dev : awtest::devices_under_test()) {
        if (dev.id == "cpu") continue;
        CAPTURE(dev.id);
        const Result r = awtest::run_on(dev.id, plan);
        const long d = awtest::first_difference(r.final_r, ref.final_r);
        CHECK_MESSAGE(d == -1, "first differing state value at trajectory " << d / AW_STATE_REALS);
        CHECK(awtest::first_difference(r.final_i, ref.final_i) == -1);
        CHECK(r.energy.max == ref.energy.max);
      }
    }
  }

  TEST_CASE("the map digest does not depend on the chunk size") {
    for (const auto& dev : awtest::devices_under_test()) {
      CAPTURE(dev.id);
      Scene s = parity_scene(Precision::Double, MathMode::Portable);
      s.initial_states = s.final_states = false;
      s.trajectories = 3000;
      std::string first;
      for (std::uint64_t chunk : {3000u, 1000u, 777u, 64u}) {
        s.chunk = chunk;
        const Result r = awtest::run_on(dev.id, make_plan(s));
        CHECK(r.chunks.size() == (3000 + chunk - 1) / chunk);
        if (first.empty()) first = digest_map(r);
        CHECK(digest_map(r) == first);
        CHECK(r.binned + r.flagged() == r.trajectories);
      }
    }
  }
}
