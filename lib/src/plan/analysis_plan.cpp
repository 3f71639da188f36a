// arnoldweb: the planner's part for the output table's table keys
// (analysis_plan.hpp).
#include "plan/analysis_plan.hpp"

#include "plan/checks.hpp"

namespace arnoldweb::detail {
namespace {

// The segment's length in T (the shortest sample interval).
double segment_length(const Scene& scene, const Plan& p) {
  return scene.average / static_cast<double>(p.segments_per_window);
}

}  // namespace

KeyPlan key_plan(const Scene& scene, const Plan& p) {
  return {scene.trajectories, scene.duration, segment_length(scene, p), p.start_time(), exact_ratio, show_number,
          show_count, p.slices, p.slice_segments, scene.slice, p.strides,
          p.windows * p.segments_per_window};
}

void plan_analysis(const Scene& scene, const Plan& p) {
  for (const KeyTable* t : key_tables())  // the output table's table keys, against the schedule
    if (t->check && t->on(scene.output_values))
      if (const KeyProblem why = t->check(*t, scene.output_values, key_plan(scene, p)); !why.key.empty())
        fail_at(scene, why.key, why.message);
}

void fill_analysis_ints(const Scene& scene, const Plan& p, IntParams& ip) {
  ip.energy_stride = p.energy_stride;
  for (const KeyTable* t : key_tables())
    if (t->fill) t->fill(*t, scene.output_values, key_plan(scene, p), ip);
}

void fill_analysis_reals(const Scene& scene, const Plan& p, RealParams& rp) {
  for (const DirectionKey* k : direction_keys())
    if (k->fill_reals) k->fill_reals(k->value(scene.output_values), rp);
  for (const KeyTable* t : key_tables())
    if (t->fill_reals && t->on(scene.output_values)) t->fill_reals(*t, scene.output_values, key_plan(scene, p), rp);
}

}  // namespace arnoldweb::detail
