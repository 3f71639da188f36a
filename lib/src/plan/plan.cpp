// arnoldweb: from a validated scene to a plan: a pure function of the scene.
// Each part of the plan is made in its own step: the method, the model's
// checks (accessible phase space), the schedule (schedule.cpp), the step-size
// guard, the effects (effects.cpp), the histograms, the kernel parameters.
#include "arnoldweb/plan.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "arnoldweb/sphere.hpp"
#include "aw_params.h"
#include "physics/models.hpp"
#include "plan/checks.hpp"
#include "plan/effects.hpp"
#include "plan/kernel_params.hpp"
#include "plan/schedule.hpp"

namespace arnoldweb {
namespace {

using detail::fail_at;
std::string fmt(double v) { return detail::show_number(v); }

constexpr double kTwoPi = 6.283185307179586476925;
constexpr double kDeg = M_PI / 180.0;
// Initial positions are drawn by rejection: with accessible fraction f, each
// trajectory tries up to 30/f positions (failure probability e^-30 ~ 1e-13).
constexpr double kMinAccessible = 0.001;
constexpr double kAttemptsTimesFraction = 30.0;
constexpr std::uint64_t kMaxStateRecords = 50'000'000;

void plan_method(const Scene& scene, Plan& p) {
  try {
    p.method = find_method(scene.method);
  } catch (const std::out_of_range& e) {
    fail_at(scene, "integrator.method", e.what());
  }
}

// The energy must leave enough of the torus accessible for initial states.
void plan_accessible(const Scene& scene, const detail::ModelRow& model, const detail::RealParams& rp, Plan& p) {
  if (!(scene.energy > model.v_min))
    fail_at(scene, "model.energy",
            "E = " + fmt(scene.energy) + " leaves no accessible phase space (V >= " + fmt(model.v_min) +
                " everywhere); choose E > " + fmt(model.v_min));
  // With Gaussian momenta the position must leave room for p_x^2 + p_y^2 / 2.
  const double mean_kinetic =
      scene.initial == "gaussian"
          ? 0.5 * (scene.gaussian_mean[0] * scene.gaussian_mean[0] + scene.gaussian_mean[1] * scene.gaussian_mean[1])
          : 0.0;
  if (scene.initial == "gaussian" && !(scene.energy - mean_kinetic > model.v_min))
    fail_at(scene, "ensemble.gaussian.mean",
            "the mean momentum carries kinetic energy " + fmt(mean_kinetic) + " >= E - min V = " +
                fmt(scene.energy - model.v_min) + ": no position has enough energy left for it");
  p.accessible_fraction = detail::accessible_fraction(model, rp, scene.energy - mean_kinetic);
  if (p.accessible_fraction >= kMinAccessible) return;
  double lo = scene.energy, hi = 2.0;  // smallest E with enough accessible torus
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (lo + hi);
    (detail::accessible_fraction(model, rp, mid) < kMinAccessible ? lo : hi) = mid;
  }
  fail_at(scene, "model.energy",
          "at E = " + fmt(scene.energy) + " only " + fmt(100 * p.accessible_fraction) +
              "% of the torus is accessible (V(X) < E); initial positions are drawn by rejection and need at "
              "least " + fmt(100 * kMinAccessible) + "%: choose E >= " + fmt(std::ceil(hi * 1000) / 1000));
}

void plan_guard(const Scene& scene, Plan& p) {
  const bool energy = scene.energy_error || scene.max_energy_error.has_value();
  p.guard = step_guard(scene.energy, p.step, scene.average, energy ? scene.energy_every : scene.average);
  if (p.guard.refused() && !scene.allow_unsafe_step)
    fail_at(scene, "integrator.step",
            "step " + fmt(p.step) + " T is unsafe at E = " + fmt(scene.energy) + ": h k |p|max = " +
                fmt(p.guard.value) + " >= pi (k = 2 for z, |p|max = " + fmt(p.guard.p_max) +
                "), where splitting methods resonate and the energy error grows by orders of magnitude; use "
                "integrator.step = " + fmt(p.guard.safe_step) +
                " (h k |p|max = pi/2), or integrator.step = \"auto\" with an integrator.tolerance, or set "
                "integrator.allow_unsafe_step = true to run anyway");
  if (p.guard.refused())
    p.warnings.push_back("integrator.step: h k |p|max = " + fmt(p.guard.value) +
                         " >= pi, allowed by integrator.allow_unsafe_step");
  else if (p.guard.warned())
    p.warnings.push_back("integrator.step: h k |p|max = " + fmt(p.guard.value) +
                         " > pi/2; expect a larger energy error (safe step: " + fmt(p.guard.safe_step) + " T)");
}

void plan_kernel(const Scene& scene, const detail::ModelRow& model, Plan& p) {
  KernelConfig& k = p.kernel;
  k.precision = scene.precision;
  k.math = scene.math;
  k.stages = p.method.stages;
  k.kick_first = p.method.kick_first;
  k.model = model.id;
  k.initial = scene.initial == "cap"        ? AW_INITIAL_CAP
              : scene.initial == "box"      ? AW_INITIAL_BOX
              : scene.initial == "gaussian" ? AW_INITIAL_GAUSSIAN
                                            : AW_INITIAL_SHELL;
  k.features = detail::features_of(scene);
  if ((scene.initial_states || scene.final_states) && scene.trajectories > kMaxStateRecords)
    fail_at(scene, scene.final_states ? "observe.final_states" : "observe.initial_states",
            "state records are kept for at most " + std::to_string(kMaxStateRecords) + " trajectories (" +
                std::to_string(scene.trajectories) + " asked for)");
}

void plan_histograms(const Scene& scene, Plan& p) {
  if (scene.velocity_map)
    p.npix = 12ull * static_cast<std::uint64_t>(scene.nside) * static_cast<std::uint64_t>(scene.nside);
  detail::plan_frames(scene, p);
  if (scene.zoom) p.zoom_resolution = scene.zoom_resolution;
  p.hist_size = static_cast<std::uint64_t>(p.frames) * p.npix +
                static_cast<std::uint64_t>(p.zoom_resolution) * static_cast<std::uint64_t>(p.zoom_resolution);
}

// Orthonormal frame of the direction at longitude lon, latitude lat (degrees).
template <class Frame>
void frame_of(double lon, double lat, Frame& out) {
  const TangentFrame f = tangent_frame(lon, lat);
  for (int i = 0; i < 3; ++i) {
    out.c[i] = f.c[i];
    out.e1[i] = f.east[i];
    out.e2[i] = f.north[i];
  }
}

// A gnomonic square region of full angular width `width` (degrees).
void region_of(const std::array<double, 2>& center, double width, detail::kernel_double::aw_region& out) {
  frame_of(center[0], center[1], out);
  out.half_width = std::tan(0.5 * width * kDeg);
}

void fill_reals(const Scene& scene, const Plan& p, detail::RealParams& rp) {
  const Method& m = p.method;
  rp.energy = scene.energy;
  rp.energy_limit = scene.max_energy_error.value_or(std::numeric_limits<double>::infinity());
  const double h = p.step * kTwoPi;
  for (std::size_t i = 0; i < m.drift.size(); ++i) rp.drift[i] = m.drift[i] * p.step;
  for (std::size_t i = 0; i < m.kick.size(); ++i) rp.kick[i] = m.kick[i] * h;
  rp.kick_merged = (m.kick.back() + m.kick.front()) * h;
  if (p.kernel.initial == AW_INITIAL_CAP) {
    frame_of(scene.cap_center[0], scene.cap_center[1], rp.cap);
    rp.cap.cos_radius = std::cos(scene.cap_radius * kDeg);
  } else if (p.kernel.initial == AW_INITIAL_BOX) {
    rp.box.lon0 = scene.box_lon[0] / 360.0;
    rp.box.lon_width = (scene.box_lon[1] - scene.box_lon[0]) / 360.0;
    rp.box.sin_lat0 = std::sin(scene.box_lat[0] * kDeg);
    rp.box.sin_lat_width = std::sin(scene.box_lat[1] * kDeg) - rp.box.sin_lat0;
  } else if (p.kernel.initial == AW_INITIAL_GAUSSIAN) {
    rp.gaussian.mean_x = scene.gaussian_mean[0];
    rp.gaussian.mean_y = scene.gaussian_mean[1];
    rp.gaussian.sigma_x = scene.gaussian_sigma[0];
    rp.gaussian.sigma_y = scene.gaussian_sigma[1];
  }
  if (scene.zoom) region_of(scene.zoom_center, scene.zoom_width, rp.zoom);
  if (scene.confine) region_of(scene.confine_center, scene.confine_width, rp.confine);
}

void fill_ints(const Scene& scene, const Plan& p, detail::IntParams& ip) {
  ip.seed = static_cast<std::int64_t>(scene.seed);
  ip.steps_per_segment = p.steps_per_segment;
  ip.segments = p.segments_per_window;
  ip.windows = p.windows;
  ip.nside = scene.nside;
  ip.max_attempts = static_cast<std::int64_t>(std::ceil(kAttemptsTimesFraction / p.accessible_fraction));
  ip.inject_index = -1;
  ip.zoom_resolution = p.zoom_resolution;
  ip.frames = p.frames;
  for (std::size_t i = 0; i < p.frame_bounds.size(); ++i) ip.frame_bounds[i] = p.frame_bounds[i];
}

}  // namespace

Plan make_plan(const Scene& scene) {
  if (scene.step_auto)
    fail_at(scene, "integrator.step",
            "\"auto\" is resolved before planning, by a pilot ensemble on a device: resolve_step(scene, backend) "
            "(accuracy.hpp; the arnoldweb command does this)");
  Plan p;
  p.scene = scene;
  auto params = std::make_shared<detail::KernelParams>();
  const detail::ModelRow& model = detail::model_of(scene);
  model.fill(scene, params->reals);
  plan_method(scene, p);
  plan_accessible(scene, model, params->reals, p);
  detail::plan_schedule(scene, p);
  plan_guard(scene, p);
  plan_kernel(scene, model, p);
  plan_histograms(scene, p);
  fill_reals(scene, p, params->reals);
  fill_ints(scene, p, params->ints);
  p.params = std::move(params);
  return p;
}

}  // namespace arnoldweb
