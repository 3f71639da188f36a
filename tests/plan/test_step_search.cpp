// The step search as planning (plan/step_search.hpp): it plans the pilot's
// ensembles and decides from what `measure` says of them, so it can be checked
// with errors given by a formula, without a device: max|dE| = C h^p per method.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "plan/step_search.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

struct PowerLaw {
  double c;
  int p;
};

// A pilot's error as a power law of its step (in T), per method; every plan it is asked about is kept.
struct FormulaPilot {
  std::map<std::string, PowerLaw> laws;
  std::vector<Plan> asked;
  detail::PilotRun operator()(const Plan& pilot) {
    asked.push_back(pilot);
    const PowerLaw& l = laws.at(pilot.method.name);
    const double e = l.c * std::pow(pilot.step, l.p);
    return {e, e / 4, 1e9, 1.0};
  }
};

const std::vector<std::string> kAuto = {"integrator.step=\"auto\"", "integrator.tolerance=1e-7",
                                        "ensemble.trajectories=100000", "run.average=10", "run.duration=10",
                                        "observe.velocity_map=false"};

// The cheapest admissible step of a law: the largest every/n, n >= n0 (the guard's
// largest step), with C h^p <= target.
double cheapest(const PowerLaw& l, double every, std::int64_t n0, double target) {
  std::int64_t n = n0;
  while (l.c * std::pow(every / static_cast<double>(n), l.p) > target) ++n;
  return every / static_cast<double>(n);
}

std::int64_t ladder_divisor(const MethodFit& f, double every) {
  return static_cast<std::int64_t>(std::llround(every / f.points.at(0).step));
}

}  // namespace

TEST_SUITE("plan") {
  TEST_CASE("step search: with errors C h^p it picks each method's largest admissible step and the cheapest method") {
    const Scene s = awtest::scene_from("", kAuto);
    FormulaPilot pilot;
    pilot.laws = {{"yoshida6a", {3e3, 6}}, {"aba864", {40.0, 6}}, {"chin4a", {5.0, 4}}};
    PilotOptions o;
    o.methods = {"yoshida6a", "aba864", "chin4a"};
    const AccuracyReport r =
        detail::search_step(s, {}, 1e-7, o, 1024, [&pilot](const Plan& p) { return pilot(p); });
    const double target = 1e-7 / o.safety;
    REQUIRE(r.found);
    REQUIRE(r.per_method.size() == 3);
    REQUIRE(r.fits.size() == 3);
    const double every = r.pilot_every;
    double best_cost = 1e300;
    std::string best_method;
    for (std::size_t i = 0; i < 3; ++i) {
      const MethodFit& f = r.fits[i];
      const AccuracyChoice& c = r.per_method[i];
      CAPTURE(f.method);
      REQUIRE(c.method == f.method);
      CHECK(f.order_fit == doctest::Approx(pilot.laws.at(f.method).p).epsilon(1e-9));  // the fit finds the law
      const double h = cheapest(pilot.laws.at(f.method), every, ladder_divisor(f, every), target);
      CHECK(c.meets);
      CHECK(c.step == doctest::Approx(h).epsilon(1e-12));
      CHECK(c.predicted_max <= target);
      if (c.forces_per_t < best_cost) best_cost = c.forces_per_t, best_method = c.method;
    }
    CHECK(r.best.method == best_method);
    // the choice was run on the pilot before it was taken, and met the target there
    CHECK(r.best.measured_max == doctest::Approx(pilot.laws.at(best_method).c * std::pow(r.best.step, 6)));
    CHECK(r.best.measured_max <= target);
  }

  TEST_CASE("step search: the pilot's plans are the scene's first trajectories, |dE| sampled, nothing else observed") {
    const Scene s = awtest::scene_from("", kAuto);
    FormulaPilot pilot;
    pilot.laws = {{"aba864", {40.0, 6}}};
    PilotOptions o;
    o.methods = {"aba864"};
    o.trajectories = 300;
    const AccuracyReport r =
        detail::search_step(s, {}, 1e-7, o, 1024, [&pilot](const Plan& p) { return pilot(p); });
    REQUIRE(!pilot.asked.empty());
    CHECK(r.pilot_trajectories == 300);
    for (const Plan& p : pilot.asked) {
      CHECK(p.scene.trajectories == 300);
      CHECK(p.scene.seed == s.seed);
      CHECK(p.scene.duration == r.pilot_duration);
      CHECK(p.scene.energy_error);
      CHECK(p.scene.energy_every == r.pilot_every);
      CHECK(!p.scene.velocity_map);
      CHECK(p.scene.method == "aba864");
    }
    // the ladder h0, h0/2, h0/4, then the choice checked: four runs
    CHECK(pilot.asked.size() == 4);
  }

  TEST_CASE("step search: a tolerance no method reaches is reported, not chosen") {
    const Scene s = awtest::scene_from("", kAuto);
    FormulaPilot pilot;
    pilot.laws = {{"aba864", {1e-3, 0}}};  // an error that does not fall with the step: round-off
    PilotOptions o;
    o.methods = {"aba864"};
    const AccuracyReport r =
        detail::search_step(s, {}, 1e-7, o, 1024, [&pilot](const Plan& p) { return pilot(p); });
    CHECK(!r.found);
    CHECK(r.why_not.find("no method reaches max|dE| <= 1e-07") != std::string::npos);
    CHECK(r.why_not.find("double precision") != std::string::npos);
  }

  TEST_CASE("step search: the scene as written is measured and its rate taken from the measure") {
    const Scene s = awtest::scene_from("", {"integrator.method=\"aba864\"", "integrator.step=0.05",
                                            "ensemble.trajectories=100000", "run.average=10", "run.duration=10",
                                            "observe.velocity_map=false"});
    FormulaPilot pilot;
    pilot.laws = {{"aba864", {40.0, 6}}};
    PilotOptions o;
    o.methods = {"aba864"};
    const AccuracyReport r =
        detail::search_step(s, {}, 1e-7, o, 1024, [&pilot](const Plan& p) { return pilot(p); });
    REQUIRE(r.as_written_measured);
    CHECK(r.as_written.step == 0.05);
    CHECK(r.as_written.measured_max == doctest::Approx(40.0 * std::pow(0.05, 6)));
    CHECK(r.rate == 1e9);
    CHECK(r.scene_seconds == doctest::Approx(r.scene_trajectory_steps / 1e9));
  }
}
