// Models (docs/models.md): every built-in model's force and Hessian against
// finite differences of its potential; the fourier model with the paper's six
// harmonics against seibert2011; the general kinetic form's speed; the fgl
// model's energy error over 1e5 steps and its order of convergence on the cpu
// backend. (Parity of fgl and fourier between devices: tests/backends/test_parity.cpp.)
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "aw_params.h"
#include "physics/model_table.hpp"
#include "support.hpp"

using namespace arnoldweb;
using detail::HostModel;
using detail::ModelDescriptor;
using detail::RealParams;

namespace {

constexpr double kTwoPi = 6.283185307179586476925;

// Values for keys that models may declare, richer than their defaults (a key no
// model declares is never used; a model's other keys keep their defaults).
const detail::ModelValues& test_values() {
  static const detail::ModelValues v = {
      {"model.epsilon", {0.04}},
      {"model.harmonics", {1, 0, 0, 0.7, 0.3, 2, -1, 3, -0.2, 1.1, 0, 1, 1, 0.45, -2}},
      {"model.kinetic_a", {1, 0.5, 0}},
      {"model.kinetic_b", {0, 0.25, 1}},
  };
  return v;
}

// Every built-in model of the table with the test values of its keys.
struct ModelCase {
  const ModelDescriptor* model;
  RealParams rp{};
};
const std::vector<ModelCase>& cases() {
  static const std::vector<ModelCase> c = [] {
    std::vector<ModelCase> out;
    for (const ModelDescriptor& m : detail::models()) {
      if (!m.host) continue;  // an expression model: tests/physics/test_expression_*
      ModelCase mc{&m};
      m.fill(test_values(), mc.rp);
      out.push_back(mc);
    }
    return out;
  }();
  return c;
}

// Central fourth-order difference of f along one coordinate, per radian.
template <class F>
double derivative(F f, const std::array<double, 3>& u, int axis) {
  const double h = 2e-4;  // turns
  auto shifted = [&](double k) {
    std::array<double, 3> v = u;
    v[axis] += k * h;
    return f(v);
  };
  return (8 * (shifted(1) - shifted(-1)) - (shifted(2) - shifted(-2))) / (12 * h * kTwoPi);
}

}  // namespace

