// arnoldweb: from a validated scene to a plan: a pure function of the scene.
// Each part of the plan is made in its own step: the method, the model's
// checks (accessible phase space), the schedule (schedule.cpp), the step-size
// guard, the effects (effects.cpp), the histograms, the kernel parameters.
#include "arnoldweb/plan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "arnoldweb/sphere.hpp"
#include "aw_params.h"
#include "physics/models.hpp"
#include "plan/checks.hpp"
#include "states/state_plan.hpp"
#include "plan/effects.hpp"
#include "plan/indicators.hpp"
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

// Whether a model parameter holds another value than its default (the scene's
// echo, to_toml, writes every key: the defaults of other models read back).
bool differs_from_default(const Scene& s, const std::string& key) {
  const Scene d;
  if (key == "model.epsilon") return s.model_epsilon != d.model_epsilon;
  if (key == "model.harmonics") return s.model_harmonics != d.model_harmonics;
  if (key == "model.kinetic_a") return s.model_kinetic_a != d.model_kinetic_a;
  if (key == "model.kinetic_b") return s.model_kinetic_b != d.model_kinetic_b;
  return true;
}

// Keys of another model than the scene's are refused where written with
// another value than their default; the kinetic form must suit the initial kind.
void plan_model(const Scene& scene, const detail::ModelRow& model, const detail::RealParams& rp) {
  for (const detail::ModelRow& other : detail::models())
    for (const std::string& key : other.keys) {
      if (std::find(model.keys.begin(), model.keys.end(), key) != model.keys.end()) continue;
      const SourcePos at = scene.pos(key);
      if ((at.line > 0 || at.set_index > 0) && differs_from_default(scene, key))
        fail_at(scene, key,
                "is a parameter of model.kind = \"" + other.name + "\", not of this scene's model \"" +
                    model.name + "\" (its keys: " +
                    (model.keys.empty() ? std::string("none but model.energy") : [&] {
                      std::string k;
                      for (const std::string& m : model.keys) k += (k.empty() ? "" : ", ") + m;
                      return k;
                    }()) + ")");
    }
  if (scene.initial == "gaussian" && !detail::standard_kinetic(model, rp))
    fail_at(scene, "ensemble.initial",
            "\"gaussian\" draws p_x, p_y and solves |P|^2/2 = E - V(X) for p_z: it needs the kinetic form "
            "|P|^2/2, and model \"" + model.name + "\" has another (use \"shell\", \"cap\" or \"box\")");
}

// The energy surface T(P) + V(X) = E of a kinetic form other than |P|^2/2
// (linear terms, zero coefficients): the fraction of positions and directions
// from which it is reached must leave room for the rejection sampling.
void plan_reachable(const Scene& scene, const detail::ModelRow& model, const detail::RealParams& rp, Plan& p) {
  p.accessible_fraction = detail::reachable_fraction(model, rp, scene.energy);
  if (p.accessible_fraction >= kMinAccessible) return;
  const auto v = model.v_range(rp);
  const auto k = model.kinetic(rp);
  std::string range;
  if (detail::energy_bounds_momenta(model, rp)) {
    double t_min = 0;  // the bottom of T: -sum b_i^2 / (2 a_i)
    for (int i = 0; i < 3; ++i) t_min -= k[3 + i] * k[3 + i] / (2 * k[i]);
    range = "T(P) >= " + fmt(t_min) + " and " + fmt(v[0]) + " <= V <= " + fmt(v[1]) + ", so E must exceed " +
            fmt(t_min + v[0]) + " (and leave room above it)";
  } else {
    range = fmt(v[0]) + " <= V <= " + fmt(v[1]) + "; with a coefficient a_i = 0 the directions along which T(s n) "
            "reaches E - V(X) depend on the sign of b.n";
  }
  fail_at(scene, "model.energy",
          "the energy surface T(P) + V(X) = " + fmt(scene.energy) + " of model \"" + model.name +
              "\" is reached from only " + fmt(100 * p.accessible_fraction) +
              "% of the positions and momentum directions drawn (initial states are drawn by rejection and need "
              "at least " + fmt(100 * kMinAccessible) + "%): " + range);
}

