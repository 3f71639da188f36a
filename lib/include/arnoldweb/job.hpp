// arnoldweb: a job is everything one scene asks for: its main run and the
// runs of its [[panel]] tables (the same scene with overrides, e.g. the zooms
// of the paper's Figures 2 and 3). The panels are planned up front, so a bad
// panel fails before any work; the parts run one after the other on one
// device (run_job, run.hpp); the outputs are written as one directory
// (write_job, output.hpp): the main run's files, panel-<name>/ for every
// panel and figure.png.
#pragma once

#include <functional>
#include <memory>
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

// What resolves integrator.step = "auto" in a scene before it is planned
// (e.g. resolve_step with a pilot device, accuracy.hpp).
using StepResolver = std::function<Scene(const Scene&)>;

// Plans the scene and every panel (a panel is the scene's text read again with
// the panel's overrides, then the scene's own overrides). A part whose step is
// "auto" is resolved with `resolve` first (without one it is refused). Throws
// SceneError.
// Parts that start from given states (ensemble.initial = "file") read them
// from ensemble.file, or take `states` (Python's initial=) when the scene names
// no file; a part with neither is refused.
Job plan_job(const Scene& scene, const StepResolver& resolve = {}, std::shared_ptr<const StateSet> states = nullptr);

}  // namespace arnoldweb
