// arnoldweb: accuracy planning. A short pilot ensemble measures the energy
// error of each method at a few steps, fits max|dE| ~ C h^p, and finds the
// cheapest method and step (force evaluations per trajectory per T =
// stages / step) whose error meets a tolerance; the choice is then checked by
// running it on the pilot ensemble. `arnoldweb accuracy SCENE` prints the
// report; integrator.step = "auto" uses the same machinery (docs/accuracy.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "arnoldweb/accuracy_report.hpp"
#include "arnoldweb/device.hpp"
#include "arnoldweb/job.hpp"
#include "arnoldweb/plan.hpp"

namespace arnoldweb {

// Run the pilot for `scene` (with its inputs, read_plan_inputs: a scene
// that starts from states pilots the first of them) on `backend` and find the
// cheapest method and step with max|dE| <= tolerance. Throws SceneError for an
// invalid scene, DeviceError for device problems.
AccuracyReport assess_accuracy(const Scene& scene, const PlanInputs& inputs, Backend& backend, double tolerance,
                               const PilotOptions& options = {});

// The stage before planning for a scene with integrator.step = "auto": a pilot
// ensemble on `pilot` chooses the step (and the method, when the scene does
// not name integrator.method itself) for integrator.tolerance. Returns the
// scene with that method and step, the choice recorded in Scene::auto_step;
// a scene with a numeric step comes back as it is. In portable math every
// device computes the same bits, so the pilot may run on any of them (the
// arnoldweb command uses the cpu backend). Throws SceneError when no method
// meets the tolerance.
Scene resolve_step(const Scene& scene, const PlanInputs& inputs, Backend& pilot, const PilotOptions& options = {});

// The resolver the arnoldweb command and Python plan jobs with (plan_job,
// job.hpp): resolve_step with a pilot on the cpu backend (in portable math the
// same bits as every device), opened only when a part asks for it.
StepResolver cpu_pilot();

}  // namespace arnoldweb
