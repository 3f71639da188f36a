// The diffusion estimator (arnoldweb/diffusion.hpp): a synthetic random walk
// of known D is recovered within its bootstrap error bar, and the error bar
// is honest over many seeds (coverage); a drift without diffusion gives D = 0;
// ballistic spreading shows in the half-range slopes; the growth's linearity
// (the exponent alpha of Var ~ t^alpha) passes linear growth and flags
// t^0.5 and t^2, in the fit, summary.json, diffusion.csv and on stderr; the
// moments of a tiny ensemble by hand; degenerate inputs are clear errors; the
// bootstrap is reproducible.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "arnoldweb/diffusion.hpp"
#include "support.hpp"

using namespace arnoldweb;

namespace {

// n random walks in 3 actions, times 0, dt, ..., (times - 1) dt: along e =
// (1, 1, 0)/sqrt 2 with diffusion coefficient d_along (steps of variance
// 2 d dt) and a common drift v, across f = (1, -1, 0)/sqrt 2 with d_across,
// and I3 with d_across too; starts spread uniformly over a square of 1e-3.
ActionSamples random_walks(std::size_t n, std::size_t times, double dt, double d_along, double d_across, double v,
                           std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> start(0.3, 0.301);
  ActionSamples s;
  s.trajectories = n;
  s.times = times;
  s.dim = 3;
  for (std::size_t k = 0; k < times; ++k) s.t.push_back(k * dt);
  s.actions.resize(n * times * 3);
  const double r = 1 / std::sqrt(2.0);
  for (std::size_t i = 0; i < n; ++i) {
    double a = 0, c = 0, z = 0;  // along, across, I3 displacements
    const double x0 = start(rng), y0 = start(rng), z0 = start(rng);
    for (std::size_t k = 0; k < times; ++k) {
      if (k > 0) {
        a += v * dt + std::sqrt(2 * d_along * dt) * gauss(rng);
        c += std::sqrt(2 * d_across * dt) * gauss(rng);
        z += std::sqrt(2 * d_across * dt) * gauss(rng);
      }
      double* I = &s.actions[(i * times + k) * 3];
      I[0] = x0 + r * (a + c);
      I[1] = y0 + r * (a - c);
      I[2] = z0 + z;
    }
  }
  return s;
}

const std::vector<double> kAlong = {1, 1, 0}, kAcross = {1, -1, 0};

// n trajectories whose displacement along (1, 1, 0)/sqrt 2 is x_i (t - t0)^(alpha / 2) plus a
// random walk of diffusion coefficient d (x of variance 1e-6), at times t0, t0 + 10, ...: the
// variance grows like (t - t0)^alpha (and 2 d t).
ActionSamples power_growth(double alpha, double d, std::size_t n, std::size_t times, double t0, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss;
  ActionSamples s;
  s.trajectories = n;
  s.times = times;
  s.dim = 3;
  s.t.push_back(t0);
  for (std::size_t k = 1; k < times; ++k) s.t.push_back(t0 + 10.0 * k);
  const double r = 1 / std::sqrt(2.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = 1e-3 * gauss(rng);
    double walk = 0;
    for (std::size_t k = 0; k < times; ++k) {
      if (k > 0) walk += std::sqrt(2 * d * 10.0) * gauss(rng);
      const double a = x * std::pow(s.t[k] - t0, alpha / 2) + walk;
      s.actions.insert(s.actions.end(), {0.3 + r * a, 0.3 + r * a, 0.0});
    }
  }
  return s;
}

bool throws_with(const std::function<void()>& f, const std::string& part) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    const bool ok = std::string(e.what()).find(part) != std::string::npos;
    if (!ok) MESSAGE("message: " << e.what());
    return ok;
  }
  return false;
}

}  // namespace

