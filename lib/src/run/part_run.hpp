// arnoldweb: one part of a job run in this process, continuing `reduction`
// (empty, or read from a checkpoint); `after` is called after every chunk
// with the backend (for checkpoints). The reduction then holds the device's
// histograms too.
#pragma once

#include "run/chunk_loop.hpp"

namespace arnoldweb::detail {

Result run_part(const Plan& plan, Backend& backend, const RunOptions& options, Reduction& reduction,
                const LocalQueue::After& after);

// A plan that starts from given states (ensemble.initial = "file") has one
// per trajectory; SceneError otherwise.
void require_states(const Plan& plan);

}  // namespace arnoldweb::detail
