// Expression models: the emitted device code of the paper's potential,
// compiled here as C++ (the cpu backend's dialect), gives the host
// evaluator's bits, and agrees with the built-in seibert2011 to round-off.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "aw_cpp_std.h"
namespace gen_paper {
#include "expression_golden/paper.h"
}  // namespace gen_paper

#include "expression_cases.hpp"
#include "expression_golden.hpp"

namespace ex = arnoldweb::detail::expression;

TEST_SUITE("expression") {
  TEST_CASE("emitted code of the paper's potential is current") {
    ex::Potential p = ex::compile_potential(awtest::paper_potential(), {});
    ex::EmitOptions o;
    o.source = awtest::paper_potential();
    const std::string why = awtest::golden_mismatch("paper.h", ex::emit_device_header(p.lowered, o));
    CHECK_MESSAGE(why.empty(), why);
  }

  TEST_CASE("emitted paper potential: host evaluator's bits, seibert2011's values") {
    ex::Potential p = ex::compile_potential(awtest::paper_potential(), {});
    ex::Evaluator ev(p.lowered);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> angle(-0.5, 0.5);
    const gen_paper::aw_rparams rp{};
    double worst = 0;
    for (int n = 0; n < 10000; ++n) {
      const double ux = angle(rng), uy = angle(rng), uz = angle(rng);
      gen_paper::aw_lstate s{};
      s.ux = ux;
      s.uy = uy;
      s.uz = uz;
      double hess[6];
      gen_paper::aw_model_force_hessian(&s, &rp, hess);
      const ex::PointValues want = ev.all(ux, uy, uz, {});
      REQUIRE(gen_paper::aw_model_potential(ux, uy, uz, &rp) == want.value);
      REQUIRE(s.fx == want.force[0]);
      REQUIRE(s.fy == want.force[1]);
      REQUIRE(s.fz == want.force[2]);
      for (int k = 0; k < 6; ++k) REQUIRE(hess[k] == want.hessian[static_cast<std::size_t>(k)]);
      gen_paper::aw_lstate t{};
      t.ux = ux;
      t.uy = uy;
      t.uz = uz;
      gen_paper::aw_model_force(&t, &rp);
      REQUIRE(t.fx == s.fx);  // the force alone is the force of force_hessian
      REQUIRE(t.fy == s.fy);
      REQUIRE(t.fz == s.fz);
      // the built-in's closed forms (lib/device/models/aw_seibert2011.h)
      const double x = ex::kTwoPi * ux, y = ex::kTwoPi * uy, z = ex::kTwoPi * uz;
      const double cz2 = std::cos(z) * std::cos(z);
      const double ref[] = {2 * std::cos(x) * std::cos(y) * cz2,
                            2 * std::sin(x) * std::cos(y) * cz2,
                            2 * std::cos(x) * std::sin(y) * cz2,
                            4 * std::cos(x) * std::cos(y) * std::sin(z) * std::cos(z),
                            -2 * std::cos(x) * std::cos(y) * cz2,
                            -4 * std::cos(x) * std::cos(y) * (cz2 - std::sin(z) * std::sin(z)),
                            4 * std::sin(x) * std::cos(y) * std::sin(z) * std::cos(z)};
      const double got[] = {want.value, s.fx, s.fy, s.fz, hess[0], hess[2], hess[4]};
      for (int k = 0; k < 7; ++k) worst = std::max(worst, std::fabs(got[k] - ref[k]));
    }
    CHECK(worst < 1e-14);
  }
}
