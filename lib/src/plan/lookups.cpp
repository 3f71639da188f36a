// arnoldweb: the planner's questions to the layers below it (lookups.hpp).
#include "plan/lookups.hpp"

#include <stdexcept>

#include "output_table/output_table.hpp"
#include "plan/checks.hpp"

namespace arnoldweb::detail {

ModelLookup look_up_model(const Scene& scene) {
  ModelLookup found;
  if (scene.model_kind == "expression") {
    try {
      found.model = &expression_row({scene.model_potential, scene.model_parameters});
    } catch (const ModelError& e) {
      found.key = e.key();
      found.error = e.what();
    }
    return found;
  }
  found.model = find_model(scene.model_kind);
  if (!found.model) {
    found.key = "model.kind";
    found.error = "unknown model \"" + scene.model_kind + "\"";
  }
  return found;
}

const ModelDescriptor& model_found(const Scene& scene, const ModelLookup& found) {
  if (!found.model) fail_at(scene, found.key, found.error);
  return *found.model;
}

PlanLookups look_up(const Scene& scene) {
  PlanLookups f;
  f.model = look_up_model(scene);
  if (f.model.model) {
    const ModelDescriptor& model = *f.model.model;
    model.fill(scene.model_values, f.reals);
    f.bounds_momenta = energy_bounds_momenta(model, f.reals);
    // the phase space the initial states are drawn from, at the scene's energy (plan_accessible)
    const auto k = model.kinetic(f.reals);
    f.accessible = k[0] > 0 && k[1] > 0 && k[2] > 0 && k[3] == 0 && k[4] == 0 && k[5] == 0;
    const bool drawn = scene.initial != "grid" && scene.initial != "file";
    // with Gaussian momenta the position must leave room for p_x^2 + p_y^2 / 2
    if (scene.initial == "gaussian")
      f.mean_kinetic =
          0.5 * (scene.gaussian_mean[0] * scene.gaussian_mean[0] + scene.gaussian_mean[1] * scene.gaussian_mean[1]);
    if (drawn && !f.accessible) f.fraction = reachable_fraction(model, f.reals, scene.energy);
    if (drawn && f.accessible) f.fraction = accessible_fraction(model, f.reals, scene.energy - f.mean_kinetic);
    if (drawn && f.accessible && f.fraction < kMinAccessible) {
      double lo = scene.energy, hi = model.v_range(f.reals)[1];  // smallest E with enough accessible torus
      for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (lo + hi);
        (accessible_fraction(model, f.reals, mid) < kMinAccessible ? lo : hi) = mid;
      }
      f.enough_energy = hi;
    }
  }
  try {
    f.method = &find_method(scene.method);
  } catch (const std::out_of_range& e) {
    f.method_error = e.what();
  }
  f.switch_bits = switch_features(scene.switches, scene.output_values);
  f.intervals = sample_intervals(scene.output_values);
  // the sphere last: it is the lowest layer asked
  if (scene.initial == "cap") f.cap = tangent_frame(scene.cap_center[0], scene.cap_center[1]);
  if (scene.zoom) f.zoom = tangent_frame(scene.zoom_center[0], scene.zoom_center[1]);
  if (scene.confine) f.confine = tangent_frame(scene.confine_center[0], scene.confine_center[1]);
  return f;
}

}  // namespace arnoldweb::detail
