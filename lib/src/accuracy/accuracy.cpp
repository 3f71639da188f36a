// arnoldweb: accuracy planning on a device (accuracy.hpp, docs/accuracy.md):
// the step search (plan/step_search.cpp) with its pilot ensembles run on a
// backend, and integrator.step = "auto" resolved from its report.
#include "arnoldweb/accuracy.hpp"

#include <chrono>
#include <limits>

#include "arnoldweb/run.hpp"
#include "plan/checks.hpp"
#include "plan/step_search.hpp"

namespace arnoldweb {
namespace {

bool written(const Scene& s, const std::string& key) {
  const SourcePos p = s.pos(key);
  return p.line > 0 || p.set_index > 0;
}

// A pilot ensemble run on the device: a lost trajectory (non-finite, or none binned) makes its error infinite.
detail::PilotRun run_pilot(const Plan& pilot, Backend& backend) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const Result r = run(pilot, backend);
  const bool lost = r.flagged_nonfinite > 0 || r.binned == 0;
  return {lost ? kInf : r.energy.max, lost ? kInf : r.energy.quantile(0.5), r.rate(), r.wall_seconds};
}

}  // namespace

AccuracyReport assess_accuracy(const Scene& scene, const PlanInputs& inputs, Backend& backend, double tolerance,
                               const PilotOptions& o) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  AccuracyReport rep = detail::search_step(scene, inputs, tolerance, o, backend.preferred_chunk(),
                                           [&backend](const Plan& pilot) { return run_pilot(pilot, backend); });
  rep.device = backend.info().id;
  rep.pilot_seconds = std::chrono::duration<double>(clock::now() - t0).count();
  return rep;
}

Scene resolve_step(const Scene& scene, const PlanInputs& inputs, Backend& pilot, const PilotOptions& options) {
  if (!scene.step_auto) return scene;
  PilotOptions o = options;
  const bool method_written = written(scene, "integrator.method");
  if (method_written) o.methods = {scene.method};
  const AccuracyReport rep = assess_accuracy(scene, inputs, pilot, scene.tolerance, o);
  if (!rep.found)
    detail::fail_at(scene, "integrator.tolerance",
         "integrator.step = \"auto\": " + rep.why_not +
             (method_written ? " (or leave integrator.method out, so that every method is considered)" : ""));
  Scene resolved = scene;
  resolved.step_auto = false;
  resolved.method = rep.best.method;
  resolved.step = rep.best.step;
  AutoStep& a = resolved.auto_step;
  a.used = true;
  a.tolerance = scene.tolerance;
  a.safety = rep.safety;
  a.method_chosen = !method_written;
  a.method = rep.best.method;
  a.step = rep.best.step;
  a.predicted_max = rep.best.predicted_max;
  a.pilot_max = rep.best.measured_max;
  a.pilot_median = rep.best.measured_median;
  a.pilot_trajectories = rep.pilot_trajectories;
  a.pilot_duration = rep.pilot_duration;
  a.pilot_device = rep.device;
  a.pilot_seconds = rep.pilot_seconds;
  return resolved;
}

StepResolver cpu_pilot() {
  auto pilot = std::make_shared<std::unique_ptr<Backend>>();
  return [pilot](const Scene& s, const PlanInputs& inputs) {
    if (!*pilot) *pilot = open_backend("cpu");
    return resolve_step(s, inputs, **pilot);
  };
}

}  // namespace arnoldweb
