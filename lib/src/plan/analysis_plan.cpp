// arnoldweb: the planner's part for the frequency analysis, the diffusion
// samples and the output table's table keys (analysis_plan.hpp).
#include "plan/analysis_plan.hpp"

#include <algorithm>
#include <cmath>

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
          show_count};
}

void plan_analysis(const Scene& scene, const Plan& p) {
  const std::int64_t segments = p.windows * p.segments_per_window;
  for (const KeyTable* t : key_tables())  // the output table's table keys, against the schedule
    if (t->check && t->on(scene.output_values))
      if (const KeyProblem why = t->check(*t, scene.output_values, key_plan(scene, p)); !why.key.empty())
        fail_at(scene, why.key, why.message);
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
  if (scene.diffusion) {
    if (exact_ratio(scene.duration, scene.diffusion_every) == 0)
      fail_at(scene, "observe.diffusion.every",
              fmt(scene.diffusion_every) + " T does not divide run.duration = " + fmt(scene.duration) + " T");
    const auto& a = scene.diffusion_along;
    const auto& c = scene.diffusion_across;
    const double dot = a[0] * c[0] + a[1] * c[1] + a[2] * c[2];
    const double na = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    const double nc = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    if (std::fabs(dot) > (1 - 1e-9) * na * nc)
      fail_at(scene, "observe.diffusion.across", "is parallel to observe.diffusion.along: choose a direction across it");
    if (scene.diffusion_average > 0) {
      const std::int64_t points = exact_ratio(scene.diffusion_average, scene.diffusion_average_every);
      if (points == 0)
        fail_at(scene, "observe.diffusion.average_every",
                fmt(scene.diffusion_average_every) + " T does not divide observe.diffusion.average = " +
                    fmt(scene.diffusion_average) + " T");
      if (scene.diffusion_average > scene.diffusion_every)
        fail_at(scene, "observe.diffusion.average",
                fmt(scene.diffusion_average) + " T is longer than the sample interval observe.diffusion.every = " +
                    fmt(scene.diffusion_every) + " T: the spans of two samples would overlap");
      if (p.slices > 1 && p.slice_segments % p.diffusion_stride != 0)
        fail_at(scene, "run.slice",
                "with observe.diffusion.average a time slice ends at a sample time: run.slice = " +
                    fmt(scene.slice) + " T must be a multiple of observe.diffusion.every = " +
                    fmt(scene.diffusion_every) + " T");
    }
    if (!(scene.diffusion_fit_from < scene.duration))
      fail_at(scene, "observe.diffusion.fit_from",
              fmt(scene.diffusion_fit_from) + " T is not before the end of the run (run.duration = " +
                  fmt(scene.duration) + " T)");
  }
}

void fill_analysis_ints(const Scene& scene, const Plan& p, IntParams& ip) {
  ip.energy_stride = p.energy_stride;
  ip.frequency_stride = p.frequency_stride;
  ip.diffusion_stride = p.diffusion_stride;
  if (scene.frequencies) {
    ip.frequency_samples = scene.frequency_samples;
    ip.frequency_order = scene.frequency_window;
    ip.series_reals = AW_FREQ_SERIES_REALS(scene.frequency_samples);  // both windows, the rates, a flag
  }
  if (scene.diffusion) ip.diffusion_samples = exact_ratio(scene.duration, scene.diffusion_every);
  ip.diffusion_average_stride = p.diffusion_average_stride;
  ip.diffusion_average_points =
      scene.diffusion && scene.diffusion_average > 0 ? exact_ratio(scene.diffusion_average, scene.diffusion_average_every) : 0;
  for (const KeyTable* t : key_tables())
    if (t->fill) t->fill(*t, scene.output_values, key_plan(scene, p), ip);
}

void fill_analysis_reals(const Scene& scene, RealParams& rp) {
  if (scene.frequencies) rp.frequency_every = scene.frequency_every;
  if (scene.diffusion && scene.diffusion_average > 0)
    rp.diffusion_average_weight = 1.0 / static_cast<double>(exact_ratio(scene.diffusion_average, scene.diffusion_average_every));
}

}  // namespace arnoldweb::detail