TEST_SUITE("models") {
  TEST_CASE("the table: every built-in model has its host code, a kinetic form, bounds and wave vectors") {
    REQUIRE(cases().size() >= 3);
    for (const ModelCase& mc : cases()) {
      const ModelDescriptor& m = *mc.model;
      CAPTURE(m.name);
      CHECK(detail::find_model(m.name) == &m);
      CHECK(!m.title.empty());
      CHECK(!m.formula.empty());
      REQUIRE(m.kinetic);
      REQUIRE(m.v_range);
      REQUIRE(m.hessian_bound);
      REQUIRE(m.wave_vectors);
      const auto v = m.v_range(mc.rp);
      CHECK(v[0] <= v[1]);
      CHECK(m.hessian_bound(mc.rp) >= 0);
      CHECK(!m.wave_vectors(mc.rp).empty());
      for (const auto& p : m.parameters) {
        CAPTURE(p.key);
        CHECK(p.key.rfind("model.", 0) == 0);
        CHECK(!p.help.empty());
        CHECK(!p.default_value.empty());
        if (p.check) CHECK(p.check(p.default_value).empty());  // the default passes its own checks
      }
    }
  }

  TEST_CASE("every model: force = -grad V and the Hessian = d^2V (finite differences), the same force from both; V within its range") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> uni(-0.5, 0.5);
    for (const ModelCase& mc : cases()) {
      const HostModel& m = *mc.model->host;
      const RealParams& rp = mc.rp;
      CAPTURE(mc.model->name);
      const auto range = mc.model->v_range(rp);
      double worst_f = 0, worst_h = 0;
      for (int t = 0; t < 200; ++t) {
        const std::array<double, 3> u = {uni(rng), uni(rng), uni(rng)};
        auto V = [&](const std::array<double, 3>& v) { return m.potential(v[0], v[1], v[2], rp); };
        const double here = V(u);
        CHECK(here >= range[0] - 1e-12);
        CHECK(here <= range[1] + 1e-12);
        double f[3], f2[3], hess[6];
        m.force_hessian(u.data(), rp, f, hess);
        m.force(u.data(), rp, f2);
        for (int i = 0; i < 3; ++i) CHECK(f[i] == f2[i]);  // bit for bit: the same operations
        for (int i = 0; i < 3; ++i) worst_f = std::max(worst_f, std::fabs(f[i] + derivative(V, u, i)));
        // the Hessian as -dF_j/dx_i
        const int index[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
        for (int j = 0; j < 3; ++j) {
          auto Fj = [&](const std::array<double, 3>& v) {
            double q[3];
            m.force(v.data(), rp, q);
            return q[j];
          };
          for (int i = 0; i < 3; ++i) worst_h = std::max(worst_h, std::fabs(hess[index[i][j]] + derivative(Fj, u, i)));
        }
      }
      std::printf("models: %-12s max |F + dV/dx| %.2e, max |Hess - d^2V| %.2e (200 points, 4th-order differences)\n",
                  mc.model->name.c_str(), worst_f, worst_h);
      CHECK(worst_f < 1e-10);
      CHECK(worst_h < 1e-9);
    }
  }

  TEST_CASE("fourier with the paper's six harmonics agrees with seibert2011 to round-off in V, force and Hessian") {
    const ModelDescriptor* fourier = detail::find_model("fourier");
    const ModelDescriptor* paper = detail::find_model("seibert2011");
    REQUIRE(fourier);
    REQUIRE(paper);
    RealParams six{}, none{};
    fourier->fill({}, six);  // the default harmonics
    paper->fill({}, none);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> uni(-0.5, 0.5);
    double worst = 0;
    for (int t = 0; t < 10000; ++t) {
      const double u[3] = {uni(rng), uni(rng), uni(rng)};
      worst = std::max(worst, std::fabs(fourier->host->potential(u[0], u[1], u[2], six) -
                                        paper->host->potential(u[0], u[1], u[2], none)));
      double fa[3], fb[3], ha[6], hb[6];
      fourier->host->force_hessian(u, six, fa, ha);
      paper->host->force_hessian(u, none, fb, hb);
      for (int i = 0; i < 3; ++i) worst = std::max(worst, std::fabs(fa[i] - fb[i]));
      for (int i = 0; i < 6; ++i) worst = std::max(worst, std::fabs(ha[i] - hb[i]));
    }
    std::printf("models: fourier (6 harmonics) vs seibert2011: max difference %.2e over 10000 points\n", worst);
    CHECK(worst < 1e-14);
    CHECK(worst > 0);  // different operations: equal to round-off, not bit for bit
    // and the same kinetic energy and drift diagonal
    double a[3];
    fourier->host->kinetic_diag(six, a);
    CHECK(a[0] == 1.0);
    CHECK(a[1] == 1.0);
    CHECK(a[2] == 1.0);
    const double p[3] = {0.3, -1.2, 2.5};
    CHECK(fourier->host->kinetic(p, six) == doctest::Approx(0.5 * (0.09 + 1.44 + 6.25)).epsilon(1e-15));
  }

  TEST_CASE("the general kinetic form: the speed puts the state on T(s n) = ke at the first crossing, or says none") {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> uni(-1.0, 1.0);
    for (const ModelCase& mc : cases()) {
      const HostModel& m = *mc.model->host;
      const RealParams& rp = mc.rp;
      CAPTURE(mc.model->name);
      double diag[3];
      m.kinetic_diag(rp, diag);
      int reached = 0, refused = 0;
      for (int t = 0; t < 20000; ++t) {
        double n[3] = {uni(rng), uni(rng), uni(rng)};
        const double r = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (r < 1e-3) continue;
        for (double& c : n) c /= r;
        const double ke = 2 * uni(rng);
        double s = 0;
        const bool ok = m.speed(ke, n, rp, s);
        // T along the ray is A s^2/2 + B s (A from the diagonal, B = T(n) - A/2)
        const double A = diag[0] * n[0] * n[0] + diag[1] * n[1] * n[1] + diag[2] * n[2] * n[2];
        const double B = m.kinetic(n, rp) - 0.5 * A;
        if (ok) {
          ++reached;
          REQUIRE(s > 0);
          // to round-off of the terms (the linear and quadratic parts may cancel)
          const double sn[3] = {s * n[0], s * n[1], s * n[2]};
          const double t = m.kinetic(sn, rp);
          CHECK(std::fabs(t - ke) <= 1e-13 * (0.5 * A * s * s + std::fabs(B) * s + std::fabs(ke)));
          // no crossing before s: the smaller root, where both are positive
          const double other = A > 0 ? -2 * B / A - s : -1;  // the sum of the roots is -2B/A
          CHECK((other <= 0 || other >= s * (1 - 1e-12)));
        } else {
          ++refused;
          CHECK(s == 0);
          // no positive root: B^2 + 2 A ke < 0, or both roots <= 0
          const double disc = B * B + 2 * A * ke;
          const bool none = disc < 0 || (A > 0 ? (-B + std::sqrt(disc)) / A <= 0 : (B == 0 || ke / B <= 0));
          CHECK(none);
        }
      }
      std::printf("models: %-12s speed: %d reached, %d without a crossing\n", mc.model->name.c_str(), reached, refused);
      CHECK(reached > 0);
    }
  }

  TEST_CASE("every model: the device's kinetic diagonal and T are the descriptor's kinetic form") {
    for (const ModelCase& mc : cases()) {
      CAPTURE(mc.model->name);
      const auto k = mc.model->kinetic(mc.rp);  // a_x, a_y, a_z, b_x, b_y, b_z
      double a[3];
      mc.model->host->kinetic_diag(mc.rp, a);
      for (int i = 0; i < 3; ++i) CHECK(a[i] == k[static_cast<std::size_t>(i)]);
      const double p[3] = {0.7, -1.3, 0.4};
      double t = 0;
      for (int i = 0; i < 3; ++i) t += 0.5 * k[static_cast<std::size_t>(i)] * p[i] * p[i] + k[static_cast<std::size_t>(3 + i)] * p[i];
      CHECK(mc.model->host->kinetic(p, mc.rp) == doctest::Approx(t).epsilon(1e-14));
    }
  }
}