// The energy must leave enough of the torus accessible for initial states.
void plan_accessible(const Scene& scene, const detail::ModelRow& model, const detail::RealParams& rp, Plan& p) {
  const auto k = model.kinetic(rp);
  if (!(k[0] > 0 && k[1] > 0 && k[2] > 0 && k[3] == 0 && k[4] == 0 && k[5] == 0))
    return plan_reachable(scene, model, rp, p);  // T(s n) = ke is not simply "ke > 0"
  const double v_min = model.v_range(rp)[0];
  if (!(scene.energy > v_min))
    fail_at(scene, "model.energy",
            "E = " + fmt(scene.energy) + " leaves no accessible phase space (V >= " + fmt(v_min) +
                " everywhere); choose E > " + fmt(v_min));
  // With Gaussian momenta the position must leave room for p_x^2 + p_y^2 / 2.
  const double mean_kinetic =
      scene.initial == "gaussian"
          ? 0.5 * (scene.gaussian_mean[0] * scene.gaussian_mean[0] + scene.gaussian_mean[1] * scene.gaussian_mean[1])
          : 0.0;
  if (scene.initial == "gaussian" && !(scene.energy - mean_kinetic > v_min))
    fail_at(scene, "ensemble.gaussian.mean",
            "the mean momentum carries kinetic energy " + fmt(mean_kinetic) + " >= E - min V = " +
                fmt(scene.energy - v_min) + ": no position has enough energy left for it");
  p.accessible_fraction = detail::accessible_fraction(model, rp, scene.energy - mean_kinetic);
  if (p.accessible_fraction >= kMinAccessible) return;
  double lo = scene.energy, hi = model.v_range(rp)[1];  // smallest E with enough accessible torus
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (lo + hi);
    (detail::accessible_fraction(model, rp, mid) < kMinAccessible ? lo : hi) = mid;
  }
  fail_at(scene, "model.energy",
          "at E = " + fmt(scene.energy) + " only " + fmt(100 * p.accessible_fraction) +
              "% of the torus is accessible (V(X) < E); initial positions are drawn by rejection and need at "
              "least " + fmt(100 * kMinAccessible) + "%: choose E >= " + fmt(std::ceil(hi * 1000) / 1000));
}

// The model's largest frequency omega (the step-size guard's h omega):
//   the paper's model: its closed form k |p|max (k = 2, |p|max = sqrt(2 (E + 2)));
//   otherwise the largest phase rate |k.v| of the model's harmonics k plus the
//   libration frequency sqrt(max a_i ||Hess V||) of its deepest well, where the
//   velocity v = dX/dt = a_i p_i + b_i is bounded by the energy when every
//   a_i > 0 (sum v_i^2 / (2 a_i) <= E - min V + sum b_i^2 / (2 a_i), so
//   |k.v| <= sqrt(2 K sum a_i k_i^2)), else by the largest |v_i| of the scene's
//   first kVelocitySample initial states plus what the potential's range can
//   add (sqrt(2 a_i (max V - min V))) (an estimate, not a bound).
constexpr int kVelocitySample = 4096;
double model_frequency(const Scene& scene, const detail::ModelRow& model, const detail::KernelParams& kp,
                       int initial, std::string& basis) {
  const detail::RealParams& rp = kp.reals;
  if (model.closed_frequency) {
    const double omega = model.closed_frequency(scene.energy, rp);
    basis = "k = 2 for z, |p|max = " + fmt(omega / 2);
    return omega;
  }
  const auto k = model.kinetic(rp);
  const auto v = model.v_range(rp);
  const auto waves = model.wave_vectors(rp);
  const double a_max = std::max({k[0], k[1], k[2]});
  const double libration = std::sqrt(a_max * model.hessian_bound(rp));
  double drift = 0;
  if (detail::energy_bounds_momenta(model, rp)) {
    double big_k = std::max(0.0, scene.energy - v[0]);
    for (int i = 0; i < 3; ++i) big_k += k[3 + i] * k[3 + i] / (2 * k[i]);
    for (const auto& w : waves)
      drift = std::max(drift, std::sqrt(2 * big_k * (k[0] * w[0] * w[0] + k[1] * w[1] * w[1] + k[2] * w[2] * w[2])));
    basis = "|k.dX/dt| <= " + fmt(drift) + " from the energy, libration " + fmt(libration);
  } else {
    std::array<double, 3> vmax{};
    int found = 0;
    for (int i = 0; i < kVelocitySample; ++i) {
      double u[3], pm[3];
      if (!model.initial_state(initial, static_cast<std::uint64_t>(i), rp, kp.ints, u, pm)) continue;
      ++found;
      for (int c = 0; c < 3; ++c) vmax[c] = std::max(vmax[c], std::fabs(k[c] * pm[c] + k[3 + c]));
    }
    for (int c = 0; c < 3; ++c)
      if (k[c] > 0) vmax[c] += std::sqrt(2 * k[c] * (v[1] - v[0]));
    for (const auto& w : waves)
      drift = std::max(drift, std::fabs(w[0]) * vmax[0] + std::fabs(w[1]) * vmax[1] + std::fabs(w[2]) * vmax[2]);
    basis = "|dX/dt| <= (" + fmt(vmax[0]) + ", " + fmt(vmax[1]) + ", " + fmt(vmax[2]) + ") estimated from " +
            std::to_string(found) + " initial states, libration " + fmt(libration);
  }
  return drift + libration;
}

