// Expression models through the scene: model.kind = "expression" with
// model.potential and model.parameters plans an expression model (its header,
// its parameter slots, V on the host), and every error reaches `arnoldweb
// check` with exit 2, naming the key and the column or the coordinate.
#include <doctest/doctest.h>

#include <fstream>

#include "arnoldweb/arnoldweb.hpp"
#include "expression_cases.hpp"
#include "plan/plan_params.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

const char* kBase = R"(
[model]
kind = "expression"
energy = 15
[ensemble]
trajectories = 1000
[integrator]
step = 0.01
[run]
average = 1
duration = 1
)";

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// `arnoldweb check` on kBase with `sets`; the exit code, the output in *out.
int check_with(const std::vector<std::string>& sets, std::string* out) {
  const std::string dir = awtest::temp_dir("expression");
  std::ofstream(dir + "/scene.toml") << kBase;
  std::vector<std::string> args = {"check", dir + "/scene.toml"};
  for (const auto& s : sets) {
    args.push_back("--set");
    args.push_back(s);
  }
  return awtest::run_cli(args, out);
}

}  // namespace

TEST_SUITE("expression") {
  TEST_CASE("model.kind = expression plans the emitted model with its parameters") {
    const Scene s = awtest::scene_from(kBase, {awtest::set("model.potential", "eps*cos(x)*cos(y)*(1 + cos(2*z))"),
                                               "model.parameters={ eps = 1.0 }"});
    const Plan p = make_plan(s);
    CHECK(p.kernel.model == 1000);
    CHECK(contains(p.kernel.model_source, "AW_FN void aw_model_force_hessian("));
    CHECK(contains(p.kernel.model_source, "rp->model[6]"));
    const auto& rp = detail::params(p).reals;
    CHECK(rp.model[0] == 1);
    CHECK(rp.model[3] == 0);
    CHECK(rp.model[6] == 1.0);
    // the same accessible torus as the built-in (V from the host evaluator)
    const Plan builtin = make_plan(awtest::scene_from(kBase, {"model.kind=\"seibert2011\""}));
    CHECK(p.accessible_fraction == doctest::Approx(builtin.accessible_fraction).epsilon(1e-3));
    // the echo reads back as the same scene
    const Scene back = awtest::scene_from(s.to_toml());
    CHECK(back.model_kind == "expression");
    CHECK(back.model_potential == s.model_potential);
    CHECK(back.model_parameters == s.model_parameters);
  }

  TEST_CASE("errors in an expression model reach arnoldweb check with exit 2") {
    const struct {
      std::vector<std::string> sets;
      std::vector<std::string> says;
    } cases[] = {
        {{awtest::set("model.potential", "cos(x) + w"), "model.parameters={ eps = 1 }"},
         {"model.potential", "column 10: unknown name \"w\" (variables are x, y, z; parameters: eps)"}},
        {{awtest::set("model.potential", "cos(x")}, {"model.potential", "column 6: expected ')'"}},
        {{awtest::set("model.potential", "cos(x/2)*cos(y)")}, {"model.potential", "not 2*pi-periodic in x"}},
        {{awtest::set("model.potential", "cos(x)*cos(z*1.5)")}, {"model.potential", "not 2*pi-periodic in z"}},
        {{awtest::set("model.potential", "eps*cos(x)")},
         {"model.potential", "column 1: unknown name \"eps\"", "no parameters are given"}},
        {{awtest::set("model.potential", "x / 0")}, {"model.potential", "column 3: division by zero"}},
        {{}, {"model.kind", "needs model.potential"}},
        {{awtest::set("model.potential", "cos(x)"), "model.parameters={ x = 1 }"}, {"model.parameters", "reserved"}},
        {{awtest::set("model.potential", "20 + cos(x)")}, {"model.energy"}},
        {{"model.kind=\"seibert2011\"", awtest::set("model.potential", "cos(x)")},
         {"model.potential", "is a parameter of model.kind = \"expression\""}},
    };
    for (const auto& c : cases) {
      std::string out;
      const int code = check_with(c.sets, &out);
      CAPTURE(out);
      CHECK(code == 2);
      for (const auto& s : c.says) CHECK(contains(out, s));
    }
  }

  TEST_CASE("arnoldweb models lists the expression kind") {
    std::string out;
    CHECK(awtest::run_cli({"models"}, &out) == 0);
    CHECK(contains(out, "expression"));
    CHECK(contains(out, "model.potential"));
  }
}
