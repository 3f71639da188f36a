// arnoldweb: the planner's part for given initial states (ensemble.initial =
// "file" with ensemble.file; docs/outputs.md, "State files"): the file read
// (StateError naming the file, dataset and row), ensemble.trajectories taken
// from it (refused when written as another number), and every state's energy
// checked against the scene's model. Without ensemble.file the states come from
// the caller (Python's initial=), who attaches them to the plan.
#pragma once

#include <memory>

#include "arnoldweb/plan.hpp"
#include "params/kernel_params.hpp"
#include "physics/model_descriptor.hpp"

namespace arnoldweb::detail {

// The states of ensemble.file (ensemble.initial = "file"), or null; refuses
// ensemble.file with another kind. Sets scene.trajectories to their number.
std::shared_ptr<StateSet> read_scene_states(Scene& scene);

// Their energies under the scene's model (the model's parameters in rp), and
// their time against run.duration (states/state_rules.hpp).
void check_scene_states(StateSet& states, const Scene& scene, const ModelDescriptor& model, const RealParams& rp);

}  // namespace arnoldweb::detail