void plan_guard(const Scene& scene, const detail::ModelRow& model, const detail::KernelParams& kp, Plan& p) {
  const bool energy = scene.energy_error || scene.max_energy_error.has_value();
  std::string basis;
  const double omega = model_frequency(scene, model, kp, p.kernel.initial, basis);
  const double unit = energy ? scene.energy_every : scene.average;
  p.guard = model.closed_frequency ? step_guard(scene.energy, p.step, scene.average, unit)
                                   : step_guard_at(omega, p.step, scene.average, unit);
  p.guard.basis = basis;
  const std::string what = model.closed_frequency ? "h k |p|max" : "h omega_max";
  if (p.guard.refused() && !scene.allow_unsafe_step)
    fail_at(scene, "integrator.step",
            "step " + fmt(p.step) + " T is unsafe at E = " + fmt(scene.energy) + ": " + what + " = " +
                fmt(p.guard.value) + " >= pi (" + basis +
                "), where splitting methods resonate and the energy error grows by orders of magnitude; use "
                "integrator.step = " + fmt(p.guard.safe_step) + " (" + what +
                " = pi/2), or integrator.step = \"auto\" with an integrator.tolerance, or set "
                "integrator.allow_unsafe_step = true to run anyway");
  if (p.guard.refused())
    p.warnings.push_back("integrator.step: " + what + " = " + fmt(p.guard.value) +
                         " >= pi, allowed by integrator.allow_unsafe_step");
  else if (p.guard.warned())
    p.warnings.push_back("integrator.step: " + what + " = " + fmt(p.guard.value) +
                         " > pi/2; expect a larger energy error (safe step: " + fmt(p.guard.safe_step) + " T)");
}

int initial_kind(const Scene& scene) {
  return scene.initial == "cap"        ? AW_INITIAL_CAP
         : scene.initial == "box"      ? AW_INITIAL_BOX
         : scene.initial == "gaussian" ? AW_INITIAL_GAUSSIAN
         : scene.initial == "grid"     ? AW_INITIAL_GRID
                                       : AW_INITIAL_SHELL;
}

