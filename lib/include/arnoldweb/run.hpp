// arnoldweb: running a plan on a backend, chunk by chunk.
#pragma once

#include <atomic>
#include <cstdint>

#include "arnoldweb/device.hpp"
#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"

namespace arnoldweb {

// Receives progress after every chunk.
class Progress {
 public:
  virtual ~Progress() = default;
  virtual void update(std::uint64_t done, std::uint64_t total, double seconds) = 0;
  virtual void finish(std::uint64_t done, std::uint64_t total, double seconds) = 0;
};

struct RunOptions {
  Progress* progress = nullptr;
  // Set to true (e.g. from a signal handler) to stop after the current chunk;
  // the result then holds the completed trajectories and interrupted = true.
  const std::atomic<bool>* stop = nullptr;
  // Target seconds per launch when the scene leaves the chunk size to the
  // runner: short enough for progress and display watchdogs.
  double chunk_seconds = 0.25;
};

// Run every trajectory of the plan. Chunks are a partition of the index range,
// so the result does not depend on how it is split. Throws DeviceError.
Result run(const Plan& plan, Backend& backend, const RunOptions& options = {});

}  // namespace arnoldweb
