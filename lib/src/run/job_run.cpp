// arnoldweb: running a job's parts one after the other (job.hpp).
#include "arnoldweb/job.hpp"

namespace arnoldweb {

JobResult run_job(const Job& job, Backend& backend, const RunOptions& options, JobObserver* observer) {
  JobResult jr;
  for (std::size_t k = 0; k < job.parts.size(); ++k) {
    if (options.stop && options.stop->load()) {
      jr.interrupted = true;
      break;
    }
    RunOptions o = options;
    if (observer) o.progress = observer->begin_part(job, k);
    jr.results.push_back(run(job.parts[k].plan, backend, o));
    if (jr.results.back().interrupted) {
      jr.interrupted = true;
      break;
    }
  }
  return jr;
}

}  // namespace arnoldweb