// ---------------------------------------------------------------- fgl runs
namespace {

constexpr std::uint64_t kFglTrajectories = 64;

// fgl at eps = 0.04, E = 0.5, actions from a box of directions (docs/models.md).
Scene fgl_scene(const std::string& method, double step, double duration, const std::vector<std::string>& sets = {}) {
  std::vector<std::string> all = {awtest::set("integrator.method", method), awtest::set("integrator.step", step),
                                  awtest::set("run.average", duration), awtest::set("run.duration", duration)};
  all.insert(all.end(), sets.begin(), sets.end());
  return awtest::scene_from(R"(
    [model]
    kind = "fgl"
    epsilon = 0.04
    energy = 0.5
    [ensemble]
    trajectories = 64
    seed = 9
    initial = "box"
    box = { lon = [0, 360], lat = [-42, 90] }
    [observe]
    velocity_map = false
    energy_error = false
    final_states = true
  )", all, "<fgl>");
}

double rms_distance(const Result& a, const Result& b) {
  double sum = 0;
  for (std::size_t i = 0; i < kFglTrajectories; ++i) {
    REQUIRE(a.ints("final_states")[i * AW_STATE_INTS + 3] == AW_STATUS_OK);
    for (int c = 0; c < 3; ++c) {
      const double turns = static_cast<double>(a.ints("final_states")[i * AW_STATE_INTS + c] - b.ints("final_states")[i * AW_STATE_INTS + c]) +
                           (a.reals("final_states")[i * AW_STATE_REALS + c] - b.reals("final_states")[i * AW_STATE_REALS + c]);
      const double dx = kTwoPi * turns;
      const double dp = a.reals("final_states")[i * AW_STATE_REALS + 3 + c] - b.reals("final_states")[i * AW_STATE_REALS + 3 + c];
      sum += dx * dx + dp * dp;
    }
  }
  return std::sqrt(sum / kFglTrajectories);
}

}  // namespace

TEST_SUITE("models") {
  TEST_CASE("fgl: the energy error stays bounded over 1e5 steps (yoshida6a, h = 0.01 T, cpu backend)") {
    const Scene s = fgl_scene("yoshida6a", 0.01, 1000, {"observe.energy_error={ every = 10 }"});
    const Plan plan = make_plan(s);
    CHECK(plan.steps_per_trajectory == 100000);
    const Result r = awtest::run_on("cpu", plan);
    std::printf("models: fgl eps 0.04, 1e5 steps: max |dE| %.3e, flagged %llu\n", r.energy.max,
                static_cast<unsigned long long>(r.flagged()));
    CHECK(r.flagged() == 0);
    CHECK(r.energy.max < 1e-10);
    CHECK(r.energy.max > 0);
  }

  TEST_CASE("fgl: leapfrog and pefrl converge at orders 2 and 4 (within 0.2, final states after 1 T)") {
    const Result ref = awtest::run_on("cpu", make_plan(fgl_scene("kahan-li-s15", 1.0 / 400, 1)));
    struct Row {
      std::string method;
      int order;
      std::vector<int> steps;
    };
    for (const Row& row : {Row{"leapfrog", 2, {50, 100, 200, 400}}, Row{"pefrl", 4, {25, 50, 100, 200}}}) {
      CAPTURE(row.method);
      std::vector<double> err;
      for (int n : row.steps) err.push_back(rms_distance(awtest::run_on("cpu", make_plan(fgl_scene(row.method, 1.0 / n, 1))), ref));
      double mx = 0, my = 0;
      for (std::size_t i = 0; i < err.size(); ++i) mx += std::log(1.0 / row.steps[i]), my += std::log(err[i]);
      mx /= err.size(), my /= err.size();
      double sxy = 0, sxx = 0;
      for (std::size_t i = 0; i < err.size(); ++i) {
        const double x = std::log(1.0 / row.steps[i]) - mx;
        sxy += x * (std::log(err[i]) - my), sxx += x * x;
      }
      const double order = sxy / sxx;
      std::printf("models: fgl %-9s errors %.2e .. %.2e, fitted order %.3f\n", row.method.c_str(), err.front(),
                  err.back(), order);
      CHECK(std::fabs(order - row.order) < 0.2);
      CHECK(err.back() > 1e-12);  // above round-off: the fit measures the method
    }
  }
}
