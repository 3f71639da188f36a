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

#include "aw_cpp_std.h"
#include "aw_params.h"
#include "physics/models.hpp"
#include "plan/kernel_params.hpp"
#include "support.hpp"

// The device core's models compiled here in double, one namespace each (as
// lib/src/physics/models.cpp does).
namespace tm_base {
#include "aw_math.h"
#include "aw_state.h"
#include "models/aw_kinetic.h"
}  // namespace tm_base
namespace tm_seibert2011 {
using namespace tm_base;
#include "models/aw_seibert2011.h"
}  // namespace tm_seibert2011
namespace tm_fgl {
using namespace tm_base;
#include "models/aw_fgl.h"
}  // namespace tm_fgl
namespace tm_fourier {
using namespace tm_base;
#include "models/aw_fourier.h"
}  // namespace tm_fourier

using namespace arnoldweb;

namespace {

constexpr double kTwoPi = 6.283185307179586476925;

// One model's functions at a point (u in turns).
struct ModelFns {
  std::string name;
  double (*potential)(double, double, double, const tm_base::aw_rparams*);
  void (*force_hessian)(tm_base::aw_lstate*, const tm_base::aw_rparams*, double*);
  void (*force)(tm_base::aw_lstate*, const tm_base::aw_rparams*);
  double (*kinetic)(double, double, double, const tm_base::aw_rparams*);
  double (*speed)(double, double, double, double, const tm_base::aw_rparams*, double*);
  void (*kinetic_diag)(const tm_base::aw_rparams*, double*);
};

// The kernel parameters a scene gives a model (the host's model table fills them).
tm_base::aw_rparams params_of(const std::string& kind, const std::vector<std::string>& sets) {
  std::vector<std::string> all = {awtest::set("model.kind", kind)};
  all.insert(all.end(), sets.begin(), sets.end());
  const Scene s = awtest::scene_from("", all, "<models>");
  detail::RealParams rp{};
  detail::model_of(s).fill(s, rp);
  tm_base::aw_rparams out;
  static_assert(sizeof out == sizeof rp, "one layout");
  std::memcpy(&out, &rp, sizeof out);
  return out;
}

const std::vector<std::pair<ModelFns, tm_base::aw_rparams>>& cases() {
  static const std::vector<std::pair<ModelFns, tm_base::aw_rparams>> c = {
      {{"seibert2011", tm_seibert2011::aw_model_potential, tm_seibert2011::aw_model_force_hessian,
        tm_seibert2011::aw_model_force, tm_seibert2011::aw_model_kinetic, tm_seibert2011::aw_model_speed,
        tm_seibert2011::aw_model_kinetic_diag},
       params_of("seibert2011", {})},
      {{"fgl", tm_fgl::aw_model_potential, tm_fgl::aw_model_force_hessian, tm_fgl::aw_model_force,
        tm_fgl::aw_model_kinetic, tm_fgl::aw_model_speed, tm_fgl::aw_model_kinetic_diag},
       params_of("fgl", {"model.epsilon=0.04"})},
      {{"fourier", tm_fourier::aw_model_potential, tm_fourier::aw_model_force_hessian, tm_fourier::aw_model_force,
        tm_fourier::aw_model_kinetic, tm_fourier::aw_model_speed, tm_fourier::aw_model_kinetic_diag},
       params_of("fourier", {"model.harmonics=[[1, 0, 0, 0.7, 0.3], [2, -1, 3, -0.2, 1.1], [0, 1, 1, 0.45, -2]]",
                             "model.kinetic_a=[1, 0.5, 0]", "model.kinetic_b=[0, 0.25, 1]"})},
  };
  return c;
}

tm_base::aw_lstate at(double ux, double uy, double uz) {
  tm_base::aw_lstate s{};
  s.ux = ux, s.uy = uy, s.uz = uz;
  return s;
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
  TEST_CASE("every model: force = -grad V and the Hessian = d^2V (finite differences), the same force from both") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> uni(-0.5, 0.5);
    for (const auto& model_case : cases()) {
      const auto& m = model_case.first;  // (not a structured binding: clang 14 cannot capture those)
      const auto& rp = model_case.second;
      CAPTURE(m.name);
      double worst_f = 0, worst_h = 0;
      for (int t = 0; t < 200; ++t) {
        const std::array<double, 3> u = {uni(rng), uni(rng), uni(rng)};
        auto V = [&, &m = m, &rp = rp](const std::array<double, 3>& v) { return m.potential(v[0], v[1], v[2], &rp); };
        tm_base::aw_lstate s = at(u[0], u[1], u[2]), s2 = s;
        double hess[6];
        m.force_hessian(&s, &rp, hess);
        m.force(&s2, &rp);
        CHECK(s.fx == s2.fx);  // bit for bit: the same operations
        CHECK(s.fy == s2.fy);
        CHECK(s.fz == s2.fz);
        const double f[3] = {s.fx, s.fy, s.fz};
        for (int i = 0; i < 3; ++i) worst_f = std::max(worst_f, std::fabs(f[i] + derivative(V, u, i)));
        // the Hessian as -dF_j/dx_i
        const int index[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
        for (int j = 0; j < 3; ++j) {
          auto Fj = [&, &m = m, &rp = rp](const std::array<double, 3>& v) {
            tm_base::aw_lstate q = at(v[0], v[1], v[2]);
            m.force(&q, &rp);
            return j == 0 ? q.fx : j == 1 ? q.fy : q.fz;
          };
          for (int i = 0; i < 3; ++i) worst_h = std::max(worst_h, std::fabs(hess[index[i][j]] + derivative(Fj, u, i)));
        }
      }
      std::printf("models: %-12s max |F + dV/dx| %.2e, max |Hess - d^2V| %.2e (200 points, 4th-order differences)\n",
                  m.name.c_str(), worst_f, worst_h);
      CHECK(worst_f < 1e-10);
      CHECK(worst_h < 1e-9);
    }
  }

  TEST_CASE("fourier with the paper's six harmonics agrees with seibert2011 to round-off in V, force and Hessian") {
    const tm_base::aw_rparams paper = params_of("fourier", {});  // the default harmonics
    const tm_base::aw_rparams none{};
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> uni(-0.5, 0.5);
    double worst = 0;
    for (int t = 0; t < 10000; ++t) {
      const double ux = uni(rng), uy = uni(rng), uz = uni(rng);
      worst = std::max(worst, std::fabs(tm_fourier::aw_model_potential(ux, uy, uz, &paper) -
                                        tm_seibert2011::aw_model_potential(ux, uy, uz, &none)));
      tm_base::aw_lstate a = at(ux, uy, uz), b = a;
      double ha[6], hb[6];
      tm_fourier::aw_model_force_hessian(&a, &paper, ha);
      tm_seibert2011::aw_model_force_hessian(&b, &none, hb);
      worst = std::max({worst, std::fabs(a.fx - b.fx), std::fabs(a.fy - b.fy), std::fabs(a.fz - b.fz)});
      for (int i = 0; i < 6; ++i) worst = std::max(worst, std::fabs(ha[i] - hb[i]));
    }
    std::printf("models: fourier (6 harmonics) vs seibert2011: max difference %.2e over 10000 points\n", worst);
    CHECK(worst < 1e-14);
    CHECK(worst > 0);  // different operations: equal to round-off, not bit for bit
    // and the same kinetic energy, drift diagonal and speed
    double a[3];
    tm_fourier::aw_model_kinetic_diag(&paper, a);
    CHECK(a[0] == 1.0);
    CHECK(a[1] == 1.0);
    CHECK(a[2] == 1.0);
    CHECK(tm_fourier::aw_model_kinetic(0.3, -1.2, 2.5, &paper) == doctest::Approx(0.5 * (0.09 + 1.44 + 6.25)).epsilon(1e-15));
  }

  TEST_CASE("the general kinetic form: the speed puts the state on T(s n) = ke at the first crossing, or says none") {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> uni(-1.0, 1.0);
    for (const auto& model_case : cases()) {
      const auto& m = model_case.first;  // (not a structured binding: clang 14 cannot capture those)
      const auto& rp = model_case.second;
      CAPTURE(m.name);
      double diag[3];
      m.kinetic_diag(&rp, diag);
      int reached = 0, refused = 0;
      for (int t = 0; t < 20000; ++t) {
        double n[3] = {uni(rng), uni(rng), uni(rng)};
        const double r = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (r < 1e-3) continue;
        for (double& c : n) c /= r;
        const double ke = 2 * uni(rng);
        double ok = 0;
        const double s = m.speed(ke, n[0], n[1], n[2], &rp, &ok);
        // T along the ray is A s^2/2 + B s (A from the diagonal, B = T(n) - A/2)
        const double A = diag[0] * n[0] * n[0] + diag[1] * n[1] * n[1] + diag[2] * n[2] * n[2];
        const double B = m.kinetic(n[0], n[1], n[2], &rp) - 0.5 * A;
        if (ok != 0) {
          ++reached;
          REQUIRE(s > 0);
          // to round-off of the terms (the linear and quadratic parts may cancel)
          const double t = m.kinetic(s * n[0], s * n[1], s * n[2], &rp);
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
      std::printf("models: %-12s speed: %d reached, %d without a crossing\n", m.name.c_str(), reached, refused);
      CHECK(reached > 0);
    }
  }

  TEST_CASE("the kinetic diagonal a_i: seibert2011 (1, 1, 1), fgl (1, 1, 0), fourier model.kinetic_a") {
    double a[3];
    tm_seibert2011::aw_model_kinetic_diag(&cases()[0].second, a);
    CHECK((a[0] == 1 && a[1] == 1 && a[2] == 1));
    tm_fgl::aw_model_kinetic_diag(&cases()[1].second, a);
    CHECK((a[0] == 1 && a[1] == 1 && a[2] == 0));
    tm_fourier::aw_model_kinetic_diag(&cases()[2].second, a);
    CHECK((a[0] == 1 && a[1] == 0.5 && a[2] == 0));
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
    REQUIRE(a.final_i[i * AW_STATE_INTS + 3] == AW_STATUS_OK);
    for (int c = 0; c < 3; ++c) {
      const double turns = static_cast<double>(a.final_i[i * AW_STATE_INTS + c] - b.final_i[i * AW_STATE_INTS + c]) +
                           (a.final_r[i * AW_STATE_REALS + c] - b.final_r[i * AW_STATE_REALS + c]);
      const double dx = kTwoPi * turns;
      const double dp = a.final_r[i * AW_STATE_REALS + 3 + c] - b.final_r[i * AW_STATE_REALS + 3 + c];
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
