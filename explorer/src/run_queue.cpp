#include "run_queue.hpp"

#include <chrono>

namespace arnoldweb::explorer {

PreparedRun prepare_run(const Scene& scene, const std::string& device) {
  PreparedRun p;
  // what the scene takes from outside read first; integrator.step = "auto": the pilot on the cpu backend, as the CLI
  p.job = plan_job(scene, read_plan_inputs(scene), cpu_pilot());
  p.output.expected_bytes = estimate_output_bytes(p.job);
  const std::uint64_t host = available_memory();
  for (const std::string& id : device_ids(device.empty() ? scene.device : device))
    for (const JobPart& part : p.job.parts) check_memory(part.plan, find_device(id), host);
  p.out_dir = check_output_dir(p.job.main().scene.output_dir, p.output);
  return p;
}

struct RunQueue::Task {
  std::string id;
  PreparedRun run;
  nlohmann::json info;
  std::string state = "queued", error;
  std::atomic<bool> stop{false};
  std::atomic<std::uint64_t> done{0}, total{0};
  std::atomic<double> seconds{0};
};

namespace {

class TaskProgress final : public Progress, public JobObserver {
 public:
  TaskProgress(std::atomic<std::uint64_t>& done, std::atomic<std::uint64_t>& total, std::atomic<double>& seconds)
      : done_(done), total_(total), seconds_(seconds) {}
  void update(std::uint64_t done, std::uint64_t total, double seconds) override {
    done_ = done;
    total_ = total;
    seconds_ = seconds;
  }
  void finish(std::uint64_t done, std::uint64_t total, double seconds) override { update(done, total, seconds); }
  Progress* begin_part(const Job&, std::size_t) override { return this; }

 private:
  std::atomic<std::uint64_t>& done_;
  std::atomic<std::uint64_t>& total_;
  std::atomic<double>& seconds_;
};

// Saves a stopped run's checkpoint only when the server is shutting down: a cancelled run
// leaves nothing behind.
class ShutdownCheckpoints final : public CheckpointSink {
 public:
  ShutdownCheckpoints(CheckpointStore& store, const std::atomic<bool>& shutting_down)
      : store_(store), shutting_down_(shutting_down) {}
  void save(const std::string& image) override {
    if (shutting_down_) store_.save(image);
  }

 private:
  CheckpointStore& store_;
  const std::atomic<bool>& shutting_down_;
};

}  // namespace

RunQueue::RunQueue(std::string device, std::function<void(const std::string&, const std::string&)> finished)
    : device_(std::move(device)), finished_(std::move(finished)), worker_([this] { work(); }) {}

RunQueue::~RunQueue() {
  shutdown();
  if (worker_.joinable()) worker_.join();
}

void RunQueue::submit(const std::string& id, PreparedRun run, nlohmann::json info) {
  auto t = std::make_shared<Task>();
  t->id = id;
  t->total = run.job.main().scene.trajectories;
  t->run = std::move(run);
  t->info = std::move(info);
  std::lock_guard<std::mutex> lock(mutex_);
  tasks_[id] = t;
  queue_.push_back(t);
  wake_.notify_all();
}

nlohmann::json RunQueue::status(const std::string& id) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = tasks_.find(id);
  if (it == tasks_.end()) return nullptr;
  const Task& t = *it->second;
  nlohmann::json j = t.info;
  j["id"] = t.id;
  j["state"] = t.state;
  j["done"] = t.done.load();
  j["total"] = t.total.load();
  j["seconds"] = t.seconds.load();
  if (!t.error.empty()) j["error"] = t.error;
  return j;
}

nlohmann::json RunQueue::list() const {
  std::vector<std::string> ids;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& [id, t] : tasks_) ids.push_back(id);
  }
  nlohmann::json a = nlohmann::json::array();
  for (const auto& id : ids) a.push_back(status(id));
  return a;
}

bool RunQueue::cancel(const std::string& id) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = tasks_.find(id);
  if (it == tasks_.end()) return false;
  Task& t = *it->second;
  if (t.state == "queued") {
    t.state = "cancelled";
    for (auto q = queue_.begin(); q != queue_.end(); ++q)
      if ((*q)->id == id) {
        queue_.erase(q);
        break;
      }
    return true;
  }
  if (t.state != "running") return false;
  t.stop = true;
  return true;
}

std::string RunQueue::shutdown() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (closing_) return stopped_note_;
  closing_ = true;
  shutting_down_ = true;
  for (auto& t : queue_) t->state = "cancelled";
  queue_.clear();
  if (running_) running_->stop = true;
  wake_.notify_all();
  lock.unlock();
  if (worker_.joinable()) worker_.join();
  return stopped_note_;
}

void RunQueue::work() {
  for (;;) {
    std::shared_ptr<Task> t;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [this] { return closing_ || !queue_.empty(); });
      if (closing_) return;
      t = queue_.front();
      queue_.pop_front();
      t->state = "running";
      running_ = t;
    }
    execute(*t);
    std::lock_guard<std::mutex> lock(mutex_);
    running_.reset();
  }
}

void RunQueue::execute(Task& t) {
  const PreparedRun& p = t.run;
  std::string state, error;
  try {
    const auto backends = open_backends(device_.empty() ? p.job.main().scene.device : device_);
    std::vector<Backend*> devices;
    for (const auto& b : backends) devices.push_back(b.get());
    CheckpointStore store(p.out_dir, p.output);
    ShutdownCheckpoints sink(store, shutting_down_);
    Checkpointing checkpoints;
    checkpoints.sink = &sink;
    checkpoints.every_seconds = 0;  // only when stopped, and then only at a shutdown
    RunOptions options;
    options.stop = &t.stop;
    options.checkpoint = &checkpoints;
    TaskProgress progress(t.done, t.total, t.seconds);
    const JobResult result = run_job_on(p.job, devices, options, &progress);
    if (result.interrupted) {
      if (shutting_down_ && checkpoints.saved_incomplete) {
        state = "stopped";
        std::lock_guard<std::mutex> lock(mutex_);
        stopped_note_ = "run " + t.id + " stopped after " + std::to_string(t.done.load()) + " of " +
                        std::to_string(t.total.load()) + " trajectories; checkpoint written to " + store.file() +
                        "; continue with `arnoldweb resume " + p.out_dir + "`";
      } else {
        state = "cancelled";
      }
    } else {
      OutputOptions output = p.output;
      output.staging = store.staging();
      write_job(p.job, result, output);
      state = "done";
    }
  } catch (const std::exception& e) {
    state = "failed";
    error = e.what();
  }
  if (state == "done" && finished_) {
    try {
      finished_(t.id, p.out_dir);
    } catch (const std::exception& e) {
      state = "failed";
      error = std::string("its outputs were written to ") + p.out_dir + " but cannot be read back: " + e.what();
    }
  }
  std::lock_guard<std::mutex> lock(mutex_);
  t.state = state;
  t.error = error;
}

}  // namespace arnoldweb::explorer
