// Every OpenCL kernel variant on a tiny ensemble, for Oclgrind (the OpenCL
// simulator: out-of-bounds and invalid accesses, API misuse, data races,
// uninitialized values), and bit-for-bit parity of its results with the cpu
// backend: Oclgrind is a third OpenCL implementation besides PoCL and NVIDIA's.
//
// The suite is skipped unless asked for: it runs under the oclgrind wrapper,
// through tests/oclgrind/run.sh (ctest `oclgrind`, label oclgrind), which
// passes --no-skip and fails on any error Oclgrind logs. Under the wrapper
// the only OpenCL device is Oclgrind's simulator.
//
// A kernel variant is what the OpenCL compiler gets: the method's stage count
// and order (AW_STAGES, AW_KICK_FIRST), precision, math, the initial kind and
// the effect bits (AW_FEATURES), and the lanes per work-item (AW_LANES: 8 as
// on PoCL, 1 as on GPUs). Each method, initial kind and effect is run in both
// precisions and both lane widths; the full cross product (thousands of
// programs) would add nothing the kernels can tell apart, since each define
// selects its own code independently of the others.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "aw_params.h"
#include "plan/plan_params.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

// 21 trajectories in chunks of 13: lanes and work-groups only partly filled,
// and a second launch that starts mid-range. Two windows of 3 steps.
Scene tiny(Precision p) {
  Scene s;
  s.file = "<oclgrind>";
  s.energy = 15;
  s.trajectories = 21;
  s.chunk = 13;
  s.seed = 4242;
  s.step = 0.02;
  s.average = 0.06;
  s.duration = 0.12;
  s.energy_every = 0.02;
  s.nside = 4;
  s.initial_states = true;
  s.final_states = true;
  s.precision = p;
  return s;
}

struct Variant {
  std::string name;
  std::function<void(Scene&)> scene;          // changes to the tiny scene
  std::function<void(Plan&)> plan = nullptr;  // test hooks set on the plan
  bool bitwise = true;                        // portable math: the cpu backend's bits
};

