// arnoldweb: running a job's parts one after the other in this process
// (job.hpp), with checkpoints (job_checkpoints.hpp): after a chunk, when one
// is due or a stop request ends the job, the reductions of the parts begun
// are saved. A job resumed from a checkpoint skips the parts it holds
// complete and continues the current one with the trajectories not done.
#include <chrono>
#include <memory>

#include "arnoldweb/run.hpp"
#include "run/job_checkpoints.hpp"
#include "run/part_run.hpp"

namespace arnoldweb {
namespace {

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

JobResult run_job(const Job& job, Backend& backend, const RunOptions& options, JobObserver* observer) {
  JobResult jr;
  std::unique_ptr<detail::JobCheckpoints> cp;
  if (options.checkpoint && options.checkpoint->sink) cp = std::make_unique<detail::JobCheckpoints>(job, *options.checkpoint);
  detail::PartReductions parts;
  if (cp) parts = cp->resume();
  for (std::size_t k = 0; k < job.parts.size(); ++k) {
    const Plan& plan = job.parts[k].plan;
    if (k < parts.size() && parts[k]->complete() && k + 1 < parts.size()) {
      // done before the checkpoint: its result as it was
      Result r = parts[k]->result();
      r.device = backend.info();
      r.kernel = "(from a checkpoint)";
      r.trajectory_steps = static_cast<double>(r.completed) * static_cast<double>(plan.steps_per_trajectory);
      jr.results.push_back(std::move(r));
      continue;
    }
    // without checkpoints a stop skips the parts not begun; with them, the
    // part begins and its first request saves the checkpoint
    if (!cp && options.stop && options.stop->load()) {
      jr.interrupted = true;
      break;
    }
    if (k >= parts.size()) parts.push_back(std::make_unique<detail::Reduction>(plan));
    RunOptions o = options;
    if (observer) o.progress = observer->begin_part(job, k);
    detail::LocalQueue::After after;
    if (cp) {
      const double t0 = now_seconds();
      after = [&, k, t0](Backend& b, bool stopping) {
        if ((stopping && cp->active()) || (!stopping && cp->due(k, parts)))
          cp->save(k, parts, b.read_histograms(), stopping, now_seconds() - t0);
      };
    }
    jr.results.push_back(detail::run_part(plan, backend, o, *parts[k], after));
    if (jr.results.back().interrupted) {
      jr.interrupted = true;
      break;
    }
  }
  return jr;
}

}  // namespace arnoldweb
