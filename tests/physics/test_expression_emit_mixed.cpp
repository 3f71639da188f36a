// Expression models: emitted code with every construct (parameters from
// rp->model, exp, sqrt, powers, division, a non-linear sin argument),
// compiled here as C++, gives the host evaluator's bits.
#include <doctest/doctest.h>

#include <random>

#include "aw_cpp_std.h"
namespace gen_mixed {
#include "expression_golden/mixed.h"
}  // namespace gen_mixed

#include "expression_cases.hpp"
#include "expression_golden.hpp"

namespace ex = arnoldweb::detail::expression;

TEST_SUITE("expression") {
  TEST_CASE("emitted code of the mixed potential is current") {
    ex::Potential p = ex::compile_potential(awtest::mixed_potential(), awtest::mixed_parameters());
    ex::EmitOptions o;
    o.source = awtest::mixed_potential();
    o.parameter_names = awtest::mixed_parameters();
    o.parameter_base = awtest::kMixedParameterBase;
    const std::string why = awtest::golden_mismatch("mixed.h", ex::emit_device_header(p.lowered, o));
    CHECK_MESSAGE(why.empty(), why);
  }

  TEST_CASE("emitted mixed potential: host evaluator's bits") {
    ex::Potential p = ex::compile_potential(awtest::mixed_potential(), awtest::mixed_parameters());
    ex::Evaluator ev(p.lowered);
    gen_mixed::aw_rparams rp{};
    const auto values = awtest::mixed_values();
    for (std::size_t i = 0; i < values.size(); ++i) rp.model[awtest::kMixedParameterBase + i] = values[i];
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> angle(-0.6, 0.6);
    for (int n = 0; n < 10000; ++n) {
      const double ux = angle(rng), uy = angle(rng), uz = angle(rng);
      gen_mixed::aw_lstate s{};
      s.ux = ux;
      s.uy = uy;
      s.uz = uz;
      double hess[6];
      gen_mixed::aw_model_force_hessian(&s, &rp, hess);
      const ex::PointValues want = ev.all(ux, uy, uz, values);
      REQUIRE(gen_mixed::aw_model_potential(ux, uy, uz, &rp) == want.value);
      REQUIRE(s.fx == want.force[0]);
      REQUIRE(s.fy == want.force[1]);
      REQUIRE(s.fz == want.force[2]);
      for (int k = 0; k < 6; ++k) REQUIRE(hess[k] == want.hessian[static_cast<std::size_t>(k)]);
    }
  }
}
