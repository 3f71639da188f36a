// arnoldweb: local links between the coordinator and worker threads (transport.hpp).
#include "scale/transport.hpp"

#include <chrono>

namespace arnoldweb::detail {

class LocalLinks::LocalChannel final : public Channel {
 public:
  LocalChannel(LocalLinks& links, int index) : links_(links), index_(index) {}
  void send(const std::string& message) override {
    {
      std::lock_guard<std::mutex> lock(links_.mutex_);
      links_.to_coordinator_.emplace_back(index_, message);
    }
    links_.to_coordinator_cv_.notify_all();
  }
  std::string receive() override {
    std::unique_lock<std::mutex> lock(links_.mutex_);
    cv_.wait(lock, [&] { return !inbox_.empty(); });
    std::string m = std::move(inbox_.front());
    inbox_.pop_front();
    return m;
  }
  void deliver(const std::string& message) {  // under links_.mutex_
    inbox_.push_back(message);
    cv_.notify_all();
  }

 private:
  LocalLinks& links_;
  int index_;
  std::condition_variable cv_;
  std::deque<std::string> inbox_;
};

LocalLinks::LocalLinks(int workers) {
  for (int w = 0; w < workers; ++w) channels_.push_back(std::make_unique<LocalChannel>(*this, w));
}

LocalLinks::~LocalLinks() = default;

Channel& LocalLinks::channel(int worker) { return *channels_[static_cast<std::size_t>(worker)]; }

bool LocalLinks::try_receive(std::pair<int, std::string>& m, double seconds) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (to_coordinator_.empty() && seconds > 0)
    to_coordinator_cv_.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return !to_coordinator_.empty(); });
  if (to_coordinator_.empty()) return false;
  m = std::move(to_coordinator_.front());
  to_coordinator_.pop_front();
  return true;
}

void LocalLinks::send(int worker, const std::string& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  channels_[static_cast<std::size_t>(worker)]->deliver(message);
}

std::pair<int, std::string> LocalTransport::receive() {
  std::pair<int, std::string> m;
  while (!links_.try_receive(m, 1.0)) {
  }
  return m;
}

}  // namespace arnoldweb::detail
