// arnoldweb: the search for the cheapest method and step that meets an
// energy tolerance (docs/accuracy.md), as planning: it plans the pilot's
// ensembles (the scene's first trajectories over a few T, |dE| sampled), asks
// `measure` for what each one gives, fits the errors and decides. It runs
// nothing itself: accuracy.cpp measures on a device (run()), and a test can
// measure with a formula. The report is accuracy_report.hpp's.
#pragma once

#include <cstdint>
#include <functional>

#include "arnoldweb/accuracy_report.hpp"
#include "arnoldweb/plan.hpp"

namespace arnoldweb::detail {

// What one pilot ensemble gave: max and median over its trajectories of
// max_t |dE| (infinite where a trajectory was lost), its rate in
// trajectory-steps per second, and its wall time.
struct PilotRun {
  double max = 0, median = 0;
  double rate = 0, wall_seconds = 0;
};
using PilotMeasure = std::function<PilotRun(const Plan& pilot)>;

// The report for `scene` (with its inputs) at `tolerance`; `preferred_chunk`:
// the device's, the least ensemble the rate is measured on. Throws SceneError
// for an invalid scene or a tolerance below round-off; device errors come from `measure`.
AccuracyReport search_step(const Scene& scene, const PlanInputs& inputs, double tolerance, const PilotOptions& o,
                           std::uint64_t preferred_chunk, const PilotMeasure& measure);

}  // namespace arnoldweb::detail
