// Accuracy planning: the pilot's fit, the cheapest choice for a tolerance, and
// integrator.step = "auto" (the whole run then meets the tolerance).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "arnoldweb/accuracy.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

const char* kScene =
    "[model]\n"
    "energy = 15.0\n"
    "[ensemble]\n"
    "trajectories = 4000\n"
    "[integrator]\n"
    "step = \"auto\"\n"
    "tolerance = 1e-7\n"
    "[run]\n"
    "average = 10.0\n"
    "duration = 10.0\n"
    "[observe]\n"
    "velocity_map = false\n";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The stages a scene with step = "auto" goes through: resolve, then plan.
Plan auto_plan(const Scene& s) {
  auto cpu = open_backend("cpu");
  return make_plan(resolve_step(s, {}, *cpu));
}

}  // namespace

TEST_SUITE("core") {
  TEST_CASE("auto: the chosen method and step meet the tolerance on the whole ensemble") {
    const Plan p = auto_plan(awtest::scene_from(kScene));
    const AutoStep& a = p.scene.auto_step;
    REQUIRE(a.used);
    CHECK(a.method_chosen);  // integrator.method is not in the scene
    CHECK(a.tolerance == 1e-7);
    CHECK(a.method == p.method.name);
    CHECK(a.step == p.step);
    CHECK(p.scene.method == a.method);  // the scene as run holds the choice
    CHECK_FALSE(p.scene.step_auto);
    CHECK(a.pilot_device == "cpu");
    CHECK(a.pilot_max > 0);
    CHECK(a.pilot_max * a.safety <= a.tolerance);
    CHECK_FALSE(p.guard.warned());  // auto stays within the advised step
    CHECK(p.steps_per_segment * p.step == doctest::Approx(1.0));  // divides the 1 T samples
    const Result r = awtest::run_on("cpu", p);
    std::printf("auto, tolerance 1e-7 at E = 15: %s h = %.6g T (pilot max|dE| %.2e); 4000 trajectories x 10 T: "
                "max|dE| %.2e\n",
                a.method.c_str(), a.step, a.pilot_max, r.energy.max);
    CHECK(r.energy.max <= 1e-7);
    CHECK(r.energy.max > 1e-7 / 1000);  // and not needlessly accurate (expensive)
    // summary.json records the choice; its scene holds the step that ran
    const std::string json = summary_json(p, r);
    CHECK(contains(json, "\"auto_step\": {"));
    CHECK(contains(json, "\"method\": \"" + a.method + "\""));
    CHECK(contains(json, "\"pilot_device\": \"cpu\""));
    CHECK(contains(json, "\"tolerance\": 1e-07"));
  }

  TEST_CASE("auto: a method written in the scene is kept, only the step is chosen") {
    const Plan p = auto_plan(awtest::scene_from(kScene, {"integrator.method=forest-ruth"}));
    CHECK(p.scene.auto_step.used);
    CHECK_FALSE(p.scene.auto_step.method_chosen);
    CHECK(p.method.name == "forest-ruth");
    CHECK(p.scene.auto_step.pilot_max * p.scene.auto_step.safety <= 1e-7);
    // forest-ruth needs a smaller step than the cheapest method would
    CHECK(p.step < auto_plan(awtest::scene_from(kScene)).step);
  }

  TEST_CASE("planning is pure: make_plan refuses an unresolved \"auto\" step, naming the stage that resolves it") {
    CHECK_THROWS_WITH_AS(make_plan(awtest::scene_from(kScene)), doctest::Contains("resolve_step"), SceneError);
  }

  TEST_CASE("auto: an unreachable tolerance is refused at integrator.tolerance") {
    try {
      auto_plan(awtest::scene_from(kScene, {"integrator.precision=float", "integrator.method=yoshida6a"}));
      FAIL("float reached 1e-7");
    } catch (const SceneError& e) {
      INFO(e.what());
      CHECK(e.key() == "integrator.tolerance");
      CHECK(contains(e.what(), "float"));
      CHECK(contains(e.what(), "precision = \"double\""));
    }
  }

  TEST_CASE("accuracy report: the scene as written, the fits and the cheapest choice") {
    Scene s = awtest::scene_from(kScene, {"integrator.step=0.02", "integrator.method=yoshida6a"});
    auto cpu = open_backend("cpu");
    PilotOptions o;
    o.trajectories = 256;
    o.duration = 2;
    const AccuracyReport r = assess_accuracy(s, {}, *cpu, 1e-8, o);
    CHECK(r.pilot_trajectories == 256);
    CHECK(r.pilot_duration == 2);
    CHECK(r.pilot_every == 1);
    REQUIRE(r.fits.size() == methods().size());
    REQUIRE(r.as_written_measured);
    CHECK(r.as_written.method == "yoshida6a");
    CHECK(r.as_written.measured_max > 1e-8);  // h = 0.02 T misses 1e-8
    CHECK_FALSE(r.as_written.meets);
    CHECK(r.rate > 0);
    CHECK(r.scene_force_evaluations == doctest::Approx(4000.0 * 500 * 7));
    REQUIRE(r.found);
    CHECK(r.best.measured_max <= 1e-8 / r.safety);
    for (const AccuracyChoice& c : r.per_method)
      if (c.meets) CHECK(c.forces_per_t >= r.best.forces_per_t);
    for (const MethodFit& f : r.fits) {
      CAPTURE(f.method);
      // the pre-filter stops a method at h0/2 only where its best case loses
      REQUIRE(f.points.size() == (f.prefiltered ? 2u : 3u));
      if (f.prefiltered) CHECK(f.optimistic_forces_per_t > r.best.forces_per_t);
      // a pilot point is predicted as measured
      CHECK(f.predict_max(f.points[1].step) == doctest::Approx(f.points[1].max));
      // and the error falls with the step at about the nominal order
      if (!f.prefiltered && f.floor == 0 && f.points.back().max > 1e-12)
        CHECK(std::log(f.points[1].max / f.points[2].max) / std::log(2.0) > f.order - 1.5);
    }
  }

  TEST_CASE("accuracy pre-filter: the same choice with fewer pilot runs, at E = 15 and E = 400") {
    auto cpu = open_backend("cpu");
    for (const char* energy : {"model.energy=15", "model.energy=400"}) {
      CAPTURE(energy);
      const Scene s = awtest::scene_from(kScene, {energy});
      PilotOptions o;
      o.trajectories = 256;
      o.duration = 2;
      const AccuracyReport with = assess_accuracy(s, {}, *cpu, 1e-8, o);
      o.prefilter = false;
      const AccuracyReport without = assess_accuracy(s, {}, *cpu, 1e-8, o);
      REQUIRE(with.found);
      REQUIRE(without.found);
      CHECK(with.best.method == without.best.method);
      CHECK(with.best.step == without.best.step);
      int skipped = 0;
      for (const MethodFit& f : with.fits) skipped += f.prefiltered ? 1 : 0;
      for (const MethodFit& f : without.fits) CHECK_FALSE(f.prefiltered);
      std::printf("pre-filter (%s, 1e-8): %s at T/%.0f; h0/4 skipped for %d of %zu methods; pilot %.2f s against "
                  "%.2f s\n",
                  energy, with.best.method.c_str(), 1 / with.best.step, skipped, with.fits.size(), with.pilot_seconds,
                  without.pilot_seconds);
      CHECK(skipped >= static_cast<int>(with.fits.size()) / 2);  // most methods are clearly dominated
    }
  }
}
