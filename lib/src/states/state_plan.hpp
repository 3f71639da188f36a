// arnoldweb: what the planner asks of ensemble.initial = "file" (state_energy.cpp).
#pragma once

#include "arnoldweb/scene.hpp"

namespace arnoldweb::detail {

// ensemble.file with ensemble.initial = "file" and only then; the file read
// and checked against the scene (StateError naming the row). Throws
// SceneError for the keys, StateError for the states; until the kernels can
// start from stored states, a SceneError saying so for "file".
void plan_initial_states(const Scene& scene);

}  // namespace arnoldweb::detail
