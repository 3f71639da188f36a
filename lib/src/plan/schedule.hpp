// arnoldweb: the parts of planning that turn times into step counts.
#pragma once

#include "arnoldweb/plan.hpp"

namespace arnoldweb::detail {

// step, steps_per_segment, segments_per_window, windows, steps_per_trajectory,
// trajectory_steps, force_evaluations (p.method and p.sample_intervals must be
// set). Throws SceneError.
void plan_schedule(const Scene& scene, Plan& p);
// frames and frame_bounds (after plan_schedule). Throws SceneError.
void plan_frames(const Scene& scene, Plan& p);

}  // namespace arnoldweb::detail
