// arnoldweb: from a validated scene to a plan (schedule, feature mask, buffers).
#include "arnoldweb/plan.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "arnoldweb/accuracy.hpp"
#include "arnoldweb/device.hpp"
#include "arnoldweb/errors.hpp"
#include "arnoldweb/sphere.hpp"
#include "plan/scene_checks.hpp"
#include "aw_model.h"
#include "aw_params.h"
#include "aw_rng.h"

namespace arnoldweb {
namespace {

constexpr double kTwoPi = 6.283185307179586476925;
// Initial positions are drawn by rejection: with accessible fraction f, each
// trajectory tries up to 30/f positions (failure probability e^-30 ~ 1e-13).
constexpr double kMinAccessible = 0.001;
constexpr double kAttemptsTimesFraction = 30.0;
constexpr std::uint64_t kMaxStateRecords = 50'000'000;
// A trajectory has at most this many steps (10^15: years of device time for
// one trajectory; every count derived from it fits 64 bits and exact doubles).
constexpr double kMaxStepsPerTrajectory = 1e15;

std::string fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

using detail::exact_ratio;
[[noreturn]] void fail(const Scene& s, const std::string& key, const std::string& message) {
  detail::fail_at(s, key, message);
}

constexpr double kDeg = M_PI / 180.0;

// Orthonormal frame of the direction at longitude lon, latitude lat (degrees):
// c the direction, e1 east, e2 north.
void frame_of(double lon, double lat, double* out) {
  const TangentFrame f = tangent_frame(lon, lat);
  for (int i = 0; i < 3; ++i) {
    out[i] = f.c[i];
    out[3 + i] = f.east[i];
    out[6 + i] = f.north[i];
  }
}

// A gnomonic square region (aw_params.h layout) of full angular width `width`.
void region_of(const std::array<double, 2>& center, double width, double* out) {
  frame_of(center[0], center[1], out);
  out[9] = std::tan(0.5 * width * kDeg);
}

}  // namespace

namespace detail {

std::int64_t exact_ratio(double x, double unit) {
  const double r = x / unit;
  if (!(r < 9.0e15)) return 0;  // beyond exact integers in a double (and NaN)
  const double n = std::nearbyint(r);
  if (n < 1 || std::fabs(r - n) > 1e-9 * n) return 0;
  return static_cast<std::int64_t>(n);
}

void fail_at(const Scene& s, const std::string& key, const std::string& message) {
  const SourcePos p = s.pos(key);
  if (p.set_index > 0) throw SceneError(s.origin(key), 0, 0, key, message);
  throw SceneError(s.file, p.line, p.column, key, message);
}

}  // namespace detail

std::string KernelConfig::defines() const {
  std::ostringstream o;
  o << "-DAW_FEATURES=" << features << "u -DAW_STAGES=" << stages
    << " -DAW_KICK_FIRST=" << (kick_first ? 1 : 0) << " -DAW_INITIAL=" << initial;
  if (precision == Precision::Float) o << " -DAW_FLOAT";
  if (math == MathMode::Native) o << " -DAW_NATIVE_MATH";
  return o.str();
}

bool KernelConfig::operator==(const KernelConfig& o) const {
  return precision == o.precision && math == o.math && features == o.features &&
         stages == o.stages && kick_first == o.kick_first && initial == o.initial;
}

std::vector<std::string> feature_names(std::uint32_t f) {
  std::vector<std::string> n;
  if (f & AW_F_VELOCITY_MAP) n.push_back("velocity_map");
  if (f & AW_F_ENERGY) n.push_back("energy_error");
  if (f & AW_F_ENERGY_LIMIT) n.push_back("max_energy_error");
  if (f & AW_F_INITIAL_STATES) n.push_back("initial_states");
  if (f & AW_F_FINAL_STATES) n.push_back("final_states");
  if (f & AW_F_TEST_INJECT) n.push_back("test_inject");
  if (f & AW_F_ZOOM) n.push_back("zoom");
  if (f & AW_F_CONFINE) n.push_back("confine");
  if (f & AW_F_FRAMES) n.push_back("frames");
  if (f & AW_F_REVERSE) n.push_back("time_reversal");
  return n;
}

StepGuard step_guard(double energy, double step, double average, double energy_every) {
  StepGuard g;
  g.p_max = std::sqrt(2.0 * (energy + 2.0));
  g.value = step * kTwoPi * 2.0 * g.p_max;
  g.limit = M_PI;
  g.advised = M_PI / 2;
  const double s_max = g.advised / (kTwoPi * 2.0 * g.p_max);
  const double unit = (energy_every > 0 && energy_every <= average) ? energy_every : average;
  // prefer a round number (1, 2, 2.5, 4, 5 x 10^k) that divides the schedule
  for (double decade = std::pow(10.0, std::floor(std::log10(s_max))); decade > 1e-9 * s_max; decade /= 10)
    for (double mantissa : {5.0, 4.0, 2.5, 2.0, 1.0}) {
      const double s = mantissa * decade;
      if (s <= s_max && exact_ratio(unit, s) > 0 && exact_ratio(average, s) > 0) {
        g.safe_step = s;
        return g;
      }
    }
  g.safe_step = unit / std::max(1.0, std::ceil(unit / s_max - 1e-12));
  return g;
}

double accessible_fraction(double energy) {
  constexpr int kSamples = 1 << 16;
  int inside = 0;
  for (int i = 0; i < kSamples; ++i) {
    double a, b, c, d;
    aw_uniform2(0x5eedULL, static_cast<aw_u64>(i), 0u, 0u, &a, &b);
    aw_uniform2(0x5eedULL, static_cast<aw_u64>(i), 0u, 1u, &c, &d);
    if (aw_potential(a - 0.5, b - 0.5, c - 0.5) < energy) ++inside;
  }
  return static_cast<double>(inside) / kSamples;
}

Plan make_plan(const Scene& scene) {
  Plan p;
  p.scene = scene;
  try {
    p.method = find_method(scene.method);
  } catch (const std::out_of_range& e) {
    fail(scene, "integrator.method", e.what());
  }
  const Method& m = p.method;

  // ---- accessible phase space
  if (!(scene.energy > -2.0))
    fail(scene, "model.energy",
         "E = " + fmt(scene.energy) + " leaves no accessible phase space (V >= -2 everywhere); "
         "choose E > -2");
  // With Gaussian momenta the position must leave room for p_x^2 + p_y^2 / 2.
  const double mean_kinetic = scene.initial == "gaussian"
                                  ? 0.5 * (scene.gaussian_mean[0] * scene.gaussian_mean[0] +
                                           scene.gaussian_mean[1] * scene.gaussian_mean[1])
                                  : 0.0;
  if (scene.initial == "gaussian" && !(scene.energy - mean_kinetic > -2.0))
    fail(scene, "ensemble.gaussian.mean",
         "the mean momentum carries kinetic energy " + fmt(mean_kinetic) + " >= E + 2 = " +
             fmt(scene.energy + 2) + ": no position has enough energy left for it");
  p.accessible_fraction = accessible_fraction(scene.energy - mean_kinetic);
  if (p.accessible_fraction < kMinAccessible) {
    double lo = scene.energy, hi = 2.0;  // smallest E with enough accessible torus
    for (int i = 0; i < 40; ++i) {
      const double mid = 0.5 * (lo + hi);
      (accessible_fraction(mid) < kMinAccessible ? lo : hi) = mid;
    }
    fail(scene, "model.energy",
         "at E = " + fmt(scene.energy) + " only " + fmt(100 * p.accessible_fraction) +
             "% of the torus is accessible (V(X) < E); initial positions are drawn by "
             "rejection and need at least " + fmt(100 * kMinAccessible) + "%: choose E >= " +
             fmt(std::ceil(hi * 1000) / 1000));
  }

  // ---- step schedule
  if (scene.step_auto) {
    // a pilot ensemble chooses the step (accuracy.cpp); the cpu backend
    // computes the same bits as every device in portable math
    auto cpu = open_backend("cpu");
    return make_plan(scene, *cpu);
  }
  p.step = scene.step;
  // Counts derived from the user's numbers stay far inside 64-bit integers
  // (and inside exact doubles): every count is checked before it is made.
  const double steps_wanted = scene.duration / p.step;
  if (!(steps_wanted <= kMaxStepsPerTrajectory)) {
    // blame the key given last (an override of the step, or of the duration)
    const bool step_last = scene.pos("integrator.step").set_index > scene.pos("run.duration").set_index;
    fail(scene, step_last ? "integrator.step" : "run.duration",
         "run.duration / integrator.step = " + fmt(scene.duration) + " T / " + fmt(p.step) + " T = " +
             fmt(steps_wanted) + " steps per trajectory; at most " + fmt(kMaxStepsPerTrajectory) +
             " are allowed: the largest run.duration with this step is " +
             fmt(kMaxStepsPerTrajectory * p.step) + " T, the smallest integrator.step for this duration " +
             fmt(scene.duration / kMaxStepsPerTrajectory) + " T");
  }
  const std::int64_t per_window = exact_ratio(scene.average, p.step);
  if (per_window == 0)
    fail(scene, "run.average",
         "run.average = " + fmt(scene.average) + " T is not a positive multiple of "
         "integrator.step = " + fmt(p.step) + " T (" + fmt(scene.average / p.step) + " steps)");
  p.windows = exact_ratio(scene.duration, scene.average);
  if (p.windows == 0)
    fail(scene, "run.duration",
         "run.duration = " + fmt(scene.duration) + " T is not a positive multiple of "
         "run.average = " + fmt(scene.average) + " T");
  const bool energy = scene.energy_error || scene.max_energy_error.has_value();
  if (energy) {
    p.segments_per_window = exact_ratio(scene.average, scene.energy_every);
    const std::int64_t seg_steps = exact_ratio(scene.energy_every, p.step);
    if (p.segments_per_window == 0 || seg_steps == 0 || seg_steps * p.segments_per_window != per_window)
      fail(scene, "observe.energy_error.every",
           "the energy sample interval " + fmt(scene.energy_every) + " T must divide "
           "run.average = " + fmt(scene.average) + " T and be a multiple of integrator.step = " +
               fmt(p.step) + " T");
    p.steps_per_segment = seg_steps;
  } else {
    p.segments_per_window = 1;
    p.steps_per_segment = per_window;
  }
  p.steps_per_trajectory = p.windows * per_window;
  p.trajectory_steps = static_cast<double>(scene.trajectories) * static_cast<double>(p.steps_per_trajectory);
  p.force_evaluations = p.trajectory_steps * m.stages;

  // ---- step-size guard
  p.guard = step_guard(scene.energy, p.step, scene.average, energy ? scene.energy_every : scene.average);
  if (p.guard.refused() && !scene.allow_unsafe_step)
    fail(scene, "integrator.step",
         "step " + fmt(p.step) + " T is unsafe at E = " + fmt(scene.energy) + ": h k |p|max = " +
             fmt(p.guard.value) + " >= pi (k = 2 for z, |p|max = " + fmt(p.guard.p_max) +
             "), where splitting methods resonate and the energy error grows by orders of "
             "magnitude; use integrator.step = " + fmt(p.guard.safe_step) +
             " (h k |p|max = pi/2), or integrator.step = \"auto\" with an integrator.tolerance, or set "
             "integrator.allow_unsafe_step = true to run anyway");
  if (p.guard.refused())
    p.warnings.push_back("integrator.step: h k |p|max = " + fmt(p.guard.value) +
                         " >= pi, allowed by integrator.allow_unsafe_step");
  else if (p.guard.warned())
    p.warnings.push_back("integrator.step: h k |p|max = " + fmt(p.guard.value) +
                         " > pi/2; expect a larger energy error (safe step: " +
                         fmt(p.guard.safe_step) + " T)");

  // ---- features
  KernelConfig& k = p.kernel;
  k.precision = scene.precision;
  k.math = scene.math;
  k.stages = m.stages;
  k.kick_first = m.kick_first;
  k.initial = scene.initial == "cap"        ? AW_INITIAL_CAP
              : scene.initial == "box"      ? AW_INITIAL_BOX
              : scene.initial == "gaussian" ? AW_INITIAL_GAUSSIAN
                                            : AW_INITIAL_SHELL;
  if (scene.zoom) k.features |= AW_F_ZOOM;
  if (scene.confine) k.features |= AW_F_CONFINE;
  if (!scene.frame_times.empty()) k.features |= AW_F_FRAMES;
  if (scene.velocity_map) k.features |= AW_F_VELOCITY_MAP;
  if (energy) k.features |= AW_F_ENERGY;
  if (scene.max_energy_error) k.features |= AW_F_ENERGY_LIMIT;
  if (scene.initial_states) k.features |= AW_F_INITIAL_STATES;
  if (scene.final_states) k.features |= AW_F_FINAL_STATES;
  if ((scene.initial_states || scene.final_states) && scene.trajectories > kMaxStateRecords)
    fail(scene, scene.final_states ? "observe.final_states" : "observe.initial_states",
         "state records are kept for at most " + std::to_string(kMaxStateRecords) +
             " trajectories (" + std::to_string(scene.trajectories) + " asked for)");
  if (scene.velocity_map)
    p.npix = 12ull * static_cast<std::uint64_t>(scene.nside) * static_cast<std::uint64_t>(scene.nside);
  // frames: boundaries as window indices
  if (!scene.frame_times.empty()) {
    if (!scene.velocity_map)
      fail(scene, "observe.frames", "frames are velocity maps: set observe.velocity_map too");
    if (static_cast<int>(scene.frame_times.size()) > AW_MAX_FRAMES + 1)
      fail(scene, "observe.frames.times", "at most " + std::to_string(AW_MAX_FRAMES + 1) + " times");
    for (double t : scene.frame_times) {
      const std::int64_t w = t == 0 ? 0 : exact_ratio(t, scene.average);
      if ((t != 0 && w == 0) || w > p.windows)
        fail(scene, "observe.frames.times",
             "frame time " + fmt(t) + " T is not a multiple of run.average = " + fmt(scene.average) +
                 " T between 0 and run.duration = " + fmt(scene.duration) + " T");
      p.frame_bounds.push_back(w);
    }
    p.frames = static_cast<int>(p.frame_bounds.size()) - 1;
  } else {
    p.frame_bounds = {0, p.windows};
  }
  if (scene.zoom) p.zoom_resolution = scene.zoom_resolution;
  p.hist_size = static_cast<std::uint64_t>(p.frames) * p.npix +
                static_cast<std::uint64_t>(p.zoom_resolution) * static_cast<std::uint64_t>(p.zoom_resolution);

  // ---- parameter buffers
  p.rp.assign(AW_P_COUNT, 0.0);
  p.rp[AW_P_ENERGY] = scene.energy;
  p.rp[AW_P_ENERGY_LIMIT] = scene.max_energy_error.value_or(std::numeric_limits<double>::infinity());
  const double h = p.step * kTwoPi;
  for (std::size_t i = 0; i < m.drift.size(); ++i) p.rp[AW_P_DRIFT + i] = m.drift[i] * p.step;
  for (std::size_t i = 0; i < m.kick.size(); ++i) p.rp[AW_P_KICK + i] = m.kick[i] * h;
  p.rp[AW_P_KICK_MERGED] = (m.kick.back() + m.kick.front()) * h;

  p.ip.assign(AW_I_COUNT, 0);
  p.ip[AW_I_SEED] = static_cast<std::int64_t>(scene.seed);
  p.ip[AW_I_STEPS_PER_SEGMENT] = p.steps_per_segment;
  p.ip[AW_I_SEGMENTS] = p.segments_per_window;
  p.ip[AW_I_WINDOWS] = p.windows;
  p.ip[AW_I_NSIDE] = scene.nside;
  p.ip[AW_I_MAX_ATTEMPTS] =
      static_cast<std::int64_t>(std::ceil(kAttemptsTimesFraction / p.accessible_fraction));
  p.ip[AW_I_STAGES] = m.stages;
  p.ip[AW_I_KICK_FIRST] = m.kick_first ? 1 : 0;
  p.ip[AW_I_INJECT_INDEX] = -1;
  p.ip[AW_I_INITIAL] = k.initial;
  p.ip[AW_I_ZOOM_RESOLUTION] = p.zoom_resolution;
  p.ip[AW_I_FRAMES] = p.frames;
  for (std::size_t i = 0; i < p.frame_bounds.size(); ++i) p.ip[AW_I_FRAME_BOUNDS + i] = p.frame_bounds[i];

  double* init = &p.rp[AW_P_INIT];
  if (k.initial == AW_INITIAL_CAP) {
    frame_of(scene.cap_center[0], scene.cap_center[1], init);
    init[9] = std::cos(scene.cap_radius * kDeg);
  } else if (k.initial == AW_INITIAL_BOX) {
    init[0] = scene.box_lon[0] / 360.0;
    init[1] = (scene.box_lon[1] - scene.box_lon[0]) / 360.0;
    init[2] = std::sin(scene.box_lat[0] * kDeg);
    init[3] = std::sin(scene.box_lat[1] * kDeg) - init[2];
  } else if (k.initial == AW_INITIAL_GAUSSIAN) {
    init[0] = scene.gaussian_mean[0];
    init[1] = scene.gaussian_mean[1];
    init[2] = scene.gaussian_sigma[0];
    init[3] = scene.gaussian_sigma[1];
  }
  if (scene.zoom) region_of(scene.zoom_center, scene.zoom_width, &p.rp[AW_P_ZOOM]);
  if (scene.confine) region_of(scene.confine_center, scene.confine_width, &p.rp[AW_P_CONFINE]);
  return p;
}

}  // namespace arnoldweb