std::vector<Variant> variants() {
  std::vector<Variant> v;
  for (const Method& m : methods())
    v.push_back({"method " + m.name, [name = m.name](Scene& s) { s.method = name; }});
  v.push_back({"initial cap", [](Scene& s) {
                 s.initial = "cap";
                 s.cap_center = {30, 20};
                 s.cap_radius = 4;
               }});
  v.push_back({"initial box", [](Scene& s) {
                 s.initial = "box";
                 s.box_lon = {100, 130};
                 s.box_lat = {-60, -50};
               }});
  v.push_back({"initial gaussian", [](Scene& s) {
                 s.initial = "gaussian";
                 s.gaussian_mean = {std::sqrt(15.0), std::sqrt(15.0)};
                 s.gaussian_sigma = {0.05, 0.05};
               }});
  v.push_back({"map only", [](Scene& s) {
                 s.energy_error = false;
                 s.initial_states = s.final_states = false;
               }});
  v.push_back({"energy error only", [](Scene& s) {
                 s.velocity_map = false;
                 s.initial_states = s.final_states = false;
               }});
  v.push_back({"final states only", [](Scene& s) {
                 s.velocity_map = false;
                 s.energy_error = false;
                 s.initial_states = false;
               }});
  v.push_back({"energy limit", [](Scene& s) { s.max_energy_error = 1e-9; }});
  v.push_back({"zoom", [](Scene& s) {
                 s.initial = "cap";
                 s.cap_center = {45, 0};
                 s.cap_radius = 10;
                 s.zoom = true;
                 s.zoom_center = {45, 0};
                 s.zoom_width = 20;
                 s.zoom_resolution = 8;
               }});
  v.push_back({"confine", [](Scene& s) {
                 s.initial = "cap";
                 s.cap_center = {45, 0};
                 s.cap_radius = 3;
                 s.confine = true;
                 s.confine_center = {45, 0};
                 s.confine_width = 4;
               }});
  v.push_back({"frames", [](Scene& s) { s.frame_times = {0, 0.06, 0.12}; }});
  v.push_back({"every effect", [](Scene& s) {
                 s.initial = "gaussian";
                 s.gaussian_mean = {std::sqrt(15.0), std::sqrt(15.0)};
                 s.gaussian_sigma = {0.05, 0.05};
                 s.zoom = true;
                 s.zoom_center = {45, 0};
                 s.zoom_width = 30;
                 s.zoom_resolution = 8;
                 s.confine = true;
                 s.confine_center = {45, 0};
                 s.confine_width = 40;
                 s.frame_times = {0, 0.06, 0.12};
                 s.max_energy_error = 1e-6;
               }});
  v.push_back({"test hook: injected NaN", [](Scene&) {},
               [](Plan& p) {
                 p.kernel.features |= AW_F_TEST_INJECT;
                 arnoldweb::detail::KernelParams& kp = arnoldweb::detail::edit_params(p);
                 kp.reals.inject_value = std::nan("");
                 kp.ints.inject_index = 17;
               }});
  v.push_back({"test hook: time reversal", [](Scene&) {},
               [](Plan& p) { p.kernel.features |= AW_F_REVERSE; }});
  // chaos indicators (docs/indicators.md): the tangent step with merged kicks,
  // and drift-first with MEGNO's extra Hessian, on a grid of directions
  v.push_back({"indicators", [](Scene& s) {
                 s.switches = {"observe.fli", "observe.lyapunov", "observe.megno"};
               }});
  v.push_back({"indicators on a grid, drift-first", [](Scene& s) {
                 s.method = "pefrl";
                 s.initial = "grid";
                 s.grid_kind = "lonlat";
                 s.grid_resolution = {7, 3};
                 s.switches.insert("observe.fli");
                 s.switches.insert("observe.megno");
               }});
  // frequency analysis (the sampling, the analysis kernel) and the actions' samples
  v.push_back({"frequencies and diffusion", [](Scene& s) {
                 s.duration = s.average = 0.64;
                 s.output_values["observe.frequencies"] = {1};
                 s.output_values["observe.frequencies.samples"] = {16};
                 s.output_values["observe.frequencies.every"] = {0.02};
                 s.output_values["observe.diffusion"] = {1};
                 s.output_values["observe.diffusion.every"] = {0.04};
               }});
  // the actions averaged over each sample's span, in time slices (the running sum starts again in each slice)
  v.push_back({"diffusion averaged, in time slices", [](Scene& s) {
                 s.duration = s.average = 0.64;
                 s.output_values = {{"observe.diffusion", {1}},
                                    {"observe.diffusion.every", {0.08}},
                                    {"observe.diffusion.average", {0.08}},
                                    {"observe.diffusion.average_every", {0.02}}};
                 s.slice = 0.16;
               }});
  // picked trajectories (observe.trajectories): their samples in the histogram buffer, two words a value,
  // one of them in the second chunk, in time slices
  v.push_back({"picked trajectories, in time slices", [](Scene& s) {
                 s.output_values["observe.trajectories.ids"] = {2, 12, 20};
                 s.output_values["observe.trajectories.every"] = {0.04};
                 s.slice = 0.04;
               }});
  v.push_back({"native math", [](Scene& s) { s.math = MathMode::Native; }, nullptr, false});
  return v;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Runs the variants on the Oclgrind device; `keep` selects which.
void run_variants(const std::function<bool(const Plan&)>& keep) {
  const auto& devs = awtest::devices_under_test();
  REQUIRE_MESSAGE(devs.size() == 1, "run this suite under the oclgrind wrapper (tests/oclgrind/run.sh)");
  const DeviceInfo& dev = devs.front();
  REQUIRE_MESSAGE(dev.name.find("Oclgrind") != std::string::npos,
                  dev.id << " is " << dev.name << ", not Oclgrind's simulator");
  int ran = 0;
  // eight lanes (a CPU's), one lane, and one lane with the frequency analysis by
  // teams of work-items (a GPU's: ARNOLDWEB_OPENCL_TEAMS, aw_naff.h "teams")
  struct Mode {
    int lanes;
    bool teams;
  };
  for (const Mode mode : {Mode{8, false}, Mode{1, false}, Mode{1, true}}) {
    const int lanes = mode.lanes;
    ::setenv("ARNOLDWEB_OPENCL_LANES", std::to_string(lanes).c_str(), 1);
    ::setenv("ARNOLDWEB_OPENCL_TEAMS", mode.teams ? "1" : "0", 1);
    for (const Variant& variant : variants()) {
      for (const Precision precision : {Precision::Double, Precision::Float}) {
        Scene s = tiny(precision);
        variant.scene(s);
        Plan plan = make_plan(s);
        if (variant.plan) variant.plan(plan);
        if (!keep(plan) || (mode.teams && !(plan.kernel.features & AW_F_FREQUENCIES))) continue;
        CAPTURE(variant.name);
        CAPTURE(mode.teams);
        CAPTURE(to_string(precision));
        CAPTURE(lanes);
        const Result r = awtest::run_on(dev.id, plan);
        ++ran;
        REQUIRE(r.kernel.find("-DAW_LANES=" + std::to_string(lanes)) != std::string::npos);
        CHECK((r.kernel.find("-DAW_NAFF_TEAM_PARALLEL=1") != std::string::npos) == mode.teams);
        CHECK(r.completed == s.trajectories);
        CHECK(r.binned + r.flagged() + r.left_region == r.trajectories);
        if (!variant.bitwise) continue;
        const Result ref = awtest::run_on("cpu", plan);
        CHECK(awtest::first_difference(r.reals("initial_states"), ref.reals("initial_states")) == -1);
        const long d = awtest::first_difference(r.reals("final_states"), ref.reals("final_states"));
        CHECK_MESSAGE(d == -1, "first differing state value at trajectory " << d / AW_STATE_REALS);
        CHECK(r.ints("final_states") == ref.ints("final_states"));
        CHECK(r.map == ref.map);
        CHECK(r.frames == ref.frames);
        CHECK(r.zoom == ref.zoom);
        CHECK(r.binned == ref.binned);
        CHECK(r.flagged_nonfinite == ref.flagged_nonfinite);
        CHECK(r.flagged_energy == ref.flagged_energy);
        CHECK(r.flagged_initial == ref.flagged_initial);
        CHECK(r.left_region == ref.left_region);
        CHECK(same_bits(r.energy.max, ref.energy.max));
        CHECK(r.energy.log_hist == ref.energy.log_hist);
        CHECK(awtest::first_difference(r.reals("indicators"), ref.reals("indicators")) == -1);
        CHECK(awtest::first_difference(r.reals("frequencies"), ref.reals("frequencies")) == -1);
        CHECK(awtest::first_difference(r.reals("actions"), ref.reals("actions")) == -1);
        CHECK(awtest::first_difference(r.reals("trajectories"), ref.reals("trajectories")) == -1);
        CHECK(r.ints("trajectories") == ref.ints("trajectories"));
        if (plan.kernel.features & AW_F_TEST_INJECT) CHECK(r.flagged_nonfinite == 1);
      }
    }
  }
  ::unsetenv("ARNOLDWEB_OPENCL_LANES");
  ::unsetenv("ARNOLDWEB_OPENCL_TEAMS");
  MESSAGE(ran << " kernel runs on " << dev.name);
  CHECK(ran > 0);
}

}  // namespace

TEST_SUITE("oclgrind" * doctest::skip()) {
  TEST_CASE("every kernel variant: no Oclgrind error, and the cpu backend's bits") {
    run_variants([](const Plan&) { return true; });
  }

  // Oclgrind 21.10's uninitialized-value plugin stops with an internal error
  // ("Work item needed to access private memory!") at frexp() with a private
  // pointer, which the energy-error histogram uses (aw_energy_bin); the
  // run.sh pass with --uninitialized takes the variants without it.
  TEST_CASE("kernel variants without energy tracking, for --uninitialized") {
    run_variants([](const Plan& p) { return (p.kernel.features & AW_F_ENERGY) == 0; });
  }
}
