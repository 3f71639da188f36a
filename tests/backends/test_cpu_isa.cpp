// The cpu backend's kernels are compiled for several instruction sets
// (cmake/ArnoldwebCpuKernels.cmake) and the best one the CPU supports is chosen
// at run time: every set this machine runs must give the same bits as every
// other, in each precision and math mode, for each model (ctest cpu.isa).
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "aw_params.h"
#include "backends/cpu/cpu_isa.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

// Sets ARNOLDWEB_CPU_ISA for the life of the object.
struct ForcedIsa {
  explicit ForcedIsa(const std::string& name) { setenv("ARNOLDWEB_CPU_ISA", name.c_str(), 1); }
  ~ForcedIsa() { unsetenv("ARNOLDWEB_CPU_ISA"); }
};

Scene isa_scene(const std::string& model, Precision p, MathMode m) {
  return awtest::scene_from(R"(
    [model]
    energy = 15
    [ensemble]
    trajectories = 3000
    seed = 99
    [integrator]
    step = 0.0025
    [run]
    average = 1
    duration = 1
    [observe]
    velocity_map = { nside = 8 }
    energy_error = { every = 1 }
    final_states = true
  )", {awtest::set("model.kind", model), awtest::set("integrator.precision", to_string(p)),
       awtest::set("integrator.math", to_string(m))}, "<cpu-isa>");
}

}  // namespace

TEST_SUITE("cpu-isa") {
  TEST_CASE("the best set is chosen unless ARNOLDWEB_CPU_ISA names one; a set not built or not supported is a DeviceError") {
    const std::vector<std::string> supported = detail::cpu_isas_supported();
    REQUIRE_FALSE(supported.empty());
    CHECK(std::string(detail::cpu_isa_selected().name) == supported.front());
    {
      ForcedIsa f(supported.back());
      CHECK(std::string(detail::cpu_isa_selected().name) == supported.back());
    }
    {
      ForcedIsa f("not-an-isa");
      CHECK_THROWS_WITH_AS(detail::cpu_isa_selected(), doctest::Contains("compiled for"), DeviceError);
      const Plan plan = make_plan(isa_scene("seibert2011", Precision::Double, MathMode::Portable));
      CHECK_THROWS_WITH_AS(awtest::run_on("cpu", plan), doctest::Contains("ARNOLDWEB_CPU_ISA=not-an-isa"),
                           DeviceError);
    }
  }

  TEST_CASE("every compiled set this CPU supports gives the same bits") {
    const std::vector<std::string> isas = detail::cpu_isas_supported();
    if (!awtest::require(isas.size() >= 2, "cpu-isa",
                         "this build's cpu kernels have fewer than two sets this CPU runs (ARNOLDWEB_CPU_ISAS)"))
      return;
    for (const std::string model : {"seibert2011", "fgl", "fourier"})
      for (Precision p : {Precision::Double, Precision::Float})
        for (MathMode m : {MathMode::Portable, MathMode::Native}) {
          const Plan plan = make_plan(isa_scene(model, p, m));
          Result ref;
          for (const std::string& isa : isas) {
            CAPTURE(model);
            CAPTURE(to_string(p));
            CAPTURE(to_string(m));
            CAPTURE(isa);
            ForcedIsa f(isa);
            const Result r = awtest::run_on("cpu", plan);
            CHECK(r.kernel.find(isa) != std::string::npos);
            if (isa == isas.front()) {
              REQUIRE(r.binned > 2000);  // a run that binned nothing would prove little
              ref = r;
              continue;
            }
            CHECK(awtest::first_difference(r.reals("final_states"), ref.reals("final_states")) == -1);
            CHECK(awtest::first_difference(r.ints("final_states"), ref.ints("final_states")) == -1);
            CHECK(digest_map(r) == digest_map(ref));
            CHECK(r.energy.max == ref.energy.max);
            CHECK(r.binned == ref.binned);
          }
        }
  }
}
