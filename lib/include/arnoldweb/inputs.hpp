// arnoldweb: the stage before planning. Everything a plan takes from outside
// its scene is read here, once (PlanInputs, plan.hpp): the states of every
// ensemble.file of the job (read, then checked against the scene that names
// it: StateError naming the file, dataset and row), and whether the pictures
// plugin opens (a run that asks for pictures where none can be drawn computes
// the rest, and its plan says why). The arnoldweb command and Python call it
// before plan_job (job.hpp); planning after it reads nothing.
#pragma once

#include <memory>

#include "arnoldweb/plan.hpp"
#include "arnoldweb/states.hpp"

namespace arnoldweb {

// The inputs of the scene and its panels (part_scenes, job.hpp); `given`: the
// states of a part that names no file (Python's initial=, checked by the caller).
PlanInputs read_plan_inputs(const Scene& scene, std::shared_ptr<const StateSet> given = nullptr);

}  // namespace arnoldweb
