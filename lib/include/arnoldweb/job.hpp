// arnoldweb: a job is everything one scene asks for: its main run and the
// runs of its [[panel]] tables (the same scene with overrides, e.g. the zooms
// of the paper's Figures 2 and 3). The panels are planned up front, so a bad
// panel fails before any work; the parts run one after the other on one
// device (run_job, run.hpp); the outputs are written as one directory
// (write_job, output.hpp): the main run's files, panel-<name>/ for every
// panel and figure.png.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "arnoldweb/plan.hpp"

namespace arnoldweb {

struct JobPart {
  std::string name;    // "" for the main run, else the panel's name
  std::string title;   // the panel's caption
  std::string subdir;  // where its outputs go in the job's directory: "" or "panel-<name>"
  Plan plan;
};

struct Job {
  std::vector<JobPart> parts;  // the main run first, then the panels in scene order
  const Plan& main() const { return parts.front().plan; }
};

// A part before it is planned: the scene it runs.
struct PartScene {
  std::string name, title, subdir;  // as JobPart's
  Scene scene;
};
// The scene and each panel's (the scene's text read again with the panel's
// overrides, then the scene's own overrides): what read_plan_inputs reads the
// inputs of and plan_job plans. Throws SceneError for a bad panel.
std::vector<PartScene> part_scenes(const Scene& scene);

// What resolves integrator.step = "auto" in a scene before it is planned
// (e.g. resolve_step with a pilot device, accuracy.hpp).
using StepResolver = std::function<Scene(const Scene&, const PlanInputs&)>;

// Plans the scene and every panel with the inputs read before
// (read_plan_inputs, inputs.hpp). A part whose step is "auto" is resolved with
// `resolve` first (without one it is refused). Throws SceneError; a part with
// ensemble.initial = "file" whose states are not among the inputs is refused.
Job plan_job(const Scene& scene, const PlanInputs& inputs = {}, const StepResolver& resolve = {});

}  // namespace arnoldweb
