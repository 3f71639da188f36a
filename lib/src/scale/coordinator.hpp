// arnoldweb: the coordinator of a job spread over several devices (MPI ranks,
// or threads): it hands out ranges of trajectories to whichever worker asks
// (dynamic: a slower device takes fewer), folds every chunk's outputs into
// the part's exact reduction (run/reduction.hpp) and the workers' histograms
// at the end, reports progress as totals, and saves checkpoints: a periodic
// one parks every worker between chunks, collects their histograms and saves
// (run/job_checkpoints.hpp); a stop request ends every worker after its chunk
// and saves. The result is the same bits for any number of workers and any
// assignment of chunks.
#pragma once

#include <functional>
#include <string>

#include "arnoldweb/run.hpp"
#include "scale/transport.hpp"

namespace arnoldweb::detail {

// `device`: what the results name; `describe` names in the result of the
// part that has just ended the devices' kernels and start-up (Result::kernel,
// Result::startup) as they were prepared for it.
JobResult coordinate_job(const Job& job, Transport& transport, const RunOptions& options, JobObserver* observer,
                         const DeviceInfo& device, const std::function<void(Result&)>& describe);

}  // namespace arnoldweb::detail
