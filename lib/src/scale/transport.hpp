// arnoldweb: how the coordinator and the workers of a job exchange messages
// (messages.hpp). The coordinator sees workers 0..workers()-1; a worker sees
// one channel to the coordinator. LocalLinks connects threads of this process
// (rank 0's own device, tests); scale/mpi/ connects MPI ranks.
#pragma once

#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace arnoldweb::detail {

class Transport {  // the coordinator's side
 public:
  virtual ~Transport() = default;
  virtual int workers() const = 0;
  virtual std::pair<int, std::string> receive() = 0;  // blocks; (worker, message)
  virtual void send(int worker, const std::string& message) = 0;
};

class Channel {  // a worker's side
 public:
  virtual ~Channel() = default;
  virtual void send(const std::string& message) = 0;
  virtual std::string receive() = 0;  // blocks
};

// Links between the coordinator and workers that are threads of this process.
class LocalLinks {
 public:
  explicit LocalLinks(int workers);
  ~LocalLinks();
  Channel& channel(int worker);
  int workers() const { return static_cast<int>(channels_.size()); }
  // The coordinator's side: a message from a worker, if one waits (waiting at most `seconds`).
  bool try_receive(std::pair<int, std::string>& m, double seconds);
  void send(int worker, const std::string& message);

 private:
  class LocalChannel;
  std::mutex mutex_;
  std::condition_variable to_coordinator_cv_;
  std::deque<std::pair<int, std::string>> to_coordinator_;
  std::vector<std::unique_ptr<LocalChannel>> channels_;
};

// A Transport of local links only.
class LocalTransport final : public Transport {
 public:
  explicit LocalTransport(LocalLinks& links) : links_(links) {}
  int workers() const override { return links_.workers(); }
  std::pair<int, std::string> receive() override;
  void send(int worker, const std::string& message) override { links_.send(worker, message); }

 private:
  LocalLinks& links_;
};

}  // namespace arnoldweb::detail