TEST_SUITE("diffusion") {
  TEST_CASE("a random walk of known D: recovered within its error bar, along and across, with its drift") {
    const double d_along = 2.5e-3, d_across = 1e-4, v = 0.05;
    const ActionSamples s = random_walks(500, 41, 1.0, d_along, d_across, v, 7);
    const DiffusionFit along = fit_diffusion(s, kAlong);
    const DiffusionFit across = fit_diffusion(s, kAcross);
    MESSAGE("along: D = " << along.D << " +- " << along.D_error << " (true " << d_along << "), drift " << along.drift
                          << "; across: D = " << across.D << " +- " << across.D_error << " (true " << d_across << ")");
    CHECK(std::fabs(along.D - d_along) < 3 * along.D_error);
    CHECK(std::fabs(across.D - d_across) < 3 * across.D_error);
    CHECK(along.D_error < 0.15 * d_along);  // 500 walks: a useful error bar
    CHECK(along.D_error > 0.01 * d_along);  // and not an absurdly small one
    CHECK(along.D_low < along.D);
    CHECK(along.D < along.D_high);
    // the drift's own noise: the mean of 500 walks is a walk of D / 500; 4 sigma over 40 T
    const double drift_sigma = std::sqrt(2 * d_along * 40 / 500) / 40;
    CHECK(std::fabs(along.drift - v) < 4 * drift_sigma);
    CHECK(std::fabs(across.drift) < 4 * drift_sigma);
    CHECK(along.used == 500);
    CHECK(along.excluded == 0);
    CHECK(along.first == 0);
    CHECK(along.last == 40);
    // the moments: the along variance is the fitted curve; across = complement (f and I3)
    const DiffusionMoments m = diffusion_moments(s, {kAlong, {}});
    // (the variance of 500 samples is known to sqrt(2/500) = 6%: 20% is over 3 sigma)
    auto near = [](double x, double expected, double rel) { return std::fabs(x - expected) < rel * expected; };
    CHECK(near(m.along_variance[40], 2 * d_along * 40, 0.2));
    CHECK(near(m.across_variance[40], 2 * 2 * d_across * 40, 0.2));
    const DiffusionMoments mf = diffusion_moments(s, {kAlong, kAcross});
    CHECK(near(mf.across_variance[40], 2 * d_across * 40, 0.2));
    CHECK(std::fabs(mf.along_mean[40] - v * 40) < 4 * drift_sigma * 40);
  }

  TEST_CASE("the error bar is honest: over 40 seeds about 68% of the estimates lie within one, 95% within two") {
    const double d = 1e-3;
    int within1 = 0, within2 = 0;
    const int seeds = 40;
    for (int seed = 0; seed < seeds; ++seed) {
      DiffusionOptions o;
      o.replicates = 100;
      o.seed = 1000 + seed;
      const DiffusionFit f = fit_diffusion(random_walks(200, 21, 1.0, d, 1e-4, 0.0, 100 + seed), kAlong, o);
      within1 += std::fabs(f.D - d) <= f.D_error;
      within2 += std::fabs(f.D - d) <= 2 * f.D_error;
    }
    MESSAGE("coverage: " << within1 << "/" << seeds << " within 1 sigma, " << within2 << "/" << seeds
                         << " within 2 sigma");
    // binomial(40, 0.68): 27 +- 3; (40, 0.95): 38 +- 1.4
    CHECK(within1 >= 19);
    CHECK(within1 <= 35);
    CHECK(within2 >= 33);
  }

  TEST_CASE("a drift without diffusion gives D = 0; spreading drifts show as a steeper second half") {
    // every trajectory I = I0 + v t (I0 spread): the centred variance does not grow
    ActionSamples s;
    s.trajectories = 50;
    s.times = 11;
    s.dim = 2;
    for (std::size_t k = 0; k < 11; ++k) s.t.push_back(10.0 * k);
    for (std::size_t i = 0; i < 50; ++i)
      for (std::size_t k = 0; k < 11; ++k) {
        s.actions.push_back(0.3 + 1e-4 * i + 2e-3 * s.t[k]);
        s.actions.push_back(0.3 - 3e-5 * i + 2e-3 * s.t[k]);
      }
    const DiffusionFit f = fit_diffusion(s, {1, 1});
    MESSAGE("drift only: D = " << f.D << " +- " << f.D_error << ", drift " << f.drift);
    CHECK(std::fabs(f.D) < 1e-15);
    CHECK(f.D_error < 1e-15);
    CHECK(std::fabs(f.drift - 2e-3 * std::sqrt(2.0)) < 1e-15);
    // different drifts per trajectory: sigma^2 ~ t^2, not diffusion
    for (std::size_t i = 0; i < 50; ++i)
      for (std::size_t k = 0; k < 11; ++k) s.actions[(i * 11 + k) * 2] += 1e-5 * i * s.t[k];
    const DiffusionFit b = fit_diffusion(s, {1, 0});
    MESSAGE("ballistic: slopes " << b.slope_first_half << " then " << b.slope_second_half);
    CHECK(b.slope_second_half > 2 * b.slope_first_half);
  }

  TEST_CASE("the growth's linearity: linear growth is diffusive, t^0.5 and t^2 are not") {
    // random walks: Var = 2 D t
    const DiffusionFit walk = fit_diffusion(random_walks(500, 41, 1.0, 2.5e-3, 1e-4, 0.0, 7), kAlong);
    MESSAGE("random walks: alpha = " << walk.alpha << " +- " << walk.alpha_error << ", D of the halves "
                                     << walk.D_first_half << ", " << walk.D_second_half);
    CHECK(std::fabs(walk.alpha - 1) < 3 * walk.alpha_error);
    CHECK(walk.alpha_error > 0);
    CHECK(walk.alpha_error < 0.2);
    CHECK(walk.diffusive);
    CHECK(walk.D_first_half == walk.slope_first_half / 2);
    CHECK(walk.D_second_half == walk.slope_second_half / 2);
    // t^alpha from a later start (a continued run): the exponent from the first sample time
    for (const double alpha : {0.5, 1.0, 2.0}) {
      CAPTURE(alpha);
      DiffusionOptions o;
      o.t_min = 1000 + 100;
      const DiffusionFit f = fit_diffusion(power_growth(alpha, 1e-12, 400, 101, 1000.0, 3), kAlong, o);
      MESSAGE("Var ~ t^" << alpha << ": alpha = " << f.alpha << " +- " << f.alpha_error << ", D of the halves "
                         << f.D_first_half << ", " << f.D_second_half << ", diffusive " << f.diffusive);
      CHECK(std::fabs(f.alpha - alpha) < 0.05);
      CHECK(f.diffusive == (alpha == 1.0));
    }
    // a variance that does not grow: no exponent, not diffusive
    const DiffusionFit flat = fit_diffusion(power_growth(0.0, 0.0, 100, 21, 0.0, 5), kAlong);
    CHECK(std::isnan(flat.alpha));
    CHECK_FALSE(flat.diffusive);
  }

  TEST_CASE("a run whose variance does not grow linearly: the warning in summary.json, on stderr, and the "
            "linearity in diffusion.csv") {
    // the D(eps) scene at eps = 0 (integrable): the actions do not move, the variance stays 0
    const std::string dir = awtest::temp_dir("diffusion-warning");
    std::string out;
    REQUIRE(awtest::run_cli({"run", std::string(ARNOLDWEB_SOURCE_DIR) + "/scenes/fgl_diffusion.toml", "--quiet",
                             "--device", "cpu", "--out", dir + "/out", "--set", "model.epsilon=0",
                             "--set", "ensemble.grid.resolution=[4,4]", "--set", "run.duration=20.48", "--set",
                             "run.average=20.48", "--set", "observe.energy_error.every=1.28", "--set",
                             "observe.diffusion={ every = 1.28, along = [1, 1, 0], across = [1, -1, 0], fit_from = 2.56 }",
                             "--set", "output.images=false"},
                            &out) == 0);
    CHECK(out.find("arnoldweb: warning: observe.diffusion: the variance along the resonance does not grow") !=
          std::string::npos);
    std::ifstream in(dir + "/out/summary.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    const nlohmann::json& fit = j["analyses"]["diffusion"]["along_fit"];
    CHECK(fit["alpha"].is_null());
    CHECK(fit["diffusive"] == false);
    bool listed = false;
    for (const auto& w : j["warnings"]) listed = listed || w.get<std::string>().find("not diffusive") != std::string::npos;
    CHECK(listed);
    std::ifstream csv(dir + "/out/diffusion.csv");
    std::string header;
    std::getline(csv, header);
    CHECK(header == "t,along_mean,along_variance,across_variance,along_D,along_D_error,along_D_first_half,"
                    "along_D_second_half,along_alpha,along_alpha_error,across_D,across_D_error,across_D_first_half,"
                    "across_D_second_half,across_alpha,across_alpha_error");
    std::string row;
    std::getline(csv, row);
    CHECK(std::count(row.begin(), row.end(), ',') == 15);
  }

  TEST_CASE("the moments of a tiny ensemble, by hand") {
    // two trajectories, three times, two actions
    ActionSamples s;
    s.trajectories = 2;
    s.times = 3;
    s.dim = 2;
    s.t = {0, 1, 2};
    s.actions = {0, 0, 1, 0, 2, 2,    // trajectory 0: dI(1) = (1, 0), dI(2) = (2, 2)
                 5, 5, 5, 6, 4, 5};   // trajectory 1: dI(1) = (0, 1), dI(2) = (-1, 0)
    const DiffusionMoments m = diffusion_moments(s, {{1, 0}, {}});
    CHECK(m.mean == std::vector<double>{0, 0, 0.5, 0.5, 0.5, 1});
    // <dI dI^T> at t = 2: ((4 + 1)/2, (4 + 0)/2; 2, (4 + 0)/2)
    CHECK(m.second[8] == 2.5);
    CHECK(m.second[9] == 2);
    CHECK(m.second[10] == 2);
    CHECK(m.second[11] == 2);
    // covariance = second - mean mean^T: (2.5 - 0.25, 2 - 0.5; ., 2 - 1)
    CHECK(m.covariance[8] == 2.25);
    CHECK(m.covariance[9] == 1.5);
    CHECK(m.covariance[11] == 1);
    CHECK(m.along_mean[2] == 0.5);
    CHECK(m.along_variance[2] == 2.25);
    CHECK(m.along_square[2] == 2.5);
    CHECK(m.across_variance[2] == 1);
  }

  TEST_CASE("degenerate inputs are clear errors; non-finite trajectories are left out and counted") {
    const ActionSamples good = random_walks(10, 5, 1.0, 1e-3, 1e-3, 0, 3);
    auto fit = [](const ActionSamples& s, std::vector<double> e = {1, 1, 0}, DiffusionOptions o = {}) {
      return [=] { fit_diffusion(s, e, o); };
    };
    ActionSamples a = good;
    a.actions.pop_back();
    CHECK(throws_with(fit(a), "expected trajectories x times x dim = 10 x 5 x 3"));
    a = good;
    a.t[3] = a.t[2];
    CHECK(throws_with(fit(a), "must increase strictly"));
    a = good;
    a.times = 1;
    a.t.resize(1);
    a.actions.resize(10 * 3);
    CHECK(throws_with(fit(a), "at least 2 sample times"));
    CHECK(throws_with(fit(good, {0, 0, 0}), "zero vector"));
    CHECK(throws_with(fit(good, {1, 1}), "has 2 components, expected 3"));
    DiffusionOptions late;
    late.t_min = 3.5;
    CHECK(throws_with(fit(good, {1, 1, 0}, late), "at least 2 sample times in [t_min, t_max]"));
    DiffusionOptions negative;
    negative.replicates = -1;
    CHECK(throws_with(fit(good, {1, 1, 0}, negative), "replicates must be >= 0"));
    CHECK(throws_with([&] { diffusion_moments(good, {{1, 1, 0}, {2, 2, 0}}); }, "parallel"));
    a = good;
    for (std::size_t i = 0; i < 9; ++i) a.actions[i * 15 + 7] = std::numeric_limits<double>::quiet_NaN();
    CHECK(throws_with(fit(a), "at least 2 trajectories with finite actions, got 1 of 10"));
    // one flagged trajectory: left out and counted, the rest as without it
    a = good;
    a.actions[4 * 15 + 7] = std::numeric_limits<double>::infinity();
    const DiffusionFit f = fit_diffusion(a, {1, 1, 0});
    CHECK(f.used == 9);
    CHECK(f.excluded == 1);
    ActionSamples without = good;
    without.trajectories = 9;
    without.actions.erase(without.actions.begin() + 4 * 15, without.actions.begin() + 5 * 15);
    CHECK(fit_diffusion(without, {1, 1, 0}).D == f.D);
  }

  TEST_CASE("the bootstrap is reproducible: the same seed gives the same error bar, another seed another") {
    const ActionSamples s = random_walks(100, 11, 1.0, 1e-3, 1e-4, 0, 5);
    DiffusionOptions o;
    o.seed = 11;
    const DiffusionFit a = fit_diffusion(s, kAlong, o), b = fit_diffusion(s, kAlong, o);
    o.seed = 12;
    const DiffusionFit c = fit_diffusion(s, kAlong, o);
    CHECK(a.D_error == b.D_error);
    CHECK(a.D_low == b.D_low);
    CHECK(a.D_error != c.D_error);
    CHECK(a.D == c.D);  // the estimate itself does not depend on the bootstrap
  }
}
