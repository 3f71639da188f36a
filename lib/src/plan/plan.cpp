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
#include "plan/checks.hpp"
#include "plan/effects.hpp"
#include "plan/indicators.hpp"
#include "plan/lookups.hpp"
#include "plan/analysis_plan.hpp"
#include "plan/model_plan.hpp"
#include "plan/plan_params.hpp"
#include "plan/plan_states.hpp"
#include "output_table/output_table.hpp"
#include "plan/schedule.hpp"

namespace arnoldweb {
namespace {

using detail::fail_at;

constexpr double kTwoPi = 6.283185307179586476925;
constexpr double kDeg = M_PI / 180.0;
// Initial positions are drawn by rejection: with accessible fraction f, each
// trajectory tries up to 30/f positions (failure probability e^-30 ~ 1e-13).
constexpr double kAttemptsTimesFraction = 30.0;
constexpr std::uint64_t kMaxStateRecords = 50'000'000;

void plan_method(const Scene& scene, const detail::PlanLookups& found, Plan& p) {
  if (!found.method) fail_at(scene, "integrator.method", found.method_error);
  p.method = *found.method;
}

int initial_kind(const Scene& scene) {
  return scene.initial == "cap"        ? AW_INITIAL_CAP
         : scene.initial == "box"      ? AW_INITIAL_BOX
         : scene.initial == "gaussian" ? AW_INITIAL_GAUSSIAN
         : scene.initial == "grid"     ? AW_INITIAL_GRID
         : scene.initial == "file"     ? AW_INITIAL_FILE
                                       : AW_INITIAL_SHELL;
}

// The keys that ask for the tangent dynamics: the output table's switches that need it.
std::string tangent_keys() {
  std::vector<std::string> keys;
  for (const detail::OutputSwitch* w : detail::output_switches())
    if (w->needs & AW_F_TANGENT) keys.push_back(w->key);
  std::string s;
  for (std::size_t i = 0; i < keys.size(); ++i) s += (i == 0 ? "" : i + 1 == keys.size() ? " or " : ", ") + keys[i];
  return s;
}

void plan_kernel(const Scene& scene, const detail::ModelDescriptor& model, std::uint32_t switch_bits, Plan& p) {
  KernelConfig& k = p.kernel;
  k.precision = scene.precision;
  k.math = scene.math;
  k.stages = p.method.stages;
  k.kick_first = p.method.kick_first;
  k.gradient = p.method.force_gradient();
  k.model = model.id;
  k.model_source = model.device_source;  // an expression model's header, or empty
  k.initial = initial_kind(scene);
  k.features = detail::features_of(scene, switch_bits);
  if (p.slices > 1) k.features |= AW_F_CARRY;  // a slice leaves the trajectories' whole state in their records
  if (k.gradient && (k.features & AW_F_TANGENT))
    fail_at(scene, "integrator.method",
            "the chaos indicators follow the tangent map of the step, and a force-gradient kick's tangent map "
            "needs third derivatives of V, which the models do not provide: use a method without force-gradient "
            "terms with " + tangent_keys() + " (" + p.method.name + " has them)");
  if ((scene.initial_states || scene.final_states) && scene.trajectories > kMaxStateRecords)
    fail_at(scene, scene.final_states ? "observe.final_states" : "observe.initial_states",
            "state records are kept for at most " + detail::show_count(kMaxStateRecords) + " trajectories (" +
                detail::show_count(scene.trajectories) + " asked for)");
}

void plan_histograms(const Scene& scene, Plan& p) {
  if (scene.velocity_map)
    p.npix = 12ull * static_cast<std::uint64_t>(scene.nside) * static_cast<std::uint64_t>(scene.nside);
  detail::plan_frames(scene, p);
  if (scene.zoom) p.zoom_resolution = scene.zoom_resolution;
  p.hist_size = static_cast<std::uint64_t>(p.frames) * p.npix +
                static_cast<std::uint64_t>(p.zoom_resolution) * static_cast<std::uint64_t>(p.zoom_resolution);
}

// The orthonormal frame of a direction (looked up: lookups.hpp) into a kernel block.
template <class Frame>
void frame_of(const TangentFrame& f, Frame& out) {
  for (int i = 0; i < 3; ++i) {
    out.c[i] = f.c[i];
    out.e1[i] = f.east[i];
    out.e2[i] = f.north[i];
  }
}

// A gnomonic square region of full angular width `width` (degrees).
void region_of(const TangentFrame& center, double width, detail::kernel_double::aw_region& out) {
  frame_of(center, out);
  out.half_width = std::tan(0.5 * width * kDeg);
}

void fill_initial(const Scene& scene, int initial, const TangentFrame& cap, detail::RealParams& rp);

// The method's coefficients at the plan's step.
void fill_method(const Plan& p, detail::RealParams& rp) {
  const Method& m = p.method;
  const double h = p.step * kTwoPi;
  for (std::size_t i = 0; i < m.drift.size(); ++i) rp.drift[i] = m.drift[i] * p.step;
  for (std::size_t i = 0; i < m.kick.size(); ++i) rp.kick[i] = m.kick[i] * h;
  rp.kick_merged = (m.kick.back() + m.kick.front()) * h;
  for (std::size_t i = 0; i < m.gradient.size(); ++i) rp.gradient[i] = m.gradient[i] * (h * h * h);
  if (!m.gradient.empty()) rp.gradient_merged = (m.gradient.back() + m.gradient.front()) * (h * h * h);
}

// The step schedule's counts (and the strides of the effects that sample).
void fill_schedule(const Plan& p, detail::IntParams& ip) {
  ip.steps_per_segment = p.steps_per_segment;
  ip.segments = p.segments_per_window;
  ip.windows = p.windows;
  detail::fill_analysis_ints(p.scene, p, ip);
}

void fill_reals(const Scene& scene, const Plan& p, const detail::PlanLookups& found, detail::RealParams& rp) {
  rp.energy = scene.energy;
  rp.energy_limit = scene.max_energy_error.value_or(std::numeric_limits<double>::infinity());
  fill_method(p, rp);
  fill_initial(scene, p.kernel.initial, found.cap, rp);
  if (scene.zoom) region_of(found.zoom, scene.zoom_width, rp.zoom);
  if (scene.confine) region_of(found.confine, scene.confine_width, rp.confine);
  detail::fill_indicator_reals(scene, p, rp);
  detail::fill_analysis_reals(scene, p, rp);
}

// The parameters of the initial kind.
void fill_initial(const Scene& scene, int initial, const TangentFrame& cap, detail::RealParams& rp) {
  if (initial == AW_INITIAL_CAP) {
    frame_of(cap, rp.cap);
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
  fill_schedule(p, ip);
  ip.nside = p.npix ? scene.nside : 0;  // no map: the zoom histogram starts at 0, as hist_size says
  ip.max_attempts = static_cast<std::int64_t>(std::ceil(kAttemptsTimesFraction / p.accessible_fraction));
  ip.inject_index = -1;
  ip.zoom_resolution = p.zoom_resolution;
  ip.frames = p.frames;
  for (std::size_t i = 0; i < p.frame_bounds.size(); ++i) ip.frame_bounds[i] = p.frame_bounds[i];
  detail::fill_indicator_ints(scene, ip);
  detail::lay_out_records(p.kernel.features, ip);
}

}  // namespace

Plan make_plan(const Scene& scene_as_written, const PlanInputs& inputs) {
  Scene scene = detail::with_grid_size(scene_as_written);
  std::shared_ptr<const StateSet> states = detail::plan_states(scene, inputs);  // ensemble.initial = "file"
  // the lower layers asked once, before anything is decided; nothing below asks them again
  const detail::PlanLookups found = detail::look_up(scene);
  if (scene.step_auto)
    fail_at(scene, "integrator.step",
            "\"auto\" is resolved before planning, by a pilot ensemble on a device: resolve_step(scene, inputs, "
            "backend) (accuracy.hpp; the arnoldweb command does this)");
  Plan p;
  p.scene = scene;
  p.states = std::move(states);
  auto params = std::make_shared<detail::KernelParams>();
  const detail::ModelDescriptor& model = detail::model_found(scene, found.model);
  p.model = &model;
  detail::plan_model_values(scene, model, params->reals);
  plan_method(scene, found, p);
  if (scene.initial == "grid")
    detail::plan_grid(scene, model, params->reals, p);
  else if (scene.initial != "file")  // states from a file: each has its own energy (states.hpp)
    detail::plan_accessible(scene, model, params->reals, found, p);
  p.sample_intervals = found.intervals;
  detail::plan_schedule(scene, p);
  detail::plan_analysis(scene, p);
  plan_kernel(scene, model, found.switch_bits, p);
  plan_histograms(scene, p);
  fill_reals(scene, p, found, params->reals);
  fill_ints(scene, p, params->ints);
  p.hist_size = detail::lay_out_picked(p.kernel.features, p.hist_size, params->ints);  // observe.trajectories
  detail::plan_guard(scene, model, found.bounds_momenta, *params, p);  // may draw initial states: after the blocks are filled
  // a run that asks for pictures where none can be drawn computes and writes the rest
  if (scene.images && !inputs.no_pictures.empty())
    p.warnings.push_back({"output.images", "output.images: no pictures will be drawn: " + inputs.no_pictures});
  p.params = std::move(params);
  return p;
}

Plan with_step(const Plan& plan, double step) {
  Plan p = plan;
  p.scene.step = step;
  p.scene.step_auto = false;
  detail::plan_schedule(p.scene, p);
  detail::KernelParams& kp = detail::edit_params(p);
  fill_method(p, kp.reals);
  kp.reals.tangent_step = p.step;
  fill_schedule(p, kp.ints);
  detail::guard_step(p.scene, *p.model, plan.guard.omega, plan.guard.basis, p);
  return p;
}

Plan with_trajectories(const Plan& plan, std::uint64_t trajectories) {
  Plan p = plan;
  p.scene.trajectories = trajectories;
  detail::plan_schedule(p.scene, p);
  return p;
}

double largest_frequency(const Scene& scene, std::string* basis) {
  // only what the frequency needs (not make_plan's lookups: no fraction of the torus, no output table)
  detail::KernelParams kp;
  const detail::ModelDescriptor& model = detail::model_of(scene);
  detail::plan_model_values(scene, model, kp.reals);
  kp.reals.energy = scene.energy;
  const int initial = initial_kind(scene);
  const TangentFrame cap = initial == AW_INITIAL_CAP ? tangent_frame(scene.cap_center[0], scene.cap_center[1]) : TangentFrame{};
  fill_initial(scene, initial, cap, kp.reals);
  kp.ints.seed = static_cast<std::int64_t>(scene.seed);
  kp.ints.max_attempts = 1000;
  std::string b;
  const double omega = detail::model_frequency(scene, model, detail::energy_bounds_momenta(model, kp.reals), kp,
                                               initial, nullptr, b);
  if (basis) *basis = b;
  return omega;
}

namespace detail {

KernelParams& edit_params(Plan& plan) {
  auto copy = std::make_shared<KernelParams>(*plan.params);
  KernelParams& p = *copy;
  plan.params = std::move(copy);
  return p;
}

}  // namespace detail
}  // namespace arnoldweb
