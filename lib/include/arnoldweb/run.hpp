// arnoldweb: running a plan on a backend, chunk by chunk.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <string>

#include "arnoldweb/device.hpp"
#include "arnoldweb/job.hpp"
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

// Where a run's checkpoints go (checkpoint.hpp writes and reads them).
class CheckpointSink {
 public:
  virtual ~CheckpointSink() = default;
  // Stores a checkpoint image atomically, replacing the previous one. Throws OutputError.
  virtual void save(const std::string& image) = 0;
};

// Checkpointing of a job (run_job): its state is saved every `every_seconds`
// of wall-clock time and when a stop request ends it early.
struct Checkpointing {
  CheckpointSink* sink = nullptr;
  // > 0: every so many seconds; 0: only when stopped early; < 0 ("auto"):
  // every 600 s (and when stopped) once the job's remaining time, estimated
  // from its progress, takes it past an hour; otherwise never.
  double every_seconds = -1;
  // A checkpoint image to continue from ("" to start afresh); a damaged one,
  // or one of another scene or version, is a CheckpointError.
  std::string resume;
  std::string resume_path;  // where it was read, for messages
  // Out: how many checkpoints were saved, and whether the last one holds a
  // job that was stopped before it was complete.
  int saved = 0;
  bool saved_incomplete = false;
};

struct RunOptions {
  Progress* progress = nullptr;
  // Set to true (e.g. from a signal handler) to stop after the current chunk;
  // the result then holds the completed trajectories and interrupted = true.
  const std::atomic<bool>* stop = nullptr;
  // Target seconds per launch when the scene leaves the chunk size to the
  // runner: short enough for progress and display watchdogs.
  double chunk_seconds = 0.25;
  // Checkpoints of the job (run_job only; run() ignores it).
  Checkpointing* checkpoint = nullptr;
};

// Run every trajectory of the plan. Chunks are a partition of the index range,
// so the result does not depend on how it is split. Throws DeviceError.
Result run(const Plan& plan, Backend& backend, const RunOptions& options = {});
// Run only trajectories [first, first + count) of the plan, each with the bits
// it has in a run of all (`arnoldweb orbit`): the result holds their outputs
// (completed = count; the maps and counts are theirs). Not in time slices.
Result run_range(const Plan& plan, Backend& backend, std::uint64_t first, std::uint64_t count,
                 const RunOptions& options = {});

// ------------------------------------------------------------------ jobs
struct JobResult {
  std::vector<Result> results;  // one per part that ran, in order
  bool interrupted = false;     // a stop request ended the job early
};

// Told when each part of a job starts; returns the progress receiver for it
// (or null).
class JobObserver {
 public:
  virtual ~JobObserver() = default;
  virtual Progress* begin_part(const Job& job, std::size_t index) = 0;
};

// Runs every part on `backend`; a stop request (options.stop) ends the part
// that is running after its current chunk and skips the rest.
JobResult run_job(const Job& job, Backend& backend, const RunOptions& options = {},
                  JobObserver* observer = nullptr);

}  // namespace arnoldweb
