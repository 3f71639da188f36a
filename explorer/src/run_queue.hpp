// arnoldweb explorer: the runs a server starts (a scene given to serve, the zooms pages ask
// for), one at a time on the server's device, through the library's public API as the CLI runs
// them: the job planned and its output place checked before it is queued (so a bad request is
// refused and changes nothing), checkpoints by CheckpointStore, outputs by write_job. A
// cancelled run writes nothing; a run stopped by the server's shutdown keeps a checkpoint
// (`arnoldweb resume` continues it).
#pragma once

#include <nlohmann/json.hpp>

#include <atomic>
#include <condition_variable>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "arnoldweb/arnoldweb.hpp"
#include "arnoldweb/cluster.hpp"

namespace arnoldweb::explorer {

// A job ready to run: planned, its output directory checked (the CLI's prepare_job, through the
// library's API).
struct PreparedRun {
  Job job;
  OutputOptions output;
  std::string out_dir;
};
// Throws SceneError (bad scene), OutputError (the place), DeviceError.
PreparedRun prepare_run(const Scene& scene, const std::string& device);

class RunQueue {
 public:
  // `finished(id, out_dir)` is called (on the queue's thread) when a run has written its outputs.
  RunQueue(std::string device, std::function<void(const std::string& id, const std::string& out_dir)> finished);
  ~RunQueue();
  RunQueue(const RunQueue&) = delete;
  RunQueue& operator=(const RunQueue&) = delete;

  // Queues a prepared run under `id`, with `info` (e.g. its region) echoed in its status.
  void submit(const std::string& id, PreparedRun run, nlohmann::json info);
  // {id, state: queued|running|done|failed|cancelled|stopped, done, total, seconds, error, dir, ...info}
  // or null for an unknown id.
  nlohmann::json status(const std::string& id) const;
  nlohmann::json list() const;
  // Cancels a queued or running run (false: unknown or finished). A running one stops after its
  // chunk and writes nothing.
  bool cancel(const std::string& id);
  // Stops the queue: the running run after its chunk, checkpointed; the queued ones are dropped.
  // Returns what happened to the running one ("" if none).
  std::string shutdown();
  const std::string& device() const { return device_; }

 private:
  struct Task;
  void work();
  void execute(Task& t);

  std::string device_;
  std::function<void(const std::string&, const std::string&)> finished_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::map<std::string, std::shared_ptr<Task>> tasks_;
  std::deque<std::shared_ptr<Task>> queue_;
  std::shared_ptr<Task> running_;
  std::string stopped_note_;
  bool closing_ = false;
  std::atomic<bool> shutting_down_{false};
  std::thread worker_;
};

}  // namespace arnoldweb::explorer
