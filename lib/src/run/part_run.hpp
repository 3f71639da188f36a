// arnoldweb: one part of a job run in this process, continuing `reduction`
// (empty, or read from a checkpoint); `after` is called after every chunk
// with the backend (for checkpoints). The reduction then holds the device's
// histograms too.
#pragma once

#include "run/chunk_loop.hpp"

namespace arnoldweb::detail {

Result run_part(const Plan& plan, Backend& backend, const RunOptions& options, Reduction& reduction,
                const LocalQueue::After& after);

}  // namespace arnoldweb::detail
