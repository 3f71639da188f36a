// Expression models: the symbolic gradient and Hessian against central finite
// differences of the host evaluator, and the periodicity check.
#include <doctest/doctest.h>

#include <cmath>
#include <algorithm>
#include <random>

#include "expression_support.hpp"

using awtest::failure_of;
namespace ex = arnoldweb::detail::expression;

namespace {

// |a - b| relative to the larger of |a|, |b| and `floor`
double rel(double a, double b, double floor) { return std::fabs(a - b) / std::max({std::fabs(a), std::fabs(b), floor}); }

void check_against_differences(const std::string& text, const std::vector<std::string>& names,
                               const std::vector<double>& values) {
  CAPTURE(text);
  ex::Potential p = ex::compile_potential(text, names);
  ex::Evaluator ev(p.lowered);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> angle(-0.5, 0.5);  // turns
  const double h = 1e-5;                                     // radians
  const double du = h / ex::kTwoPi;
  static const int pairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
  double worst_f = 0, worst_h = 0;
  for (int n = 0; n < 200; ++n) {
    const double u[3] = {angle(rng), angle(rng), angle(rng)};
    const ex::PointValues at = ev.all(u[0], u[1], u[2], values);
    double scale = std::fabs(at.value);
    for (double f : at.force) scale = std::max(scale, std::fabs(f));
    for (int i = 0; i < 3; ++i) {
      double up[3] = {u[0], u[1], u[2]}, dn[3] = {u[0], u[1], u[2]};
      up[i] += du;
      dn[i] -= du;
      // F_i = -dV/dx_i
      const double fd = -(ev.potential(up[0], up[1], up[2], values) - ev.potential(dn[0], dn[1], dn[2], values)) / (2 * h);
      worst_f = std::max(worst_f, rel(at.force[static_cast<std::size_t>(i)], fd, scale + 1e-3));
    }
    for (std::size_t k = 0; k < 6; ++k) {
      const int i = pairs[k][0], j = pairs[k][1];
      double up[3] = {u[0], u[1], u[2]}, dn[3] = {u[0], u[1], u[2]};
      up[j] += du;
      dn[j] -= du;
      // H_ij = d(dV/dx_i)/dx_j = -dF_i/dx_j
      const double fd = -(ev.all(up[0], up[1], up[2], values).force[static_cast<std::size_t>(i)] -
                          ev.all(dn[0], dn[1], dn[2], values).force[static_cast<std::size_t>(i)]) /
                        (2 * h);
      double hscale = scale;
      for (double x : at.hessian) hscale = std::max(hscale, std::fabs(x));
      worst_h = std::max(worst_h, rel(at.hessian[k], fd, hscale + 1e-3));
    }
  }
  CHECK(worst_f < 1e-8);
  CHECK(worst_h < 1e-8);
}

}  // namespace

TEST_SUITE("expression") {
  TEST_CASE("gradient and Hessian agree with central differences at random points") {
    check_against_differences("cos(x)*cos(y)*(1 + cos(2*z))", {}, {});
    check_against_differences("eps/(cos(x) + cos(y) + cos(z) + 4)", {"eps"}, {0.04});
    check_against_differences("a*exp(cos(x - y))*sqrt(2 + sin(z)) + b*sin(x)^3*cos(2*y + z)^2", {"a", "b"},
                              {0.3, -1.7});
    check_against_differences("sin(cos(x)*2 + y)/(3 + cos(z)^-1*0 + sin(x + y + z)^2)", {}, {});
    check_against_differences("cos(k*x + phi)*cos(y)", {"k", "phi"}, {3, 0.4});
  }

  TEST_CASE("periodic potentials pass the periodicity check") {
    for (const char* text : {"cos(x)*cos(y)*(1 + cos(2*z))", "exp(cos(x))*sin(3*y - z)", "sin(cos(x))*cos(y)^2",
                             "1/(2 + cos(x + y + z))", "0", "cos(x/2)^2"}) {
      CAPTURE(text);
      ex::Potential p = ex::compile_potential(text, {});
      CHECK_NOTHROW(ex::check_periodic(p, {}));
    }
  }

  TEST_CASE("a potential that is not 2 pi periodic is refused, naming the coordinate") {
    const struct {
      const char* text;
      const char* coordinate;
    } cases[] = {
        {"x", "in x:"}, {"cos(y/2)", "in y:"}, {"cos(x)*cos(1.5*z)", "in z:"}, {"sin(x) + 1e-6*z", "in z:"},
        {"exp(sin(y + 0.001*y))", "in y:"},
    };
    for (const auto& c : cases) {
      CAPTURE(c.text);
      ex::Potential p = ex::compile_potential(c.text, {});
      try {
        ex::check_periodic(p, {});
        FAIL("accepted");
      } catch (const ex::ExpressionError& e) {
        CHECK(std::string(e.message()).find(std::string("not 2*pi-periodic ") + c.coordinate) != std::string::npos);
      }
    }
    // a parameter that makes it non-periodic
    ex::Potential k = ex::compile_potential("cos(k*x)", {"k"});
    CHECK_NOTHROW(ex::check_periodic(k, {2}));
    CHECK_THROWS_WITH_AS(ex::check_periodic(k, {2.5}), doctest::Contains("not 2*pi-periodic in x"),
                         ex::ExpressionError);
  }

  TEST_CASE("a potential that is not finite on the torus is refused") {
    ex::Potential nan = ex::compile_potential("sqrt(cos(x))", {});
    CHECK_THROWS_WITH_AS(ex::check_periodic(nan, {}), doctest::Contains("V is not finite at"), ex::ExpressionError);
  }
}
