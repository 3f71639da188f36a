// arnoldweb: the planner's part for the output table's table keys
// (observe.frequencies, observe.diffusion, observe.trajectories: their rows'
// checks and parameters, lib/src/output_table/): their checks against the
// schedule and their parameters in the kernels' blocks.
#pragma once

#include "arnoldweb/plan.hpp"
#include "output_table/output_table.hpp"
#include "params/kernel_params.hpp"

namespace arnoldweb::detail {

// What the output table's table keys take from the plan (KeyPlan): the
// schedule's facts and the planner's exact ratios and number formats.
KeyPlan key_plan(const Scene& scene, const Plan& p);

// Checks (SceneError naming the key) after the schedule is made.
void plan_analysis(const Scene& scene, const Plan& p);

// Their parameters (the strides come from the schedule).
void fill_analysis_ints(const Scene& scene, const Plan& p, IntParams& ip);
void fill_analysis_reals(const Scene& scene, const Plan& p, RealParams& rp);

}  // namespace arnoldweb::detail
