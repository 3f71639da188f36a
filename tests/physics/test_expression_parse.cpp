// Expression models: the grammar, the errors (with their columns) and the
// simplifier's output (lib/src/physics/expression/).
#include <doctest/doctest.h>

#include <cmath>
#include <set>

#include "expression_support.hpp"
#include "physics/expression/parser.hpp"

using awtest::constant_of;
using awtest::failure_of;
namespace ex = arnoldweb::detail::expression;

namespace {
double value_at(const std::string& text, double x, double y, double z, const std::vector<std::string>& names = {},
                const std::vector<double>& values = {}) {
  ex::Potential p = ex::compile_potential(text, names);
  ex::Evaluator ev(p.lowered);
  return ev.potential(x / ex::kTwoPi, y / ex::kTwoPi, z / ex::kTwoPi, values);
}
std::string simplified(const std::string& text, const std::vector<std::string>& names = {}) {
  ex::Graph g;
  const int root = ex::parse(g, text, names);
  return ex::to_text(g, root, names);
}
}  // namespace

TEST_SUITE("expression") {
  TEST_CASE("every construct of the grammar: numbers, operators, precedence, associativity") {
    double v = 0;
    const struct {
      const char* text;
      double value;
    } cases[] = {
        {"1 + 2*3", 7},      {"(1 + 2)*3", 9},   {"8/2/2", 2},         {"1 - 2 - 3", -4},  {"2^3", 8},
        {"-2^2", -4},        {"(-2)^2", 4},      {"2^-1", 0.5},        {"2^(-2)", 0.25},   {"+3", 3},
        {"--3", 3},          {"2e1", 20},        {".5", 0.5},          {"1.5E-1", 0.15},   {"2.5e+2", 250},
        {"sqrt(4)", 2},      {"exp(0)", 1},      {"cos(0)", 1},        {"sin(0)", 0},      {"cos(pi)", -1},
        {"2*pi", 2 * M_PI},  {"3 - -1", 4},      {"2*3^2", 18},        {"12/4*3", 9},      {"1/2^2", 0.25},
    };
    for (const auto& c : cases) {
      CAPTURE(c.text);
      REQUIRE(constant_of(c.text, &v));
      CHECK(v == doctest::Approx(c.value).epsilon(1e-15));
    }
  }

  TEST_CASE("variables in radians, functions and parameters evaluate as written") {
    const double x = 0.7, y = -1.3, z = 2.9;
    CHECK(value_at("x", x, y, z) == doctest::Approx(x).epsilon(1e-15));
    CHECK(value_at("sin(x)*cos(y) + exp(cos(z))/2", x, y, z) ==
          doctest::Approx(std::sin(x) * std::cos(y) + std::exp(std::cos(z)) / 2).epsilon(1e-14));
    CHECK(value_at("sqrt(2 + sin(x + 2*y - z))", x, y, z) ==
          doctest::Approx(std::sqrt(2 + std::sin(x + 2 * y - z))).epsilon(1e-14));
    CHECK(value_at("eps*cos(x)^3 - a/(2 + cos(y))", x, y, z, {"eps", "a"}, {0.25, 1.5}) ==
          doctest::Approx(0.25 * std::pow(std::cos(x), 3) - 1.5 / (2 + std::cos(y))).epsilon(1e-14));
    CHECK(value_at("cos(x/2 + 0.3)", x, y, z) == doctest::Approx(std::cos(x / 2 + 0.3)).epsilon(1e-14));
    CHECK(value_at("sin(cos(x)*y)", x, y, z) == doctest::Approx(std::sin(std::cos(x) * y)).epsilon(1e-14));
    CHECK(value_at("cos(x)^-2", x, y, z) == doctest::Approx(1 / (std::cos(x) * std::cos(x))).epsilon(1e-14));
  }

  TEST_CASE("errors name the column and what is allowed") {
    const struct {
      const char* text;
      int column;
      const char* says;
    } cases[] = {
        {"", 1, "the expression is empty"},
        {"   ", 4, "the expression is empty"},
        {"cos(x) + w", 10, "unknown name \"w\" (variables are x, y, z; parameters: eps)"},
        {"cos(x", 6, "expected ')' to close the '(' at column 4"},
        {"x ** 2", 3, "powers are written ^"},
        {"x / 0", 3, "division by zero"},
        {"x/(1 - 1)", 2, "division by zero"},
        {"2x", 2, "write products with *"},
        {"x^2.5", 3, "an exponent must be an integer"},
        {"x^y", 3, "an exponent must be an integer"},
        {"x^2^3", 4, "a power of a power is ambiguous"},
        {"x^100", 3, "too large"},
        {"foo(x)", 1, "unknown function \"foo\""},
        {"sin x", 5, "sin needs its argument in parentheses"},
        {"x + ", 5, "unexpected end"},
        {"x # 2", 3, "unexpected character '#'"},
        {"1e + x", 1, "malformed number"},
        {"1e999", 1, "out of the range"},
        {"x)", 2, "')' without a matching '('"},
        {"*x", 1, "expected a number, a name or '(', found '*'"},
        {"exp(1000)", 1, "overflows"},
        {"sqrt(-1)", 1, "square root of a negative constant"},
        {"1e300*1e300", 6, "not finite"},
    };
    for (const auto& c : cases) {
      CAPTURE(c.text);
      const auto f = failure_of(c.text, {"eps"});
      CHECK(f.column == c.column);
      CHECK(f.message.find(c.says) != std::string::npos);
    }
    CHECK(failure_of("w").message.find("no parameters are given") != std::string::npos);
  }

  TEST_CASE("excessive length and depth are refused") {
    std::string deep;
    for (int i = 0; i < 70; ++i) deep += "(";
    deep += "x";
    for (int i = 0; i < 70; ++i) deep += ")";
    const auto f = failure_of(deep);
    CHECK(f.column == ex::kMaxDepth + 1);
    CHECK(f.message.find("nested too deeply") != std::string::npos);
    std::string negs(80, '-');
    CHECK(failure_of(negs + "x").message.find("nested too deeply") != std::string::npos);
    std::string longtext = "x";
    while (longtext.size() <= ex::kMaxLength) longtext += " + x";
    const auto l = failure_of(longtext);
    CHECK(l.column == 0);
    CHECK(l.message.find("characters long (at most 4096)") != std::string::npos);
  }

  TEST_CASE("parameter names: identifiers other than x, y, z, pi and the functions") {
    std::string why;
    CHECK(ex::valid_parameter_name("eps", &why));
    CHECK(ex::valid_parameter_name("k_2", &why));
    CHECK_FALSE(ex::valid_parameter_name("x", &why));
    CHECK(why.find("reserved") != std::string::npos);
    CHECK_FALSE(ex::valid_parameter_name("cos", &why));
    CHECK_FALSE(ex::valid_parameter_name("2a", &why));
    CHECK_FALSE(ex::valid_parameter_name("a-b", &why));
  }

  TEST_CASE("the simplifier folds constants and drops neutral elements") {
    CHECK(simplified("x*1 + 0*y") == "x");
    CHECK(simplified("0 + x - 0") == "x");
    CHECK(simplified("2*3*x") == "6*x");
    CHECK(simplified("-(-x)") == "x");
    CHECK(simplified("x - x") == "0");
    CHECK(simplified("x/1") == "x");
    CHECK(simplified("cos(-x)") == "cos(x)");
    CHECK(simplified("sin(-x)") == "-sin(x)");
    CHECK(simplified("x + -y") == "x - y");
    CHECK(simplified("(-x)*y") == "-(x*y)");
    CHECK(simplified("x^1 + y^0") == "1 + x");  // constants first in + and *
    CHECK(simplified("y*x - x*y") == "0");  // a*b and b*a are one node
    CHECK(simplified("a*(b + c)", {"a", "b", "c"}) == "a*(b + c)");
    CHECK(simplified("(x + y) + z") == "x + y + z");
    CHECK(simplified("x + (y + z)") == "x + (y + z)");  // never reassociated
  }

  TEST_CASE("derivatives are simplified and share sin and cos with the potential") {
    ex::Potential p = ex::compile_potential("sin(x)*cos(y)", {});
    const auto& g = p.radians.graph;
    CHECK(ex::to_text(g, p.radians.gradient[0], {}) == "cos(y)*cos(x)");
    CHECK(ex::to_text(g, p.radians.gradient[1], {}) == "-(sin(x)*sin(y))");
    CHECK(ex::to_text(g, p.radians.gradient[2], {}) == "0");
    CHECK(ex::to_text(g, p.radians.hessian[0], {}) == "-(sin(x)*cos(y))");

    // the paper's potential: force and Hessian need sin/cos of three arguments
    // (x, y, 2z), one aw_sincos2pi each
    ex::Potential paper = ex::compile_potential("cos(x)*cos(y)*(1 + cos(2*z))", {});
    const auto& l = paper.lowered.graph;
    std::set<int> arguments;
    for (int id = 0; id < l.size(); ++id)
      if (l[id].op == ex::Op::SinTurns || l[id].op == ex::Op::CosTurns) arguments.insert(l[id].a);
    CHECK(arguments.size() == 3);
    for (int a : arguments) CHECK(ex::to_text(l, a, {}).find("6.28") == std::string::npos);  // in turns
  }
}
