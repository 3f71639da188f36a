// arnoldweb: the ranks of an MPI job (cluster.hpp). Rank 0 coordinates
// (scale/coordinator.hpp) in its main thread, which makes every MPI call
// (MPI_THREAD_FUNNELED), and drives its own device in a worker thread linked
// in-process (scale/transport.hpp); the other ranks are workers
// (scale/worker.hpp) whose channel is point-to-point messages to rank 0.
// A message is its length, then pieces of at most 1 GiB (MPI counts are int).
#include <mpi.h>

#include <cstdint>
#include <thread>

#include "arnoldweb/cluster.hpp"
#include "arnoldweb/errors.hpp"
#include "scale/coordinator.hpp"
#include "scale/local_devices.hpp"
#include "scale/messages.hpp"
#include "scale/worker.hpp"

namespace arnoldweb {
namespace {

constexpr int kTag = 15;
constexpr std::uint64_t kPiece = 1u << 30;

void send_bytes(int to, const std::string& m) {
  std::uint64_t n = m.size();
  MPI_Send(&n, 1, MPI_UINT64_T, to, kTag, MPI_COMM_WORLD);
  for (std::uint64_t at = 0; at < n; at += kPiece)
    MPI_Send(m.data() + at, static_cast<int>(std::min(kPiece, n - at)), MPI_BYTE, to, kTag, MPI_COMM_WORLD);
}

std::string receive_bytes(int from) {
  std::uint64_t n = 0;
  MPI_Recv(&n, 1, MPI_UINT64_T, from, kTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  std::string m(n, '\0');
  for (std::uint64_t at = 0; at < n; at += kPiece)
    MPI_Recv(m.data() + at, static_cast<int>(std::min(kPiece, n - at)), MPI_BYTE, from, kTag, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
  return m;
}

// Rank 0's view: worker 0 is its own device (a thread), worker r is rank r.
class RankTransport final : public detail::Transport {
 public:
  RankTransport(int size, detail::LocalLinks& local) : size_(size), local_(local) {}
  int workers() const override { return size_; }
  std::pair<int, std::string> receive() override {
    std::pair<int, std::string> m;
    for (;;) {
      if (local_.try_receive(m, 0)) return m;
      int flag = 0;
      MPI_Status st;
      MPI_Iprobe(MPI_ANY_SOURCE, kTag, MPI_COMM_WORLD, &flag, &st);
      if (flag) return {st.MPI_SOURCE, receive_bytes(st.MPI_SOURCE)};
      if (local_.try_receive(m, 0.0002)) return m;
    }
  }
  void send(int worker, const std::string& message) override {
    if (worker == 0) local_.send(0, message);
    else send_bytes(worker, message);
  }

 private:
  int size_;
  detail::LocalLinks& local_;
};

class RankChannel final : public detail::Channel {
 public:
  void send(const std::string& message) override { send_bytes(0, message); }
  std::string receive() override { return receive_bytes(0); }
};

class MpiCluster final : public Cluster {
 public:
  MpiCluster() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    MPI_Comm node;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
    MPI_Comm_rank(node, &local_rank_);
    MPI_Comm_free(&node);
  }
  ~MpiCluster() override { MPI_Finalize(); }
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  int local_rank() const override { return local_rank_; }

  std::string broadcast(const std::string& bytes) override {
    std::uint64_t n = bytes.size();
    MPI_Bcast(&n, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    std::string b = rank_ == 0 ? bytes : std::string(n, '\0');
    for (std::uint64_t at = 0; at < n; at += kPiece)
      MPI_Bcast(b.data() + at, static_cast<int>(std::min(kPiece, n - at)), MPI_BYTE, 0, MPI_COMM_WORLD);
    return b;
  }

  JobResult run_job(const Job& job, Backend& backend, const RunOptions& options, JobObserver* observer) override {
    detail::LocalLinks local(1);
    RankTransport transport(size_, local);
    std::thread own(detail::local_worker, std::cref(job), std::ref(backend), std::ref(local.channel(0)),
                    std::cref(options), "rank 0");
    JobResult r;
    try {
      r = detail::coordinate_job(job, transport, options, observer, backend.info(), [&](Result& part) {
        part.kernel = backend.kernel_description() + "; " + std::to_string(size_) + " devices (MPI ranks)";
        part.startup = {inventory_seconds(), {backend.startup}};  // rank 0's own device
      });
    } catch (...) {
      // the other ranks end with MPI_Abort (the caller's); rank 0's own thread ends here
      detail::Message end;
      end.type = detail::MessageType::End;
      local.send(0, detail::encode(end));
      own.join();
      throw;
    }
    own.join();
    return r;
  }

  void serve(const Job& job, Backend& backend, const RunOptions& options) override {
    RankChannel channel;
    detail::work_job(job, backend, channel, options);
  }

  [[noreturn]] void abort(int code) override {
    MPI_Abort(MPI_COMM_WORLD, code);
    std::_Exit(code);
  }

 private:
  int rank_ = 0, size_ = 1, local_rank_ = 0;
};

}  // namespace

bool cluster_built() { return true; }

std::unique_ptr<Cluster> start_cluster(int* argc, char*** argv) {
  if (launcher_size() <= 1) return nullptr;
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  if (provided < MPI_THREAD_FUNNELED) {
    MPI_Finalize();
    throw DeviceError("", "MPI_Init_thread", provided, "this MPI library cannot be used with threads");
  }
  auto c = std::make_unique<MpiCluster>();
  if (c->size() <= 1) return nullptr;  // MPI_Finalize in the destructor
  return c;
}

}  // namespace arnoldweb
