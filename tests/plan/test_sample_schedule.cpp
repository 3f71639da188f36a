// The sample schedule of a plan (lib/src/plan/schedule.cpp) as the key table
// documents it (issue 37): the shortest of the sample intervals divides
// run.average and is a multiple of integrator.step, and every other is a
// multiple of it, whichever effect has the shortest; the actions may be
// sampled more often than the energy.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "arnoldweb/errors.hpp"
#include "arnoldweb/plan.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

Plan plan_with(const std::vector<std::string>& sets) {
  return make_plan(awtest::scene_from(R"(
    [model]
    kind = "fgl"
    epsilon = 0.01
    energy = 0.5
    [ensemble]
    initial = "grid"
    grid = { kind = "plane", resolution = [4, 4], range1 = [0.29, 0.31], range2 = [0.29, 0.31], axes = [0, 1] }
    [integrator]
    method = "saba3"
    step = 0.02
    [run]
    average = 10.0
    duration = 10.0
    [observe]
    velocity_map = false
    energy_error = { every = 1.0 }
    diffusion = { every = 0.5, along = [1, 1, 0], across = [1, -1, 0], fit_from = 2 }
  )", sets));
}

std::string refusal(const std::vector<std::string>& sets) {
  try {
    plan_with(sets);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_SUITE("plan") {
  TEST_CASE("issue 37: the actions every 0.5 T under an energy interval of 1 T: the finer one is the segment") {
    const Plan p = plan_with({});
    CHECK(p.steps_per_segment == 25);     // 0.5 T of 0.02 T
    CHECK(p.segments_per_window == 20);   // 10 T
    CHECK(p.strides.at("observe.diffusion.every") == 1);
    CHECK(p.energy_stride == 2);          // the energy still every 1 T
    // the same schedule with the roles exchanged
    const Plan q = plan_with({"observe.energy_error.every=0.5", "observe.diffusion.every=1"});
    CHECK(q.steps_per_segment == 25);
    CHECK(q.energy_stride == 1);
    CHECK(q.strides.at("observe.diffusion.every") == 2);
  }

  TEST_CASE("issue 37: an interval that is no multiple of the shortest is refused, naming it and the shortest") {
    std::string e = refusal({"observe.diffusion.every=0.3", "run.duration=9", "run.average=9"});
    CAPTURE(e);
    CHECK(contains(e, "observe.energy_error.every: 1 T is not a multiple of the shortest sample interval, "
                      "observe.diffusion.every = 0.3 T"));
    e = refusal({"observe.diffusion.every=1.5", "run.duration=15", "run.average=15"});
    CAPTURE(e);
    CHECK(contains(e, "observe.diffusion.every: 1.5 T is not a multiple of the shortest sample interval, "
                      "observe.energy_error.every = 1 T"));
    e = refusal({"observe.diffusion.every=0.51"});
    CAPTURE(e);
    CHECK(contains(e, "observe.diffusion.every"));
  }

  TEST_CASE("issue 37: the key table states the rule the schedule applies") {
    const auto& keys = scene_keys();
    auto row = [&](const std::string& key) {
      return *std::find_if(keys.begin(), keys.end(), [&](const SceneKey& k) { return k.key == key; });
    };
    CHECK(contains(row("observe.diffusion.every").allowed, "a multiple of the shortest sample interval"));
    CHECK_FALSE(contains(row("observe.diffusion.every").allowed, "energy"));
    CHECK(contains(row("observe.frequencies.every").meaning, "every other is a multiple of it"));
    CHECK(contains(row("run.slice").meaning, "multiple of the shortest sample interval"));
  }

  TEST_CASE("issue 37: every direction is refused when checked, never normalised to zeros in the run") {
    for (const char* along : {"[1e200, 1e200, 0]", "[1e-170, 1e-170, 0]", "[0, 0, 0]"}) {
      CAPTURE(along);
      const std::string e = refusal({std::string("observe.diffusion.along=") + along});
      CHECK(contains(e, "observe.diffusion.along: must be an array [a, b, c] of floats, largest absolute component "
                        "from 1e-150 to 1e150"));
    }
    // at the ends of the range the directions are those written, across made orthogonal to along
    CHECK_NOTHROW(plan_with({"observe.diffusion.along=[1e150, 1e150, 0]", "observe.diffusion.across=[1e-150, -1e-150, 0]"}));
    CHECK(contains(refusal({"observe.diffusion.along=[1e150, 1e150, 0]", "observe.diffusion.across=[1e-150, 1e-150, 0]"}),
                   "is parallel to observe.diffusion.along"));
  }
}
