// A scene's model evaluated on the host (models.hpp: SceneModel; Python's
// aw.potential, aw.energy, aw.shell_momenta): the energy is the one
// check_states gives (the same code, the same bits), positions are periodic
// (wrapped as states are), the shell momenta lie on H = E, and the initial
// states the kernels make are found again from their own directions.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "arnoldweb/arnoldweb.hpp"
#include "arnoldweb/models.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

// One scene of every kind of model: the paper's, its FGL form, a Fourier
// potential with a kinetic form other than |P|^2/2, and an expression.
std::vector<Scene> model_scenes() {
  return {
      awtest::scene_from("[model]\nenergy = 15.0\n"),
      awtest::scene_from("[model]\nkind = \"fgl\"\nenergy = 1.0\n"),
      awtest::scene_from("[model]\nkind = \"fourier\"\nenergy = 3.0\nharmonics = [[1, 0, 0, 0.5, 0.25], [0, 2, -1, 1.5, 0]]\n"
                         "kinetic_a = [1, 0.5, 2]\nkinetic_b = [0, 0.25, -0.5]\n"),
      awtest::scene_from("[model]\nkind = \"expression\"\nenergy = 15.0\n"
                         "potential = \"eps*cos(x)*cos(y)*(1 + cos(2*z)) + sin(z)/4\"\nparameters = { eps = 1.0 }\n"),
  };
}

}  // namespace

TEST_SUITE("states") {
  TEST_CASE("SceneModel: the energy check_states gives, periodic positions, momenta on the shell") {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> turn(-0.5, 0.5), normal_ish(-1.0, 1.0);
    for (const Scene& scene : model_scenes()) {
      CAPTURE(scene.to_toml().substr(0, 120));
      const SceneModel model(scene);
      CHECK(model.energy() == scene.energy);
      std::vector<double> u, p, found;
      int reached = 0;
      for (int i = 0; i < 400; ++i) {
        auto exact = [&] { return std::round(turn(rng) * 1048576) / 1048576; };  // whole turns added stay exact
        const double x[3] = {exact(), exact(), exact()};
        double n[3] = {normal_ish(rng), normal_ish(rng), normal_ish(rng)};
        const double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (double& c : n) c /= norm;
        // periodic: whole turns apart, the same value (wrapped as states are)
        const double far[3] = {x[0] + 7, x[1] - 3, x[2] + 1024};
        CHECK(model.potential(far) == model.potential(x));
        double q[3] = {0, 0, 0};
        if (!model.shell_momentum(x, n, q)) {
          CHECK(q[0] == 0);  // left as it was
          continue;
        }
        ++reached;
        CHECK(model.hamiltonian(x, q) == doctest::Approx(scene.energy).epsilon(1e-12));
        CHECK(q[0] * n[0] + q[1] * n[1] + q[2] * n[2] > 0);  // along n, not against it
        for (int k = 0; k < 3; ++k) u.push_back(x[k]), p.push_back(q[k]);
        found.push_back(model.hamiltonian(x, q));
      }
      CHECK(reached > 100);
      // the energies check_states gives the same states: bit for bit
      StateSet s = states_from_arrays(u.data(), found.size(), 3, p.data(), found.size(), 3, PositionUnits::Turns,
                                      "initial");
      check_states(s, scene);
      CHECK(s.energy == found);
    }
  }

  TEST_CASE("SceneModel: no momentum where the energy is below V, and a refused model key is the planner's error") {
    const SceneModel model(awtest::scene_from("[model]\nenergy = 0.5\n"));  // V = 2 at the origin
    const double origin[3] = {0, 0, 0}, n[3] = {1, 0, 0};
    double p[3] = {9, 9, 9};
    CHECK_FALSE(model.shell_momentum(origin, n, p));
    CHECK(p[0] == 9);
    CHECK(model.potential(origin) == 2.0);
    CHECK_THROWS_AS(SceneModel(awtest::scene_from("[model]\nepsilon = 0.5\n")), SceneError);  // fgl's key
  }

  TEST_CASE("SceneModel: the kernels' initial states are found again from their own directions") {
    const Scene scene = awtest::scene_from(
        "[model]\nenergy = 15.0\n[ensemble]\ntrajectories = 2000\n[integrator]\nstep = 0.02\n"
        "[run]\naverage = 0.02\nduration = 0.02\n[observe]\ninitial_states = true\nvelocity_map = false\n"
        "energy_error = false\n");
    const Plan plan = make_plan(scene);
    auto dev = open_backend("cpu");
    const Result r = run(plan, *dev);
    const std::vector<double>& rec = r.reals("initial_states");
    const std::size_t per = rec.size() / r.completed;
    const SceneModel model(scene);
    double worst = 0;
    for (std::size_t t = 0; t < r.completed; ++t) {
      const double* u = &rec[t * per];
      const double* p = &rec[t * per + 3];
      CHECK(model.hamiltonian(u, p) == doctest::Approx(15.0).epsilon(1e-13));
      const double norm = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      const double n[3] = {p[0] / norm, p[1] / norm, p[2] / norm};
      double q[3];
      REQUIRE(model.shell_momentum(u, n, q));
      for (int k = 0; k < 3; ++k) worst = std::max(worst, std::fabs(q[k] - p[k]) / norm);
    }
    CHECK(worst < 1e-15);
  }
}
