// arnoldweb: a worker of a job spread over several devices: it runs the
// parts the coordinator begins, with the ranges it hands out, on its device,
// through the same device loop as one process (run/chunk_loop.hpp).
#pragma once

#include "arnoldweb/run.hpp"
#include "scale/transport.hpp"

namespace arnoldweb::detail {

// Serves until the coordinator ends the job. options.stop is passed on to
// the coordinator with every request. Throws what the device throws.
void work_job(const Job& job, Backend& backend, Channel& channel, const RunOptions& options);

}  // namespace arnoldweb::detail
