// arnoldweb: the loop that keeps one device busy. It asks a work queue for
// the next range of trajectories, runs it, hands the outputs back with the
// next request, and sizes its requests to about RunOptions::chunk_seconds per
// launch (never below one wave of the device, always a multiple of the chunk
// granule). The queue decides what is left, folds the outputs and says when
// to stop: one process (LocalQueue) or a rank of an MPI job (run/mpi/) use
// the same loop.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "arnoldweb/device.hpp"
#include "arnoldweb/run.hpp"
#include "run/reduction.hpp"

namespace arnoldweb::detail {

class WorkQueue {
 public:
  virtual ~WorkQueue() = default;
  // Takes the outputs of `finished` (count 0 the first time) and returns the
  // next work for a device that wants about `want` trajectories (count 0:
  // nothing more for this device), with the records it starts from where the
  // plan has them (their storage is the queue's, valid until the next call).
  // The records of `out` may be taken (moved) by the queue: the device fills
  // them afresh for every chunk. `backend` holds the histograms of every
  // range it ran, for a queue that saves a checkpoint now.
  virtual ChunkWork next(const ChunkWork& finished, ChunkOutput& out, std::uint64_t want, Backend& backend) = 0;
};

// The records the trajectories [first, first + count) start from when the
// plan gives their states (ensemble.initial = "file"): each one's carry
// columns hold its state, the rest is zero.
void initial_records(const Plan& plan, std::uint64_t first, std::uint64_t count, std::vector<double>& rec_r,
                     std::vector<std::int64_t>& rec_i);

// The work of a range over the whole schedule, with the records it starts
// from (filled into rec_r, rec_i) where the plan gives states.
ChunkWork whole_work(const Plan& plan, const IndexRange& range, std::vector<double>& rec_r,
                     std::vector<std::int64_t>& rec_i);

// Chunks start at multiples of this (ensemble.chunk if set, else kChunkGranule;
// never above the largest chunk the device takes).
std::uint64_t chunk_granule(const Plan& plan, std::uint64_t max_chunk);

// The first range of `pending` (which it shortens), at most `want` long and
// ending at a multiple of `granule` unless it ends a pending range.
IndexRange take_range(std::vector<IndexRange>& pending, std::uint64_t want, std::uint64_t granule);

// Prepares `backend` for the plan and runs ranges from `queue` until it gives none.
void drive_device(const Plan& plan, Backend& backend, WorkQueue& queue, const RunOptions& options);

// The queue of one process: the pending ranges of a reduction, in order. It
// folds every output into the reduction, reports progress, calls `after`
// after each chunk (checkpoints) and stops at a stop request.
class LocalQueue final : public WorkQueue {
 public:
  using After = std::function<void(Backend&, bool stopping)>;
  LocalQueue(const Plan& plan, Reduction& reduction, const RunOptions& options, After after = {});
  ChunkWork next(const ChunkWork& finished, ChunkOutput& out, std::uint64_t want, Backend& backend) override;
  bool stopped() const { return stopped_; }
  double seconds() const;  // since the queue was made

 private:
  const Plan& plan_;
  Reduction& reduction_;
  const RunOptions& options_;
  After after_;
  std::vector<IndexRange> pending_;
  std::uint64_t granule_;
  bool stopped_ = false;
  double start_;
  std::vector<double> rec_r_;  // the records the work starts from
  std::vector<std::int64_t> rec_i_;
};

}  // namespace arnoldweb::detail
