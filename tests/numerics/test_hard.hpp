// arnoldweb tests, suite "hard": what the hard-case test files share.
//
// - The model in long double, in radians, never wrapped: an independent
//   implementation (libm's sinl/cosl, no turns, no winding counts) of the
//   same Hamiltonian H = |P|^2/2 + 2 cos x cos y cos^2 z.
// - A splitting step in long double that runs a method's coefficient table
//   exactly as the plan hands it to the kernels (the same double-rounded
//   drift and kick coefficients), so that the only differences from the core
//   are rounding and the wrapping.
// - Hand-made states of the core (core_d, tests/support/core_double.hpp) and their
//   unwrapped positions.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"
#include "arnoldweb/scene.hpp"
#include "aw_params.h"
#include "core_double.hpp"
#include "support.hpp"

namespace hard {

constexpr long double kTwoPiL = 6.283185307179586476925286766559005768L;

// Phase-space point in radians (unwrapped) and momentum.
struct LdState {
  long double x[3];
  long double p[3];
};

// F = -grad V in long double.
inline void ld_force(const long double* x, long double* f) {
  long double sx, cx, sy, cy, sz, cz;
  sincosl(x[0], &sx, &cx);
  sincosl(x[1], &sy, &cy);
  sincosl(x[2], &sz, &cz);
  f[0] = 2 * sx * cy * cz * cz;
  f[1] = 2 * cx * sy * cz * cz;
  f[2] = 4 * cx * cy * sz * cz;
}

inline long double ld_potential(const long double* x) {
  const long double cz = cosl(x[2]);
  return 2 * cosl(x[0]) * cosl(x[1]) * cz * cz;
}

inline long double ld_energy(const LdState& s) {
  return (s.p[0] * s.p[0] + s.p[1] * s.p[1] + s.p[2] * s.p[2]) / 2 + ld_potential(s.x);
}

// A plan's method and step, in long double radians, without wrapping: drift
// x += (2 pi rp.drift[i]) p, kick p += rp.kick[i] F. Kicks at
// step boundaries are not merged (the same map up to one rounding).
class LdSplitting {
 public:
  explicit LdSplitting(const arnoldweb::Plan& plan) : kick_first_(plan.method.kick_first) {
    const int s = plan.method.stages;
    const int drifts = kick_first_ ? s : s + 1;
    for (int i = 0; i < drifts; ++i) drift_.push_back(kTwoPiL * arnoldweb::detail::params(plan).reals.drift[i]);
    for (int i = 0; i <= s; ++i) kick_.push_back(arnoldweb::detail::params(plan).reals.kick[i]);
  }

  void step(LdState& s) const {
    if (kick_first_) {
      kick(s, kick_[0]);
      for (std::size_t i = 0; i < drift_.size(); ++i) {
        drift(s, drift_[i]);
        kick(s, kick_[i + 1]);
      }
    } else {
      for (std::size_t i = 0; i + 1 < drift_.size(); ++i) {
        drift(s, drift_[i]);
        kick(s, kick_[i + 1]);
      }
      drift(s, drift_.back());
    }
  }

