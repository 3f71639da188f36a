// model.kind and the models' parameters: read, written back, refused with the
// key and the allowed range; keys of another model, a kinetic form the initial
// kind cannot use and unreachable energies refused by the planner.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "arnoldweb/models.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The SceneError of reading (and then planning) a scene, "" if none.
struct Refusal {
  std::string key, message;
};
Refusal refusal(const std::string& toml, const std::vector<std::string>& sets = {}) {
  try {
    make_plan(awtest::scene_from(toml, sets, "<model-keys>"));
  } catch (const SceneError& e) {
    return {e.key(), e.message()};
  }
  return {};
}

}  // namespace

TEST_SUITE("scene") {
  TEST_CASE("model.kind: the default is seibert2011, listed first; every model of the table plans and its echo reads back") {
    const Scene d = awtest::scene_from("");
    CHECK(d.model_kind == "seibert2011");
    const std::vector<ModelInfo> models = model_list();
    REQUIRE(!models.empty());
    CHECK(models.front().name == "seibert2011");
    for (const ModelInfo& m : models) {
      CAPTURE(m.name);
      std::vector<std::string> sets = {awtest::set("model.kind", m.name), "integrator.allow_unsafe_step=true",
                                       "model.energy=2"};
      if (m.name == "expression") sets.push_back("model.potential=\"cos(x)*cos(y)\"");
      const Scene s = awtest::scene_from("", sets);
      const Plan p = make_plan(s);
      CHECK(p.kernel.model >= 0);
      const Scene back = awtest::scene_from(s.to_toml());  // the echo reads back as the same scene, and plans
      CHECK(back.model_kind == m.name);
      const std::string a = s.to_toml(), b = back.to_toml();
      CHECK(b.substr(b.find("[model]")) == a.substr(a.find("[model]")));
      CHECK_NOTHROW(make_plan(back));
    }
    const Scene f = awtest::scene_from("[model]\nkind = \"fourier\"\nharmonics = [[1, 0, 0, 0.5, 0.25], [0, 2, -1, 1.5, 0]]\n"
                                       "kinetic_a = [1, 2, 0]\nkinetic_b = [0, 0, 1]\n"
                                       "[integrator]\nallow_unsafe_step = true\n");  // p_z unbounded on the shell
    const std::vector<double> harmonics = {1, 0, 0, 0.5, 0.25, 0, 2, -1, 1.5, 0};
    CHECK(f.model_values.at("model.harmonics") == harmonics);
    CHECK(f.model_values.at("model.kinetic_a") == std::vector<double>{1, 2, 0});
    const Scene back = awtest::scene_from(f.to_toml());
    CHECK_NOTHROW(make_plan(back));
    CHECK(back.model_kind == "fourier");
    CHECK(back.model_values.at("model.harmonics") == harmonics);
    CHECK(back.model_values.at("model.kinetic_a") == f.model_values.at("model.kinetic_a"));
    CHECK(back.model_values.at("model.kinetic_b") == f.model_values.at("model.kinetic_b"));
    CHECK(contains(f.to_toml(), "harmonics = [[1, 0, 0, 0.5, 0.25], [0, 2, -1, 1.5, 0.0]]"));
  }

  TEST_CASE("bad model keys are refused naming the key and what is allowed") {
    Refusal r = refusal("[model]\nkind = \"fgll\"\n");
    CHECK(r.key == "model.kind");
    CHECK(contains(r.message, "did you mean \"fgl\""));
    r = refusal("[model]\nkind = \"fgl\"\nepsilon = 1.5\n");
    CHECK(r.key == "model.epsilon");
    CHECK(contains(r.message, "from 0 to 1"));
    std::string many = "[model]\nkind = \"fourier\"\nharmonics = [";
    for (int j = 0; j < 33; ++j) many += std::string(j ? ", " : "") + "[1, 0, 0, 0.1, 0]";
    r = refusal(many + "]\n");
    CHECK(r.key == "model.harmonics");
    CHECK(contains(r.message, "1 to 32 harmonics"));
    CHECK(contains(r.message, "(33 rows)"));
    r = refusal("[model]\nkind = \"fourier\"\nharmonics = [[1.5, 0, 0, 1, 0]]\n");
    CHECK(r.key == "model.harmonics");
    CHECK(contains(r.message, "k must be integers"));
    r = refusal("[model]\nkind = \"fourier\"\nharmonics = [[1, 0, 0, 1]]\n");
    CHECK(r.key == "model.harmonics");
    CHECK(contains(r.message, "[kx, ky, kz, c, phi]"));
    r = refusal("[model]\nkind = \"fourier\"\nharmonics = [[0, 0, 0, 1, 0]]\n");
    CHECK(contains(r.message, "k = 0"));
    r = refusal("[model]\nkind = \"fourier\"\nkinetic_a = [1, -1, 1]\n");
    CHECK(r.key == "model.kinetic_a");
    CHECK(contains(r.message, ">= 0"));
  }

  TEST_CASE("a parameter of another model is refused where it is written with another value than its default") {
    CHECK(refusal("[model]\nepsilon = 0.01\n").key.empty());  // the default, as the echo writes it
    Refusal r = refusal("[model]\nepsilon = 0.02\n");
    CHECK(r.key == "model.epsilon");
    CHECK(contains(r.message, "model.kind = \"fgl\""));
    CHECK(contains(r.message, "\"seibert2011\""));
    r = refusal("[model]\nkind = \"fgl\"\nharmonics = [[1, 0, 0, 1, 0]]\n");
    CHECK(r.key == "model.harmonics");
    r = refusal("", {"model.kind=\"fgl\"", "model.kinetic_b=[0, 0, 1]"});
    CHECK(r.key == "model.kinetic_b");
  }

  TEST_CASE("gaussian initial momenta need the kinetic form |P|^2/2") {
    const Refusal r = refusal("[model]\nkind = \"fgl\"\nenergy = 0.5\n[ensemble]\ninitial = \"gaussian\"\n");
    CHECK(r.key == "ensemble.initial");
    CHECK(contains(r.message, "|P|^2/2"));
    // fourier with a = 1, b = 0 has it
    CHECK(refusal("[model]\nkind = \"fourier\"\nenergy = 15\n[ensemble]\ninitial = \"gaussian\"\n"
                  "gaussian = { mean = [3, 3], sigma = [0.01, 0.01] }\n").key.empty());
  }

  TEST_CASE("an energy surface that is not reached is refused naming model.energy and the reachable range") {
    // a = (1, 1, 0), b = 0: T >= 0 and T(s n) = 0 for n along z, so E = -1.5 < min V = -1 is not reached
    Refusal r = refusal("[model]\nkind = \"fourier\"\nenergy = -1.5\nharmonics = [[1, 0, 0, 1, 0]]\n"
                        "kinetic_a = [1, 1, 0]\n");
    CHECK(r.key == "model.energy");
    CHECK(contains(r.message, "energy surface"));
    CHECK(contains(r.message, "-1 <= V <= 1"));
    // the same with |P|^2/2: the accessible torus
    r = refusal("[model]\nkind = \"fourier\"\nenergy = -1.5\nharmonics = [[1, 0, 0, 1, 0]]\n");
    CHECK(r.key == "model.energy");
    CHECK(contains(r.message, "choose E > -1"));
    // T with a linear term: bounded below by -b^2/(2a)
    r = refusal("[model]\nkind = \"fourier\"\nenergy = -1.9\nharmonics = [[1, 0, 0, 0.1, 0]]\n"
                "kinetic_b = [1, 0, 0]\n");
    CHECK(r.key == "model.energy");
    CHECK(contains(r.message, "T(P) >= -0.5"));
    CHECK(contains(r.message, "E must exceed -0.6"));
    // fgl below its potential is reached through I3 < 0
    CHECK(refusal("[model]\nkind = \"fgl\"\nenergy = -0.5\n").key.empty());
  }

  TEST_CASE("the step-size guard follows the model's own largest frequency") {
    const Plan paper = make_plan(awtest::scene_from("[model]\nenergy = 15\n"));
    CHECK(paper.guard.omega == doctest::Approx(2 * std::sqrt(2 * 17.0)));
    // fourier with the paper's harmonics: sqrt(2 (E + 2) max |k|^2) + sqrt(sum |c| |k|^2) = sqrt(204) + sqrt(8)
    const Plan fourier = make_plan(awtest::scene_from("[model]\nkind = \"fourier\"\nenergy = 15\n"));
    CHECK(fourier.guard.omega == doctest::Approx(std::sqrt(2 * 17.0 * 6) + std::sqrt(8.0)));
    // fgl: from its initial states' velocities; a larger eps, a larger omega
    const std::string fgl = "[model]\nkind = \"fgl\"\nenergy = 0.5\n[ensemble]\ninitial = \"box\"\n"
                            "box = { lon = [0, 360], lat = [-42, 90] }\n";
    const Plan small = make_plan(awtest::scene_from(fgl, {"model.epsilon=0.001"}));
    const Plan large = make_plan(awtest::scene_from(fgl, {"model.epsilon=0.04"}));
    CHECK(small.guard.omega > 3);   // |I1| + |I2| + 1 reach about 3 in this box
    CHECK(small.guard.omega < 10);
    CHECK(large.guard.omega > small.guard.omega);
    CHECK(contains(large.guard.basis, "initial states"));
    // and refuses a step where h omega >= pi, naming the key
    const Refusal r = refusal(fgl, {"integrator.step=0.2", "run.average=1", "run.duration=1",
                                    "observe.energy_error=false"});
    CHECK(r.key == "integrator.step");
    CHECK(contains(r.message, "h omega_max"));
    CHECK(largest_frequency(awtest::scene_from(fgl, {"model.epsilon=0.04"})) == large.guard.omega);
  }
}
