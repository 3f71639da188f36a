// arnoldweb: a worker thread of this process (local_devices.cpp): serves the
// coordinator over `channel`; an exception becomes an Error message naming
// `who` and the device.
#pragma once

#include <string>

#include "arnoldweb/run.hpp"
#include "scale/transport.hpp"

namespace arnoldweb::detail {

void local_worker(const Job& job, Backend& backend, Channel& channel, const RunOptions& options,
                  const std::string& who);

}  // namespace arnoldweb::detail
