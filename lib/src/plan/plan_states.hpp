// arnoldweb: the planner's part for given initial states (ensemble.initial =
// "file"; docs/outputs.md, "State files"). The states are an input of the
// plan, read and checked before planning (read_plan_inputs, inputs.hpp);
// here ensemble.trajectories is taken from them (refused when written as
// another number), and ensemble.file is refused with another initial kind.
#pragma once

#include <memory>

#include "arnoldweb/plan.hpp"

namespace arnoldweb::detail {

// The states the scene starts from (null: none given, or another initial
// kind); sets scene.trajectories to their number.
std::shared_ptr<const StateSet> plan_states(Scene& scene, const PlanInputs& inputs);

}  // namespace arnoldweb::detail
