// arnoldweb: running one plan in this process: the device loop
// (chunk_loop.hpp) over the plan's index range, folded into a reduction
// (reduction.hpp).
#include "arnoldweb/run.hpp"

#include <stdexcept>

#include "run/chunk_loop.hpp"
#include "run/analyses.hpp"
#include "run/part_run.hpp"
#include "aw_params.h"
#include "plan/checks.hpp"

namespace arnoldweb {
namespace detail {

Result run_part(const Plan& plan, Backend& backend, const RunOptions& options, Reduction& reduction,
                const LocalQueue::After& after) {
  require_states(plan);
  const double before = reduction.seconds;
  LocalQueue queue(plan, reduction, options, after);
  drive_device(plan, backend, queue, options);
  reduction.add_histograms(backend.read_histograms());
  reduction.seconds = before + queue.seconds();
  Result r = reduction.result();
  r.device = backend.info();
  r.kernel = backend.kernel_description();
  r.startup = {inventory_seconds(), {backend.startup}};
  r.interrupted = queue.stopped();
  r.trajectory_steps = static_cast<double>(r.completed) * static_cast<double>(plan.steps_per_trajectory);
  if (r.completed == plan.scene.trajectories) analyse(plan, r);
  if (options.progress) options.progress->finish(r.completed, plan.scene.trajectories, r.wall_seconds);
  return r;
}

void require_states(const Plan& plan) {
  if (plan.kernel.initial != AW_INITIAL_FILE) return;
  if (!plan.states)
    fail_at(plan.scene, "ensemble.initial",
            "\"file\" starts every trajectory from a given state, and none were given (ensemble.file, or "
            "initial= from Python)");
  if (plan.states->count != plan.scene.trajectories)
    fail_at(plan.scene, "ensemble.trajectories",
            std::to_string(plan.states->count) + " states were given for " + std::to_string(plan.scene.trajectories) +
                " trajectories");
}

}  // namespace detail

Result run(const Plan& plan, Backend& backend, const RunOptions& options) {
  detail::Reduction reduction(plan);
  return detail::run_part(plan, backend, options, reduction, {});
}

Result run_range(const Plan& plan, Backend& backend, std::uint64_t first, std::uint64_t count,
                 const RunOptions& options) {
  if (count == 0 || first >= plan.scene.trajectories || count > plan.scene.trajectories - first)
    throw std::invalid_argument("run_range: trajectories [" + std::to_string(first) + ", " +
                                std::to_string(first + count) + ") are not a range of the plan's " +
                                std::to_string(plan.scene.trajectories));
  if (plan.slices > 1)
    detail::fail_at(plan.scene, "run.slice", "a run of some trajectories runs them whole: set run.slice = 0");
  detail::Reduction reduction(plan);
  reduction.restrict_to({first, count});
  return detail::run_part(plan, backend, options, reduction, {});
}

}  // namespace arnoldweb
