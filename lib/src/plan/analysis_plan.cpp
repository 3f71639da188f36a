// arnoldweb: the planner's part for the frequency analysis and the output
// table's table keys (analysis_plan.hpp).
#include "plan/analysis_plan.hpp"

#include "plan/checks.hpp"

namespace arnoldweb::detail {
namespace {

std::string fmt(double v) { return show_number(v); }

// The segment's length in T (the shortest sample interval).
double segment_length(const Scene& scene, const Plan& p) {
  return scene.average / static_cast<double>(p.segments_per_window);
}

}  // namespace

KeyPlan key_plan(const Scene& scene, const Plan& p) {
  return {scene.trajectories, scene.duration, segment_length(scene, p), p.start_time(), exact_ratio, show_number,
          show_count, p.slices, p.slice_segments, scene.slice, p.strides};
}

void plan_analysis(const Scene& scene, const Plan& p) {
  const std::int64_t segments = p.windows * p.segments_per_window;
  if (scene.frequencies) {
    const double needed = 2.0 * scene.frequency_samples * scene.frequency_every;
    if (static_cast<double>(segments / p.frequency_stride) < 2.0 * scene.frequency_samples)
      fail_at(scene, "observe.frequencies.samples",
              "two windows of " + show_count(scene.frequency_samples) + " samples every " +
                  fmt(scene.frequency_every) + " T take " + fmt(needed) + " T, and run.duration is " +
                  fmt(scene.duration) + " T: choose fewer samples, a shorter interval or a longer run");
    if (p.slices > 1)
      fail_at(scene, "run.slice",
              "the frequency analysis keeps a window's samples on the device between time slices, which slices "
              "do not carry: run observe.frequencies without run.slice");
  }
  for (const KeyTable* t : key_tables())  // the output table's table keys, against the schedule
    if (t->check && t->on(scene.output_values))
      if (const KeyProblem why = t->check(*t, scene.output_values, key_plan(scene, p)); !why.key.empty())
        fail_at(scene, why.key, why.message);
}

void fill_analysis_ints(const Scene& scene, const Plan& p, IntParams& ip) {
  ip.energy_stride = p.energy_stride;
  ip.frequency_stride = p.frequency_stride;
  if (scene.frequencies) {
    ip.frequency_samples = scene.frequency_samples;
    ip.frequency_order = scene.frequency_window;
    ip.series_reals = AW_FREQ_SERIES_REALS(scene.frequency_samples);  // both windows, the rates, a flag
  }
  for (const KeyTable* t : key_tables())
    if (t->fill) t->fill(*t, scene.output_values, key_plan(scene, p), ip);
}

void fill_analysis_reals(const Scene& scene, const Plan& p, RealParams& rp) {
  if (scene.frequencies) rp.frequency_every = scene.frequency_every;
  for (const KeyTable* t : key_tables())
    if (t->fill_reals && t->on(scene.output_values)) t->fill_reals(*t, scene.output_values, key_plan(scene, p), rp);
}

}  // namespace arnoldweb::detail
