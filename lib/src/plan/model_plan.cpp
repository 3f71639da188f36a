// arnoldweb: the planner's part for the model (model_plan.hpp): which model a
// scene runs, its parameters into the kernels' blocks, the keys of other
// models refused, the accessible phase space, the largest frequency for the
// step-size guard.
#include "plan/model_plan.hpp"

#include <algorithm>
#include <cmath>

#include "plan/checks.hpp"
#include "plan/plan_params.hpp"

namespace arnoldweb::detail {
namespace {

std::string fmt(double v) { return show_number(v); }

// Whether a model key holds another value than its default (the scene's echo,
// to_toml, writes every key: the defaults of other models read back).
bool differs_from_default(const Scene& s, const ModelParameter& p) {
  const auto it = s.model_values.find(p.key);
  return it != s.model_values.end() && it->second != p.default_value;
}

std::string key_list(const ModelDescriptor& model) {
  std::string k;
  for (const std::string& m : model.keys()) k += (k.empty() ? "" : ", ") + m;
  return k.empty() ? std::string("none but model.energy") : k;
}

}  // namespace

const ModelDescriptor& model_of(const Scene& scene) { return model_found(scene, look_up_model(scene)); }

// Keys of another model than the scene's are refused where written with
// another value than their default; the kinetic form must suit the initial kind.
void plan_model_values(const Scene& scene, const ModelDescriptor& model, RealParams& rp) {
  const std::vector<std::string> own = model.keys();
  for (const ModelDescriptor& other : models())
    for (const std::string& key : other.keys()) {
      if (std::find(own.begin(), own.end(), key) != own.end()) continue;
      const SourcePos at = scene.pos(key);
      const ModelParameter* p = other.parameter(key);  // a number: written at its default is the echo's
      if ((at.line > 0 || at.set_index > 0) && (!p || differs_from_default(scene, *p)))
        fail_at(scene, key,
                "is a parameter of model.kind = \"" + other.name + "\", not of this scene's model \"" + model.name +
                    "\" (its keys: " + key_list(model) + ")");
    }
  model.fill(scene.model_values, rp);
  if (scene.initial == "gaussian" && !standard_kinetic(model, rp))
    fail_at(scene, "ensemble.initial",
            "\"gaussian\" draws p_x, p_y and solves |P|^2/2 = E - V(X) for p_z: it needs the kinetic form "
            "|P|^2/2, and model \"" + model.name + "\" has another (use \"shell\", \"cap\" or \"box\")");
}

namespace {

// The energy surface T(P) + V(X) = E of a kinetic form other than |P|^2/2
// (linear terms, zero coefficients): the fraction of positions and directions
// from which it is reached must leave room for the rejection sampling.
void plan_reachable(const Scene& scene, const ModelDescriptor& model, const RealParams& rp, const PlanLookups& found,
                    Plan& p) {
  p.accessible_fraction = found.fraction;
  if (p.accessible_fraction >= kMinAccessible) return;
  const auto v = model.v_range(rp);
  const auto k = model.kinetic(rp);
  std::string range;
  if (found.bounds_momenta) {
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

}  // namespace

// The energy must leave enough of the torus accessible for initial states.
void plan_accessible(const Scene& scene, const ModelDescriptor& model, const RealParams& rp, const PlanLookups& found,
                     Plan& p) {
  if (!found.accessible) return plan_reachable(scene, model, rp, found, p);  // T(s n) = ke is not simply "ke > 0"
  const double v_min = model.v_range(rp)[0];
  if (!(scene.energy > v_min))
    fail_at(scene, "model.energy",
            "E = " + fmt(scene.energy) + " leaves no accessible phase space (V >= " + fmt(v_min) +
                " everywhere); choose E > " + fmt(v_min));
  // With Gaussian momenta the position must leave room for p_x^2 + p_y^2 / 2.
  const double mean_kinetic = found.mean_kinetic;
  if (scene.initial == "gaussian" && !(scene.energy - mean_kinetic > v_min))
    fail_at(scene, "ensemble.gaussian.mean",
            "the mean momentum carries kinetic energy " + fmt(mean_kinetic) + " >= E - min V = " +
                fmt(scene.energy - v_min) + ": no position has enough energy left for it");
  p.accessible_fraction = found.fraction;
  if (p.accessible_fraction >= kMinAccessible) return;
  fail_at(scene, "model.energy",
          "at E = " + fmt(scene.energy) + " only " + fmt(100 * p.accessible_fraction) +
              "% of the torus is accessible (V(X) < E); initial positions are drawn by rejection and need at "
              "least " + fmt(100 * kMinAccessible) + "%: choose E >= " + fmt(std::ceil(found.enough_energy * 1000) / 1000));
}

// The model's largest frequency omega (the step-size guard's h omega):
//   the paper's model: its closed form k |p|max (k = 2, |p|max = sqrt(2 (E + 2)));
//   otherwise the largest phase rate |k.v| of the model's harmonics k plus the
//   libration frequency sqrt(max a_i ||Hess V||) of its deepest well, where the
//   velocity v = dX/dt = a_i p_i + b_i is bounded by the energy when every
//   a_i > 0 (sum v_i^2 / (2 a_i) <= E - min V + sum b_i^2 / (2 a_i), so
//   |k.v| <= sqrt(2 K sum a_i k_i^2)), else by the largest |v_i| of the
//   trajectories' initial states plus what the potential's range can add
//   (sqrt(2 a_i (max V - min V))): the states given (ensemble.initial = "file",
//   every one), or the first kVelocitySample the scene draws (an estimate, not
//   a bound).
constexpr int kVelocitySample = 4096;
namespace {

// The largest |v_c| = |a_c p_c + b_c| of the states, and how many were counted.
std::uint64_t fastest_velocities(const ModelDescriptor& model, const KernelParams& kp, int initial, const StateSet* states,
                       std::array<double, 3>& vmax) {
  const auto k = model.kinetic(kp.reals);
  vmax = {};
  std::uint64_t found = 0;
  auto count = [&](const double* pm) {
    ++found;
    for (int c = 0; c < 3; ++c) vmax[c] = std::max(vmax[c], std::fabs(k[c] * pm[c] + k[3 + c]));
  };
  if (states) {
    for (std::uint64_t i = 0; i < states->count; ++i)
      if (states->status[i] == 0) count(&states->momentum[3 * i]);
    return found;
  }
  for (int i = 0; i < kVelocitySample; ++i) {
    double u[3], pm[3];
    if (model.initial_state(initial, static_cast<std::uint64_t>(i), kp.reals, kp.ints, u, pm)) count(pm);
  }
  return found;
}

}  // namespace

double model_frequency(const Scene& scene, const ModelDescriptor& model, bool bounds_momenta, const KernelParams& kp,
                       int initial, const StateSet* states, std::string& basis) {
  const RealParams& rp = kp.reals;
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
  if (bounds_momenta) {
    double big_k = std::max(0.0, scene.energy - v[0]);
    for (int i = 0; i < 3; ++i) big_k += k[3 + i] * k[3 + i] / (2 * k[i]);
    for (const auto& w : waves)
      drift = std::max(drift, std::sqrt(2 * big_k * (k[0] * w[0] * w[0] + k[1] * w[1] * w[1] + k[2] * w[2] * w[2])));
    basis = "|k.dX/dt| <= " + fmt(drift) + " from the energy, libration " + fmt(libration);
  } else {
    std::array<double, 3> vmax{};
    const std::uint64_t found = fastest_velocities(model, kp, initial, states, vmax);
    for (int c = 0; c < 3; ++c)
      if (k[c] > 0) vmax[c] += std::sqrt(2 * k[c] * (v[1] - v[0]));
    for (const auto& w : waves)
      drift = std::max(drift, std::fabs(w[0]) * vmax[0] + std::fabs(w[1]) * vmax[1] + std::fabs(w[2]) * vmax[2]);
    basis = "|dX/dt| <= (" + fmt(vmax[0]) + ", " + fmt(vmax[1]) + ", " + fmt(vmax[2]) + ") estimated from " +
            show_count(found) + (states ? " states of " + states->source : std::string(" initial states")) +
            ", libration " + fmt(libration);
  }
  return drift + libration;
}

void plan_guard(const Scene& scene, const ModelDescriptor& model, bool bounds_momenta, const KernelParams& kp, Plan& p) {
  std::string basis;
  const double omega = model_frequency(scene, model, bounds_momenta, kp, p.kernel.initial, p.states.get(), basis);
  guard_step(scene, model, omega, basis, p);
}

void guard_step(const Scene& scene, const ModelDescriptor& model, double omega, const std::string& basis, Plan& p) {
  const bool energy = scene.energy_error || scene.max_energy_error.has_value();
  const double unit = energy ? scene.energy_every : scene.average;
  p.guard = model.closed_frequency ? step_guard(scene.energy, p.step, scene.average, unit)
                                   : step_guard_at(omega, p.step, scene.average, unit);
  p.guard.basis = basis;
  p.guard.quantity = model.closed_frequency ? "h k |p|max" : "h omega_max";
  const std::string& what = p.guard.quantity;
  if (model.effective_perturbation) p.effective_perturbation = model.effective_perturbation(scene.energy);
  p.warnings.erase(std::remove_if(p.warnings.begin(), p.warnings.end(),
                                  [](const Plan::Warning& w) { return w.key == "integrator.step"; }),
                   p.warnings.end());  // the step's own, made again (with_step)
  if (p.guard.refused() && !scene.allow_unsafe_step)
    fail_at(scene, "integrator.step",
            "step " + fmt(p.step) + " T is unsafe at E = " + fmt(scene.energy) + ": " + what + " = " +
                fmt(p.guard.value) + " >= pi (" + basis +
                "), where splitting methods resonate and the energy error grows by orders of magnitude; use "
                "integrator.step = " + fmt(p.guard.safe_step) + " (" + what +
                " = pi/2), or integrator.step = \"auto\" with an integrator.tolerance, or set "
                "integrator.allow_unsafe_step = true to run anyway");
  if (p.guard.refused())
    p.warnings.push_back({"integrator.step", "integrator.step: " + what + " = " + fmt(p.guard.value) +
                                                 " >= pi, allowed by integrator.allow_unsafe_step"});
  else if (p.guard.warned())
    p.warnings.push_back({"integrator.step", "integrator.step: " + what + " = " + fmt(p.guard.value) +
                                                 " > pi/2; expect a larger energy error (safe step: " +
                                                 fmt(p.guard.safe_step) + " T)"});
}

}  // namespace arnoldweb::detail

namespace arnoldweb {

std::vector<std::array<int, 3>> model_resonances(const Plan& plan) {
  if (!plan.model || plan.model->overlay_all_resonances || !plan.params) return {};
  return plan.model->wave_vectors(detail::params(plan).reals);
}

}  // namespace arnoldweb
