// The stage before planning (inputs.hpp) and a planner that reads nothing
// (plan.hpp): a scene's state file is read by read_plan_inputs, never by
// make_plan; the plan takes the states' real speeds for the step-size guard
// (issue 37, item 10); whether the pictures plugin opens is an input too.
#include <doctest/doctest.h>
#include <hdf5.h>

#include <cmath>
#include <string>
#include <vector>

#include "arnoldweb/accuracy.hpp"
#include "arnoldweb/inputs.hpp"
#include "arnoldweb/job.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

constexpr double kTwoPi = 6.283185307179586476925;
constexpr double kEnergy = 0.5, kEpsilon = 0.01;

// A state file of FGL states at energy kEnergy (docs/outputs.md, "State files"): angles
// spread over the torus, actions I1, I2 in [-reach, reach] plus one state at I1 = fastest
// (0: none); I3 makes each state's H = I1^2/2 + I2^2/2 + I3 + eps / D equal kEnergy.
std::string fgl_state_file(const std::string& path, double reach, double fastest = 0) {
  const int n = 64;
  std::vector<double> u(3 * n), p(3 * n);
  for (int i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) u[3 * i + c] = std::fmod(0.37 * (i + 1) * (c + 1.3), 1.0) - 0.5;
    const double i1 = i == 0 && fastest != 0 ? fastest : reach * std::sin(1.7 * i);
    const double i2 = reach * std::cos(2.3 * i);
    double d = 4;
    for (int c = 0; c < 3; ++c) d += std::cos(kTwoPi * u[3 * i + c]);
    p[3 * i] = i1;
    p[3 * i + 1] = i2;
    p[3 * i + 2] = kEnergy - i1 * i1 / 2 - i2 * i2 / 2 - kEpsilon / d;
  }
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  REQUIRE(file >= 0);
  const hsize_t dims[2] = {static_cast<hsize_t>(n), 3};
  for (const auto& [name, values] : {std::make_pair("position_turns", &u), std::make_pair("momentum", &p)}) {
    const hid_t space = H5Screate_simple(2, dims, nullptr);
    const hid_t set = H5Dcreate2(file, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    REQUIRE(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values->data()) >= 0);
    H5Dclose(set);
    H5Sclose(space);
  }
  H5Fclose(file);
  return path;
}

// FGL at E = 0.5 from the states of `file` ("": none named), a step of 0.02 T.
Scene fgl_scene(const std::string& file, const std::vector<std::string>& sets = {}) {
  std::vector<std::string> all = sets;
  if (!file.empty()) all.push_back(awtest::set("ensemble.file", file));
  return awtest::scene_from(
      "[model]\nkind = \"fgl\"\nepsilon = 0.01\nenergy = 0.5\n[ensemble]\ninitial = \"file\"\n"
      "[integrator]\nmethod = \"saba3\"\nstep = 0.02\n[run]\naverage = 1.0\nduration = 1.0\n"
      "[observe]\nvelocity_map = false\n[output]\nimages = false\n",
      all, "<plan-inputs>");
}

Plan plan_with_inputs(const Scene& scene) { return make_plan(scene, read_plan_inputs(scene)); }

}  // namespace

