// arnoldweb: the step schedule of a plan: steps per energy sample, samples per
// averaging window, windows per trajectory, frame boundaries. Every count is
// checked against overflow before it is made.
#include "plan/schedule.hpp"

#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "aw_params.h"
#include "plan/checks.hpp"

namespace arnoldweb::detail {
namespace {

// A trajectory has at most this many steps (10^15: years of device time for
// one trajectory; every count derived from it fits 64 bits and exact doubles).
constexpr double kMaxStepsPerTrajectory = 1e15;

std::string fmt(double v) { return show_number(v); }

void check_counts(const Scene& scene) {
  const double steps_wanted = scene.duration / scene.step;
  if (steps_wanted <= kMaxStepsPerTrajectory) return;
  // blame the key given last: an override of one of them, else the one later
  // in the file (a key left at its default is never given last)
  const auto given = [&](const char* key) {
    const SourcePos p = scene.pos(key);
    return std::make_tuple(p.set_index, p.line, p.column);
  };
  const bool step_last = given("integrator.step") > given("run.duration");
  fail_at(scene, step_last ? "integrator.step" : "run.duration",
          "run.duration / integrator.step = " + fmt(scene.duration) + " T / " + fmt(scene.step) + " T = " +
              fmt(steps_wanted) + " steps per trajectory; at most " + fmt(kMaxStepsPerTrajectory) +
              " are allowed: the largest run.duration with this step is " + fmt(kMaxStepsPerTrajectory * scene.step) +
              " T, the smallest integrator.step for this duration " + fmt(scene.duration / kMaxStepsPerTrajectory) +
              " T");
}

// run.slice: whole segments (the energy sample interval, or the window) per slice.
void plan_slices(const Scene& scene, Plan& p) {
  const std::int64_t segments = p.windows * p.segments_per_window;
  p.slices = 1;
  p.slice_segments = segments;
  if (scene.slice == 0 || scene.slice >= scene.duration) return;
  const double segment = scene.average / static_cast<double>(p.segments_per_window);
  const std::int64_t per_slice = exact_ratio(scene.slice, segment);
  if (per_slice == 0)
    fail_at(scene, "run.slice",
            "run.slice = " + fmt(scene.slice) + " T is not a multiple of the sample interval " + fmt(segment) +
                " T (the shortest of observe.energy_error.every, observe.frequencies.every, "
                "observe.diffusion.every, or run.average): a slice ends at a sample");
  p.slice_segments = per_slice;
  p.slices = (segments + per_slice - 1) / per_slice;
}

}  // namespace

void plan_schedule(const Scene& scene, Plan& p) {
  const std::vector<std::pair<std::string, double>>& intervals = p.sample_intervals;
  p.step = scene.step;
  check_counts(scene);
  const std::int64_t per_window = exact_ratio(scene.average, p.step);
  if (per_window == 0)
    fail_at(scene, "run.average",
            "run.average = " + fmt(scene.average) + " T is not a positive multiple of integrator.step = " +
                fmt(p.step) + " T (" + fmt(scene.average / p.step) + " steps)");
  p.windows = exact_ratio(scene.duration, scene.average);
  if (p.windows == 0)
    fail_at(scene, "run.duration",
            "run.duration = " + fmt(scene.duration) + " T is not a positive multiple of run.average = " +
                fmt(scene.average) + " T");
  const bool energy = scene.energy_error || scene.max_energy_error.has_value();
  // The segment: the finest sample interval asked for (the energy's, the
  // frequencies', the actions'); every other is a whole number of segments.
  double unit = energy ? scene.energy_every : scene.average;
  std::string unit_key = energy ? "observe.energy_error.every" : "run.average";
  for (const auto& [key, every] : intervals)
    if (every < unit) unit = every, unit_key = key;
  p.segments_per_window = exact_ratio(scene.average, unit);
  const std::int64_t seg_steps = exact_ratio(unit, p.step);
  if (p.segments_per_window == 0 || seg_steps == 0 || seg_steps * p.segments_per_window != per_window) {
    if (unit_key == "run.average")
      fail_at(scene, "run.average", "run.average = " + fmt(scene.average) + " T is not a multiple of integrator.step");
    fail_at(scene, unit_key,
            std::string(unit_key == "observe.energy_error.every" ? "the energy sample interval "
                                                                  : "the sample interval ") +
                fmt(unit) + " T must divide run.average = " + fmt(scene.average) +
                " T and be a multiple of integrator.step = " + fmt(p.step) + " T");
  }
  p.steps_per_segment = seg_steps;
  // how many segments apart each effect samples
  auto stride = [&](double every, const char* key) -> std::int64_t {
    const std::int64_t k = exact_ratio(every, unit);
    if (k == 0)
      fail_at(scene, key,
              fmt(every) + " T is not a multiple of the shortest sample interval, " + unit_key + " = " + fmt(unit) +
                  " T: every sample interval is a multiple of the shortest");
    return k;
  };
  p.energy_stride = energy ? stride(scene.energy_every, "observe.energy_error.every") : 1;
  p.strides.clear();
  for (const auto& [key, every] : intervals) p.strides[key] = stride(every, key.c_str());
  p.steps_per_trajectory = p.windows * per_window;
  plan_slices(scene, p);
  p.trajectory_steps = static_cast<double>(scene.trajectories) * static_cast<double>(p.steps_per_trajectory);
  p.force_evaluations = p.trajectory_steps * p.method.stages;
}

void plan_frames(const Scene& scene, Plan& p) {
  p.frames = 1;
  p.frame_bounds = {0, p.windows};
  if (scene.frame_times.empty()) return;
  if (!scene.velocity_map) fail_at(scene, "observe.frames", "frames are velocity maps: set observe.velocity_map too");
  if (static_cast<int>(scene.frame_times.size()) > AW_MAX_FRAMES + 1)
    fail_at(scene, "observe.frames.times", "at most " + std::to_string(AW_MAX_FRAMES + 1) + " times");
  p.frame_bounds.clear();
  for (double t : scene.frame_times) {
    const std::int64_t w = t == 0 ? 0 : exact_ratio(t, scene.average);
    if ((t != 0 && w == 0) || w > p.windows)
      fail_at(scene, "observe.frames.times",
              "frame time " + fmt(t) + " T is not a multiple of run.average = " + fmt(scene.average) +
                  " T between 0 and run.duration = " + fmt(scene.duration) + " T");
    p.frame_bounds.push_back(w);
  }
  p.frames = static_cast<int>(p.frame_bounds.size()) - 1;
}

}  // namespace arnoldweb::detail
