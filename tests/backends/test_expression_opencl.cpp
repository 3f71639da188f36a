// Expression models on OpenCL (PoCL here): the paper's potential written as
// an expression, its emitted header compiled in place of the built-in's,
// agrees with the built-in seibert2011 to round-off (the cpu backend's run-time
// kernel: test_expression_cpu.cpp). Most cases build the plan's kernel
// configuration directly from a built-in scene; one checks that the scene's
// route (model.kind = "expression") gives the same bits.
#include <doctest/doctest.h>

#include <cmath>

#include "arnoldweb/arnoldweb.hpp"
#include "aw_params.h"
#include "../physics/expression_cases.hpp"
#include "physics/expression/expression_model.hpp"
#include "plan/plan_params.hpp"
#include "run_outputs.hpp"
#include "support.hpp"

using namespace arnoldweb;
namespace ex = arnoldweb::detail::expression;

namespace {

Scene small_scene(const std::vector<std::string>& sets = {}) {
  return awtest::scene_from(R"(
    [model]
    energy = 15
    [ensemble]
    trajectories = 2000
    seed = 7
    [integrator]
    step = 0.01
    [run]
    average = 5
    duration = 5
    [observe]
    velocity_map = { nside = 8 }
    energy_error = { every = 1 }
    initial_states = true
    final_states = true
  )", sets, "<expression>");
}

// The plan of `scene` with its model replaced by the expression `text`.
Plan as_expression(const Scene& scene, const std::string& text) {
  Plan p = make_plan(scene);
  const ex::ExpressionModel m = ex::make_expression_model(text, {});
  p.kernel.model = ex::kExpressionModelId;
  p.kernel.model_source = m.device_header;
  auto& reals = detail::edit_params(p).reals;
  for (int i = 0; i < 3; ++i) reals.model[i] = 1;  // a = (1, 1, 1), b = 0: T = |P|^2/2
  ex::fill_parameter_slots(m, reals.model, AW_MAX_MODEL_PARAMS);
  return p;
}

}  // namespace

TEST_SUITE("expression-opencl") {
  TEST_CASE("the paper's potential as an expression agrees with seibert2011 on OpenCL to round-off") {
    const std::string dev = awtest::first_opencl();
    if (!awtest::require(!dev.empty(), "expression-opencl", "no OpenCL device here (install pocl-opencl-icd)")) return;
    const Scene scene = small_scene();
    const Result builtin = awtest::run_on(dev, make_plan(scene));
    const Result expr = awtest::run_on(dev, as_expression(scene, awtest::paper_potential()));
    REQUIRE(expr.completed == builtin.completed);
    REQUIRE(expr.reals("final_states").size() == builtin.reals("final_states").size());
    CHECK(expr.flagged() == builtin.flagged());
    // initial states: the same draws, V and the speed differ in the last bits
    double worst_init = 0;
    for (std::size_t i = 0; i < builtin.reals("initial_states").size(); ++i)
      worst_init = std::max(worst_init, std::fabs(expr.reals("initial_states")[i] - builtin.reals("initial_states")[i]));
    CHECK(worst_init < 1e-13);
    // final states after 500 steps: round-off grows with the flow's divergence; most stay close
    std::size_t close = 0;
    const std::size_t n = builtin.reals("final_states").size() / AW_STATE_REALS;
    for (std::size_t t = 0; t < n; ++t) {
      double d = 0;
      for (std::size_t k = 0; k < AW_STATE_REALS; ++k)
        d = std::max(d, std::fabs(expr.reals("final_states")[t * AW_STATE_REALS + k] - builtin.reals("final_states")[t * AW_STATE_REALS + k]));
      if (d < 1e-8) ++close;
    }
    CHECK(close >= n * 99 / 100);
    // the integrator's energy error is the method's, not the model's rounding
    CHECK(expr.energy.max == doctest::Approx(builtin.energy.max).epsilon(0.01));
    // the scene's route (model.kind = "expression") compiles and runs exactly this
    const Result scene_route = awtest::run_on(
        dev, make_plan(small_scene({"model.kind=\"expression\"", awtest::set("model.potential", awtest::paper_potential())})));
    CHECK(awtest::first_difference(scene_route.reals("final_states"), expr.reals("final_states")) == -1);
    CHECK(digest_map(scene_route) == digest_map(expr));
    MESSAGE("expression vs built-in: max |dE| " << expr.energy.max << " vs " << builtin.energy.max << "; "
                                                << close << " of " << n << " final states within 1e-8");
  }

  TEST_CASE("an expression model in float compiles and runs on OpenCL") {
    const std::string dev = awtest::first_opencl();
    if (!awtest::require(!dev.empty(), "expression-opencl", "no OpenCL device here (install pocl-opencl-icd)")) return;
    const Scene scene = small_scene({"integrator.precision=\"float\""});
    const Result expr = awtest::run_on(dev, as_expression(scene, awtest::paper_potential()));
    const Result builtin = awtest::run_on(dev, make_plan(scene));
    CHECK(expr.completed == 2000);
    CHECK(expr.energy.max == doctest::Approx(builtin.energy.max).epsilon(0.2));
  }

  TEST_CASE("every construct compiles as OpenCL C and conserves the energy of its Hamiltonian") {
    const std::string dev = awtest::first_opencl();
    if (!awtest::require(!dev.empty(), "expression-opencl", "no OpenCL device here (install pocl-opencl-icd)")) return;
    // a smooth periodic potential with exp, sqrt, powers and a division, below E
    const Result r = awtest::run_on(
        dev, as_expression(small_scene(), "exp(cos(x - y))*sqrt(2 + sin(z)) + sin(x)^3*cos(2*y + z)^2/(3 + cos(z))"));
    CHECK(r.completed == 2000);
    CHECK(r.flagged_nonfinite == 0);
    CHECK(r.energy.max < 1e-3);
    CHECK(r.energy.max > 0);
  }
}