TEST_SUITE("plan") {
  TEST_CASE("a scene's state file is read before planning, by read_plan_inputs; make_plan reads nothing") {
    const std::string file = fgl_state_file(awtest::temp_dir("plan-inputs") + "/slow.h5", 0.3);
    const Scene scene = fgl_scene(file);
    const PlanInputs inputs = read_plan_inputs(scene);
    REQUIRE(inputs.state_files.count(file) == 1);
    CHECK(inputs.state_files.at(file)->count == 64);
    CHECK(inputs.states_for(scene).get() == inputs.state_files.at(file).get());
    const Plan planned = make_plan(scene, inputs);
    CHECK(planned.states.get() == inputs.state_files.at(file).get());  // the states read, not a copy
    CHECK(planned.scene.trajectories == 64);
    // without the inputs the plan has no states (nor their speeds: the guard is let be), and a
    // job of it is refused naming the stage
    const Scene unguarded = fgl_scene(file, {"integrator.allow_unsafe_step=true"});
    CHECK_FALSE(make_plan(unguarded).states.get());
    CHECK_THROWS_WITH_AS(plan_job(unguarded), doctest::Contains("read_plan_inputs"), SceneError);
    CHECK(plan_job(scene, inputs).main().states.get() == planned.states.get());
  }

  TEST_CASE("the step guard takes the speeds of the states a file gives (issue 37, item 10)") {
    const std::string dir = awtest::temp_dir("plan-inputs-guard");
    // slow states: |dX/dt| <= (0.3, 0.3, 1) plus what V's range adds (the shell at E = 0.5
    // holds far larger momenta: the estimate from its states refused this step)
    const Plan slow = plan_with_inputs(fgl_scene(fgl_state_file(dir + "/slow.h5", 0.3)));
    INFO(slow.guard.basis);
    CHECK(slow.guard.basis.find("64 states of") != std::string::npos);
    CHECK_FALSE(slow.guard.refused());
    CHECK_FALSE(slow.guard.warned());  // h omega < pi/2
    CHECK(slow.guard.omega < 3);  // |k.v| <= 2 x 0.43 + 1, libration 0.26
    CHECK(slow.guard.safe_step >= 0.02);  // the advice is at least the step it accepts
    CHECK(slow.guard.safe_step <= 0.2);
    CHECK(slow.warnings.empty());
    // the same scene drawn on the shell is planned as before: its own states' speeds
    const Plan shell = make_plan(fgl_scene("", {"ensemble.initial=\"shell\"", "integrator.allow_unsafe_step=true"}));
    CHECK(shell.guard.basis.find("initial states") != std::string::npos);
    CHECK(shell.guard.omega > 10 * slow.guard.omega);
    // a fast state in the file: still refused, naming the key and a step that is safe for it
    try {
      plan_with_inputs(fgl_scene(fgl_state_file(dir + "/fast.h5", 0.3, 30)));
      FAIL("a step unsafe for the file's fastest state was accepted");
    } catch (const SceneError& e) {
      const std::string why = e.what();
      INFO(why);
      CHECK(e.key() == "integrator.step");
      CHECK(why.find("64 states of") != std::string::npos);
      CHECK(why.find("use integrator.step = 0.005") != std::string::npos);
    }
  }

  TEST_CASE("integrator.step = \"auto\" from a state file: the pilot runs the first of its states") {
    const std::string file = fgl_state_file(awtest::temp_dir("plan-inputs-auto") + "/slow.h5", 0.3);
    // ensemble.trajectories written as the file's count: a pilot of all 64 states under the
    // pilot's 16 would be refused
    const Scene scene = fgl_scene(file, {"integrator.step=\"auto\"", "integrator.tolerance=1e-6",
                                         "ensemble.trajectories=64"});
    const PlanInputs inputs = read_plan_inputs(scene);
    PilotOptions o;
    o.trajectories = 16;
    o.duration = 1;
    o.methods = {"saba3"};
    auto cpu = open_backend("cpu");
    const Scene resolved = resolve_step(scene, inputs, *cpu, o);
    REQUIRE(resolved.auto_step.used);
    CHECK(resolved.auto_step.pilot_trajectories == 16);
    CHECK(resolved.auto_step.pilot_max > 0);
    const Plan p = make_plan(resolved, inputs);  // the run itself: every state
    CHECK(p.scene.trajectories == 64);
    CHECK(p.states->count == 64);
  }

  TEST_CASE("whether pictures can be drawn is an input: the plan warns where they cannot, and keeps it with_step") {
    const Scene with_images = awtest::scene_from("[output]\nimages = true\n");
    PlanInputs inputs;
    inputs.no_pictures = "the plugin is missing here";
    const Plan p = make_plan(with_images, inputs);
    REQUIRE(p.warnings.size() == 1);
    CHECK(p.warnings[0].key == "output.images");
    CHECK(p.warnings[0].text == "output.images: no pictures will be drawn: the plugin is missing here");
    CHECK(with_step(p, 0.005).warnings == p.warnings);
    CHECK(make_plan(with_images).warnings.empty());  // no input said so
    CHECK(make_plan(awtest::scene_from("[output]\nimages = false\n"), inputs).warnings.empty());
  }
}