void plan_kernel(const Scene& scene, const detail::ModelRow& model, Plan& p) {
  KernelConfig& k = p.kernel;
  k.precision = scene.precision;
  k.math = scene.math;
  k.stages = p.method.stages;
  k.kick_first = p.method.kick_first;
  k.gradient = p.method.force_gradient();
  k.model = model.id;
  k.model_source = model.device_source;  // an expression model's header, or empty
  k.initial = initial_kind(scene);
  k.features = detail::features_of(scene);
  if (k.gradient && (k.features & AW_F_TANGENT))
    fail_at(scene, "integrator.method",
            "the chaos indicators follow the tangent map of the step, and a force-gradient kick's tangent map "
            "needs third derivatives of V, which the models do not provide: use a method without force-gradient "
            "terms with observe.fli, observe.megno or observe.lyapunov (" + p.method.name + " has them)");
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

void fill_initial(const Scene& scene, int initial, detail::RealParams& rp);

void fill_reals(const Scene& scene, const Plan& p, detail::RealParams& rp) {
  const Method& m = p.method;
  rp.energy = scene.energy;
  rp.energy_limit = scene.max_energy_error.value_or(std::numeric_limits<double>::infinity());
  const double h = p.step * kTwoPi;
  for (std::size_t i = 0; i < m.drift.size(); ++i) rp.drift[i] = m.drift[i] * p.step;
  for (std::size_t i = 0; i < m.kick.size(); ++i) rp.kick[i] = m.kick[i] * h;
  rp.kick_merged = (m.kick.back() + m.kick.front()) * h;
  for (std::size_t i = 0; i < m.gradient.size(); ++i) rp.gradient[i] = m.gradient[i] * (h * h * h);
  if (!m.gradient.empty()) rp.gradient_merged = (m.gradient.back() + m.gradient.front()) * (h * h * h);
  fill_initial(scene, p.kernel.initial, rp);
  if (scene.zoom) region_of(scene.zoom_center, scene.zoom_width, rp.zoom);
  if (scene.confine) region_of(scene.confine_center, scene.confine_width, rp.confine);
  detail::fill_indicator_reals(scene, p, rp);
}

// The parameters of the initial kind.
void fill_initial(const Scene& scene, int initial, detail::RealParams& rp) {
  if (initial == AW_INITIAL_CAP) {
    frame_of(scene.cap_center[0], scene.cap_center[1], rp.cap);
    rp.cap.cos_radius = std::cos(scene.cap_radius * kDeg);
  } else if (initial == AW_INITIAL_BOX) {
    rp.box.lon0 = scene.box_lon[0] / 360.0;
    rp.box.lon_width = (scene.box_lon[1] - scene.box_lon[0]) / 360.0;
    rp.box.sin_lat0 = std::sin(scene.box_lat[0] * kDeg);
    rp.box.sin_lat_width = std::sin(scene.box_lat[1] * kDeg) - rp.box.sin_lat0;
  } else if (initial == AW_INITIAL_GAUSSIAN) {
    rp.gaussian.mean_x = scene.gaussian_mean[0];
    rp.gaussian.mean_y = scene.gaussian_mean[1];
    rp.gaussian.sigma_x = scene.gaussian_sigma[0];
    rp.gaussian.sigma_y = scene.gaussian_sigma[1];
  }
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
  detail::fill_indicator_ints(scene, ip);
}

}  // namespace

Plan make_plan(const Scene& scene_as_written) {
  const Scene scene = detail::with_grid_size(scene_as_written);
  if (scene.step_auto)
    fail_at(scene, "integrator.step",
            "\"auto\" is resolved before planning, by a pilot ensemble on a device: resolve_step(scene, backend) "
            "(accuracy.hpp; the arnoldweb command does this)");
  Plan p;
  p.scene = scene;
  auto params = std::make_shared<detail::KernelParams>();
  const detail::ModelRow& model = detail::model_of(scene);
  model.fill(scene, params->reals);
  detail::plan_initial_states(scene);  // ensemble.initial = "file" (issue 25): the file read and checked
  plan_method(scene, p);
  plan_model(scene, model, params->reals);
  if (scene.initial == "grid")
    detail::plan_grid(scene, model, params->reals, p);
  else
    plan_accessible(scene, model, params->reals, p);
  detail::plan_schedule(scene, p);
  plan_kernel(scene, model, p);
  plan_histograms(scene, p);
  fill_reals(scene, p, params->reals);
  fill_ints(scene, p, params->ints);
  plan_guard(scene, model, *params, p);  // may draw initial states: after the blocks are filled
  p.params = std::move(params);
  return p;
}

double largest_frequency(const Scene& scene, std::string* basis) {
  detail::KernelParams kp;
  const detail::ModelRow& model = detail::model_of(scene);
  model.fill(scene, kp.reals);
  plan_model(scene, model, kp.reals);
  kp.reals.energy = scene.energy;
  fill_initial(scene, initial_kind(scene), kp.reals);
  kp.ints.seed = static_cast<std::int64_t>(scene.seed);
  kp.ints.max_attempts = 1000;
  std::string b;
  const double omega = model_frequency(scene, model, kp, initial_kind(scene), b);
  if (basis) *basis = b;
  return omega;
}

}  // namespace arnoldweb