 private:
  static void drift(LdState& s, long double d) {
    for (int c = 0; c < 3; ++c) s.x[c] += d * s.p[c];
  }
  static void kick(LdState& s, long double k) {
    long double f[3];
    ld_force(s.x, f);
    for (int c = 0; c < 3; ++c) s.p[c] += k * f[c];
  }
  bool kick_first_;
  std::vector<long double> drift_, kick_;
};

// A state of the core from wrapped turns and momentum (force computed).
inline core_d::aw_lstate core_state(const double u[3], const double p[3]) {
  core_d::aw_lstate s{};
  s.ux = u[0];
  s.uy = u[1];
  s.uz = u[2];
  s.px = p[0];
  s.py = p[1];
  s.pz = p[2];
  core_d::aw_force(&s);
  return s;
}

// A state on the shell of energy E at position u (turns) with momentum along
// direction d (any length).
inline core_d::aw_lstate shell_state(double energy, const double u[3], const double d[3]) {
  const double v = core_d::aw_potential(u[0], u[1], u[2]);
  const double pm = std::sqrt(2 * (energy - v));
  const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  const double p[3] = {pm * d[0] / n, pm * d[1] / n, pm * d[2] / n};
  return core_state(u, p);
}

// The same point for the long-double model: x = 2 pi u.
inline LdState to_ld(const core_d::aw_lstate& s) {
  LdState l;
  const double u[3] = {s.ux, s.uy, s.uz};
  const std::int64_t w[3] = {s.wx, s.wy, s.wz};
  const double p[3] = {s.px, s.py, s.pz};
  for (int c = 0; c < 3; ++c) {
    l.x[c] = kTwoPiL * (static_cast<long double>(w[c]) + u[c]);
    l.p[c] = p[c];
  }
  return l;
}

// Unwrapped position of the core in radians: X = 2 pi (w + u), in long double
// (w + u rounds to 2^-63 |w|: 7e-15 turns at |w| = 5e4).
inline long double unwrapped(const core_d::aw_lstate& s, int c) {
  const double u = c == 0 ? s.ux : c == 1 ? s.uy : s.uz;
  const std::int64_t w = c == 0 ? s.wx : c == 1 ? s.wy : s.wz;
  return kTwoPiL * (static_cast<long double>(w) + u);
}

// Phase-space distance |dX| + |dP| (Euclidean in each) between the core and a
// long-double state.
inline double distance(const core_d::aw_lstate& s, const LdState& l) {
  long double dx2 = 0, dp2 = 0;
  const double p[3] = {s.px, s.py, s.pz};
  for (int c = 0; c < 3; ++c) {
    const long double dx = unwrapped(s, c) - l.x[c];
    const long double dp = p[c] - l.p[c];
    dx2 += dx * dx;
    dp2 += dp * dp;
  }
  return static_cast<double>(sqrtl(dx2) + sqrtl(dp2));
}

// ------------------------------------------------------------ hard orbits
// A fixed set of orbits, each one trajectory of a scene's own ensemble (seed
// 2026, the trajectory `index`), so that the same orbit can be run through
// the core here and through every backend. Their character was measured from
// the growth of a 1e-12 perturbation (docs/numerics.md) and is checked again
// by the tests that rely on it.
struct Orbit {
  const char* name;
  double energy;
  double step;        // in T: the paper's 0.01 T, or a safe step at E = 400
  bool at_w;          // Gaussian momenta about W = (sqrt E, sqrt E, 0), sigma 0.01 (Figure 4)
  std::uint64_t index;
};

inline const Orbit kRegular15{"regular, E = 15", 15.0, 0.01, false, 35};
inline const Orbit kChaotic15{"chaotic, E = 15 (at W)", 15.0, 0.01, true, 0};
inline const Orbit kWell{"near the well bottom, E = -1.9", -1.9, 0.01, false, 0};
inline const Orbit kRegular400{"regular, E = 400", 400.0, 0.0025, false, 0};
inline const Orbit kChaotic400{"chaotic, E = 400", 400.0, 0.0025, false, 13};
inline const Orbit kSaddle{"saddle level, E = 0", 0.0, 0.01, false, 0};
inline const Orbit kTop{"maximum level, E = 2", 2.0, 0.01, false, 0};

// The orbit's ensemble, run for `duration` T as one window with |dE| sampled
// every `every` T, initial and final states recorded.
inline arnoldweb::Scene orbit_scene(const Orbit& o, double duration, double every = 1.0) {
  std::vector<std::string> sets = {awtest::set("model.energy", o.energy),
                                   awtest::set("ensemble.trajectories", o.index + 1),
                                   awtest::set("integrator.step", o.step),
                                   awtest::set("run.average", duration),
                                   awtest::set("run.duration", duration),
                                   awtest::set("observe.energy_error.every", every)};
  if (o.at_w) {
    const double w = std::sqrt(o.energy);
    sets.push_back("ensemble.initial=\"gaussian\"");
    sets.push_back(awtest::set("ensemble.gaussian.mean", std::array<double, 2>{w, w}));
    sets.push_back("ensemble.gaussian.sigma=[0.01, 0.01]");
  }
  return awtest::scene_from(R"(
    [ensemble]
    seed = 2026
    [observe]
    velocity_map = false
    initial_states = true
    final_states = true
  )", sets, "<hard orbit>");
}

// The orbit's initial state as the kernels draw it (force computed).
inline core_d::aw_lstate orbit_start(const arnoldweb::Plan& plan, std::uint64_t index) {
  core_d::aw_lstate s;
  core_d::aw_initial_state(&s, plan.kernel.initial, index, core_d::rp_of(plan), core_d::ip_of(plan));
  core_d::aw_force(&s);
  return s;
}

// Steps of the plan per T.
inline std::int64_t steps_per_t(const arnoldweb::Plan& plan) {
  return static_cast<std::int64_t>(std::llround(1.0 / plan.step));
}

// Advance the core by `n` segments of `steps` steps (the kernels' own
// segmentation when `steps` is the plan's steps_per_segment).
inline void advance(core_d::aw_lstate* s, const arnoldweb::Plan& plan, std::int64_t n, std::int64_t steps) {
  for (std::int64_t k = 0; k < n; ++k)
    core_d::aw_segment(s, steps, core_d::rp_of(plan), plan.method.stages, plan.method.kick_first, plan.method.force_gradient());
}

// Growth factor of a perturbation of 1e-12 in p_x after t T, in the core (the
// phase-space distance of the twin over 1e-12): ~linear in t on a regular
// orbit, ~exp(lambda t) on a chaotic one until it saturates at O(1) / 1e-12.
inline std::vector<double> twin_growth(const arnoldweb::Plan& plan, const core_d::aw_lstate& start, int t_max) {
  core_d::aw_lstate a = start, b = start;
  b.px += 1e-12;
  core_d::aw_force(&b);
  const double d0 = distance(a, to_ld(b));
  std::vector<double> g(static_cast<std::size_t>(t_max) + 1, 1.0);
  for (int t = 1; t <= t_max; ++t) {
    advance(&a, plan, 1, steps_per_t(plan));
    advance(&b, plan, 1, steps_per_t(plan));
    g[static_cast<std::size_t>(t)] = distance(a, to_ld(b)) / d0;
  }
  return g;
}

// ------------------------------------------------------------------ drift
// The energy error dE(t) = E(t) - E(0) of one orbit sampled every `every`
// steps for `steps` steps, and a straight line fitted to it.
struct DriftStats {
  double duration = 0;     // in T
  double max_abs = 0;      // max |dE| over the run (the error's amplitude)
  double slope_total = 0;  // least-squares slope of dE against t, times the duration
  double z = 0;            // that slope over its standard error from block means
  double first_max = 0;    // max |dE| in the first and the last of `blocks` blocks
  double last_max = 0;
};

// The envelope of |H - H~| over the shell an orbit belongs to: the largest
// energy error of 512 trajectories started like it, over 100 T on the cpu
// backend. A chaotic orbit's error rises and falls with the region it visits;
// a secular drift would take it beyond this.
inline double shell_envelope(const Orbit& o) {
  arnoldweb::Scene e = orbit_scene(o, 100.0);
  e.trajectories = 512;
  e.initial_states = e.final_states = false;
  return awtest::run_on("cpu", arnoldweb::make_plan(e)).energy.max;
}

inline DriftStats energy_drift(const Orbit& o, std::int64_t steps, std::int64_t every, int blocks = 20) {
  const arnoldweb::Plan plan = arnoldweb::make_plan(orbit_scene(o, 1.0));
  core_d::aw_lstate s = orbit_start(plan, o.index);
  const double e0 = core_d::aw_energy(&s);
  const std::int64_t samples = steps / every, per_block = samples / blocks;
  std::vector<double> block_mean(static_cast<std::size_t>(blocks), 0.0), block_max(static_cast<std::size_t>(blocks), 0.0);
  // running sums for the least-squares line through all samples (t in units of samples)
  long double st = 0, sd = 0, stt = 0, std_ = 0;
  DriftStats r;
  for (std::int64_t i = 0; i < samples; ++i) {
    core_d::aw_segment(&s, every, core_d::rp_of(plan), plan.method.stages, plan.method.kick_first, plan.method.force_gradient());
    const double de = core_d::aw_energy(&s) - e0;
    const long double t = static_cast<long double>(i + 1);
    st += t;
    sd += de;
    stt += t * t;
    std_ += t * de;
    r.max_abs = std::max(r.max_abs, std::fabs(de));
    const std::size_t b = static_cast<std::size_t>(std::min<std::int64_t>(i / per_block, blocks - 1));
    block_mean[b] += de / static_cast<double>(per_block);
    block_max[b] = std::max(block_max[b], std::fabs(de));
  }
  const long double n = static_cast<long double>(samples);
  const long double slope = (n * std_ - st * sd) / (n * stt - st * st);  // per sample
  r.slope_total = static_cast<double>(slope * n);
  // the same slope from the block means, with its standard error (the block
  // means are nearly independent where single samples are not)
  double mb = 0, mx = 0;
  for (int b = 0; b < blocks; ++b) {
    mb += block_mean[static_cast<std::size_t>(b)] / blocks;
    mx += (b + 0.5) / blocks;
  }
  double sxy = 0, sxx = 0;
  for (int b = 0; b < blocks; ++b) {
    sxy += (b + 0.5 - mx) * (block_mean[static_cast<std::size_t>(b)] - mb);
    sxx += (b + 0.5 - mx) * (b + 0.5 - mx);
  }
  const double bslope = sxy / sxx;
  double res = 0;
  for (int b = 0; b < blocks; ++b) {
    const double e = block_mean[static_cast<std::size_t>(b)] - mb - bslope * (b + 0.5 - mx);
    res += e * e;
  }
  const double se = std::sqrt(res / (blocks - 2) / sxx);
  r.z = se > 0 ? bslope / se : 0;
  r.first_max = block_max.front();
  r.last_max = block_max.back();
  r.duration = static_cast<double>(steps) * plan.step;
  return r;
}

// ------------------------------------------------------------ reversal
// Phase-space distance of every trajectory's final state from its initial
// state (positions in radians from winding counts and wrapped turns).
inline std::vector<double> return_errors(const arnoldweb::Result& r) {
  std::vector<double> err;
  for (std::size_t i = 0; i < r.trajectories; ++i) {
    double dx2 = 0, dp2 = 0;
    for (int c = 0; c < 3; ++c) {
      const double turns = static_cast<double>(r.ints("final_states")[i * AW_STATE_INTS + c]) +
                           (r.reals("final_states")[i * AW_STATE_REALS + c] - r.reals("initial_states")[i * AW_STATE_REALS + c]);
      const double dx = 2 * M_PI * turns;
      const double dp = r.reals("final_states")[i * AW_STATE_REALS + 3 + c] - r.reals("initial_states")[i * AW_STATE_REALS + 3 + c];
      dx2 += dx * dx;
      dp2 += dp * dp;
    }
    err.push_back(std::sqrt(dx2) + std::sqrt(dp2));
  }
  return err;
}

inline double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const std::size_t i = std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())));
  return v[i];
}

// Forward t T, P -> -P, t T again, P -> -P, in the core; the distance from the start.
inline double core_return_error(const arnoldweb::Plan& plan, const core_d::aw_lstate& start, int t) {
  core_d::aw_lstate s = start;
  advance(&s, plan, t, steps_per_t(plan));
  s.px = -s.px;
  s.py = -s.py;
  s.pz = -s.pz;
  advance(&s, plan, t, steps_per_t(plan));
  s.px = -s.px;
  s.py = -s.py;
  s.pz = -s.pz;
  return distance(s, to_ld(start));
}

}  // namespace hard
