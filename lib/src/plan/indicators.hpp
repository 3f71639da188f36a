// arnoldweb: the planner's part for the chaos indicators and grids of initial
// conditions (docs/indicators.md): the grid's size (it is the number of
// trajectories), its parameters and checks, the initial tangent vector.
#pragma once

#include <cstdint>

#include "arnoldweb/plan.hpp"
#include "physics/model_table.hpp"
#include "params/kernel_params.hpp"

namespace arnoldweb::detail {

// Points of the scene's grid (ensemble.initial = "grid"), 0 otherwise.
std::uint64_t grid_points(const Scene& scene);

// The scene with ensemble.trajectories = the grid's points (a grid scene), or
// as it is. A grid scene that sets ensemble.trajectories to another number
// is refused (SceneError naming both).
Scene with_grid_size(const Scene& scene);

// Checks a grid scene's values together (E > V at the position for direction
// grids) and sets the plan's accessible fraction (1: no draws).
void plan_grid(const Scene& scene, const ModelDescriptor& model, const RealParams& rp, Plan& p);

// The indicators' and the grid's parameters.
void fill_indicator_reals(const Scene& scene, const Plan& p, RealParams& rp);
void fill_indicator_ints(const Scene& scene, IntParams& ip);

}  // namespace arnoldweb::detail
