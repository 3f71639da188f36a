// arnoldweb: the coordinator of a job over several devices (coordinator.hpp).
#include "scale/coordinator.hpp"

#include <chrono>
#include <stdexcept>

#include "arnoldweb/errors.hpp"
#include "plan/checks.hpp"
#include "run/chunk_loop.hpp"
#include "run/job_checkpoints.hpp"
#include "run/analyses.hpp"
#include "run/part_run.hpp"
#include "scale/messages.hpp"

namespace arnoldweb::detail {
namespace {

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void add_into(std::vector<std::uint64_t>& sum, const std::vector<std::uint64_t>& h) {
  if (h.empty()) return;
  if (sum.empty()) sum.assign(h.size(), 0);
  for (std::size_t i = 0; i < h.size() && i < sum.size(); ++i) sum[i] += h[i];
}

// One part over every worker.
class PartCoordinator {
 public:
  PartCoordinator(const Job& job, std::size_t k, PartReductions& parts, Transport& t, const RunOptions& o,
                  JobCheckpoints* cp)
      : job_(job), k_(k), parts_(parts), red_(*parts[k]), t_(t), o_(o), cp_(cp),
        pending_(red_.pending()), granule_(chunk_granule(job.parts[k].plan, largest_chunk(job.parts[k].plan))),
        workers_(t.workers()), want_(workers_, 1), snap_(workers_), final_(workers_), finished_(workers_, false) {}

  bool run(double& seconds) {
    const double t0 = now_seconds(), before = red_.seconds;
    Message begin;
    begin.type = MessageType::Begin;
    begin.part = k_;
    for (int w = 0; w < workers_; ++w) t_.send(w, encode(begin));
    const std::uint64_t n = job_.parts[k_].plan.scene.trajectories;
    while (finished_count_ < workers_) {
      auto [w, bytes] = t_.receive();
      Message m = decode(bytes);
      switch (m.type) {
        case MessageType::Request: {
          if (m.count) {
            red_.add(m.first, m.count, m.out);
            if (o_.progress) o_.progress->update(red_.completed(), n, now_seconds() - t0);
          }
          want_[w] = m.want;
          stop_asked_ |= m.stop || (o_.stop && o_.stop->load());
          stopping_ = stop_asked_ && !red_.complete();
          if (!stopping_ && !snapshot_ && cp_ && cp_->due(k_, parts_)) snapshot_ = true;
          if (snapshot_ && !stopping_) {
            Message s;
            s.type = MessageType::Snapshot;
            t_.send(w, encode(s));
          } else {
            reply_next(w);
          }
          break;
        }
        case MessageType::Histograms:
          snap_[w] = m.histograms;
          parked_.push_back(w);
          break;
        case MessageType::Final:
          final_[w] = m.histograms;
          finished_[w] = true;
          ++finished_count_;
          break;
        case MessageType::Error:
          throw DeviceError("", "", 0, m.text);
        default:
          throw std::runtime_error("unexpected message from worker " + std::to_string(w));
      }
      if (snapshot_ && static_cast<int>(parked_.size()) + finished_count_ == workers_) complete_snapshot(t0);
    }
    std::vector<std::uint64_t> h;
    for (const auto& f : final_) add_into(h, f);
    red_.add_histograms(h);
    if (stopping_ && cp_ && cp_->active()) cp_->save(k_, parts_, {}, true, now_seconds() - t0);
    seconds = before + (now_seconds() - t0);
    red_.seconds = seconds;
    return stopping_;
  }

 private:
  void reply_next(int w) {
    Message r;
    const IndexRange range = stopping_ ? IndexRange{} : take_range(pending_, want_[w], granule_);
    r.type = range.count ? MessageType::Range : MessageType::Done;
    r.first = range.first;
    r.count = range.count;
    t_.send(w, encode(r));
  }

  void complete_snapshot(double t0) {
    std::vector<std::uint64_t> h;
    for (int w : parked_) add_into(h, snap_[w]);
    for (int w = 0; w < workers_; ++w)
      if (finished_[w]) add_into(h, final_[w]);
    cp_->save(k_, parts_, h, false, now_seconds() - t0);
    snapshot_ = false;
    for (int w : parked_) reply_next(w);
    parked_.clear();
  }

  const Job& job_;
  std::size_t k_;
  PartReductions& parts_;
  Reduction& red_;
  Transport& t_;
  const RunOptions& o_;
  JobCheckpoints* cp_;
  std::vector<IndexRange> pending_;
  std::uint64_t granule_;
  int workers_;
  std::vector<std::uint64_t> want_;
  std::vector<std::vector<std::uint64_t>> snap_, final_;
  std::vector<bool> finished_;
  std::vector<int> parked_;
  int finished_count_ = 0;
  bool snapshot_ = false, stop_asked_ = false, stopping_ = false;
};

}  // namespace

JobResult coordinate_job(const Job& job, Transport& transport, const RunOptions& options, JobObserver* observer,
                         const DeviceInfo& device, const std::function<void(Result&)>& describe) {
  for (const JobPart& part : job.parts) {
    require_states(part.plan);
    if (part.plan.slices > 1 && transport.workers() > 1)
      fail_at(part.plan.scene, "run.slice",
              "time slices carry every trajectory's state from one slice to the next in one process: run a "
              "sliced scene on one device (" + std::to_string(transport.workers()) +
                  " were given; run.slice = 0 spreads a run over devices)");
  }
  JobResult jr;
  std::unique_ptr<JobCheckpoints> cp;
  if (options.checkpoint && options.checkpoint->sink) cp = std::make_unique<JobCheckpoints>(job, *options.checkpoint);
  PartReductions parts;
  if (cp) parts = cp->resume();
  for (std::size_t k = 0; k < job.parts.size(); ++k) {
    const Plan& plan = job.parts[k].plan;
    Result r;
    if (k < parts.size() && parts[k]->complete() && k + 1 < parts.size()) {
      r = parts[k]->result();  // done before the checkpoint
      r.kernel = "(from a checkpoint)";
      analyse(plan, r);
    } else {
      if (!cp && options.stop && options.stop->load()) {
        jr.interrupted = true;
        break;
      }
      if (k >= parts.size()) parts.push_back(std::make_unique<Reduction>(plan));
      RunOptions o = options;
      if (observer) o.progress = observer->begin_part(job, k);
      PartCoordinator part(job, k, parts, transport, o, cp.get());
      double seconds = 0;
      const bool stopped = part.run(seconds);
      r = parts[k]->result();
      describe(r);
      r.interrupted = stopped;
      if (!stopped) analyse(plan, r);
      if (o.progress) o.progress->finish(r.completed, plan.scene.trajectories, r.wall_seconds);
    }
    r.device = device;
    r.trajectory_steps = static_cast<double>(r.completed) * static_cast<double>(plan.steps_per_trajectory);
    jr.results.push_back(std::move(r));
    if (jr.results.back().interrupted) {
      jr.interrupted = true;
      break;
    }
  }
  Message end;
  end.type = MessageType::End;
  for (int w = 0; w < transport.workers(); ++w) transport.send(w, encode(end));
  return jr;
}

}  // namespace arnoldweb::detail
