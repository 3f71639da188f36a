// arnoldweb: a worker of a job over several devices (worker.hpp).
#include "scale/worker.hpp"

#include <stdexcept>
#include <utility>

#include "run/chunk_loop.hpp"
#include "scale/messages.hpp"

namespace arnoldweb::detail {
namespace {

class ChannelQueue final : public WorkQueue {
 public:
  ChannelQueue(Channel& channel, const Plan& plan, std::uint64_t part, const RunOptions& options)
      : channel_(channel), plan_(plan), part_(part), options_(options) {}

  ChunkWork next(const ChunkWork& finished, ChunkOutput& out, std::uint64_t want, Backend& backend) override {
    Message request;
    request.type = MessageType::Request;
    request.part = part_;
    request.first = finished.first;
    request.count = finished.count;
    request.want = want;
    request.stop = options_.stop && options_.stop->load();
    if (finished.count) request.out = std::move(out);
    channel_.send(encode(request));
    for (;;) {
      const Message reply = decode(channel_.receive());
      if (reply.type == MessageType::Range) return whole_work(plan_, {reply.first, reply.count}, rec_r_, rec_i_);
      if (reply.type == MessageType::Done) return {};
      if (reply.type != MessageType::Snapshot) throw std::runtime_error("unexpected message from the coordinator");
      Message h;
      h.type = MessageType::Histograms;
      h.part = part_;
      h.histograms = backend.read_histograms();
      channel_.send(encode(h));
    }
  }

 private:
  Channel& channel_;
  const Plan& plan_;
  std::uint64_t part_;
  const RunOptions& options_;
  std::vector<double> rec_r_;  // the records a range starts from (states given by the plan)
  std::vector<std::int64_t> rec_i_;
};

}  // namespace

void work_job(const Job& job, Backend& backend, Channel& channel, const RunOptions& options) {
  for (;;) {
    const Message m = decode(channel.receive());
    if (m.type == MessageType::End) return;
    if (m.type != MessageType::Begin || m.part >= job.parts.size())
      throw std::runtime_error("unexpected message from the coordinator");
    const Plan& plan = job.parts[m.part].plan;
    ChannelQueue queue(channel, plan, m.part, options);
    drive_device(plan, backend, queue, options);
    Message final_hist;
    final_hist.type = MessageType::Final;
    final_hist.part = m.part;
    final_hist.histograms = backend.read_histograms();
    channel.send(encode(final_hist));
  }
}

}  // namespace arnoldweb::detail
