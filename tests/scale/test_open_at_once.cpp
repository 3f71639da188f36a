// The devices of a list open at once (issue 42, item 4): a thread each, the
// backends in the list's order whatever order they opened in, and when some
// fail, the error of the first failing device of the list (not of the first
// to fail in time), thrown as it was, once every thread has ended and every
// device opened has been closed. Suite "scale": no device needed.
#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "arnoldweb/errors.hpp"
#include "backends/open_at_once.hpp"

namespace {

std::atomic<int> live{0};  // fake devices open now

class FakeDevice final : public arnoldweb::Backend {
 public:
  explicit FakeDevice(const std::string& id) {
    info_.id = id;
    ++live;
  }
  ~FakeDevice() override { --live; }
  const arnoldweb::DeviceInfo& info() const override { return info_; }
  void prepare(const arnoldweb::Plan&, std::uint64_t) override {}
  void run_chunk(const arnoldweb::ChunkWork&, arnoldweb::ChunkOutput&) override {}
  std::vector<std::uint64_t> read_histograms() override { return {}; }
  std::uint64_t preferred_chunk() const override { return 1; }
  std::string kernel_description() const override { return ""; }

 private:
  arnoldweb::DeviceInfo info_;
};

// Lets each opener wait until `n` of them have started: they finish only if
// they run at the same time (a serial open would wait for ever, so it gives up
// after 20 s and says so).
class Gate {
 public:
  explicit Gate(int n) : left_(n) {}
  bool arrive_and_wait() {
    std::unique_lock<std::mutex> lock(m_);
    if (--left_ == 0) cv_.notify_all();
    return cv_.wait_for(lock, std::chrono::seconds(20), [&] { return left_ <= 0; });
  }

 private:
  std::mutex m_;
  std::condition_variable cv_;
  int left_;
};

}  // namespace

TEST_SUITE("scale") {
  TEST_CASE("open_at_once opens every device of a list at the same time and keeps the list's order") {
    const std::vector<std::string> ids = {"cuda:0", "cuda:1", "opencl:0", "cpu"};
    Gate gate(static_cast<int>(ids.size()));
    std::atomic<int> together{0};
    const auto backends = arnoldweb::detail::open_at_once(ids, [&](const std::string& id) {
      if (gate.arrive_and_wait()) ++together;
      // the last of the list is ready first, the first last
      if (id == "cuda:0") std::this_thread::sleep_for(std::chrono::milliseconds(50));
      return std::make_unique<FakeDevice>(id);
    });
    CHECK(together == 4);
    REQUIRE(backends.size() == ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i) CHECK(backends[i]->info().id == ids[i]);
  }

  TEST_CASE("open_at_once: the first failing device of the list is reported, as thrown, and nothing stays open") {
    const int before = live;
    const std::vector<std::string> ids = {"cpu", "cuda:1", "cuda:2", "opencl:0"};
    auto open = [&](const std::string& id) -> std::unique_ptr<arnoldweb::Backend> {
      // cuda:2 fails at once, cuda:1 (earlier in the list) later: cuda:1 is the one reported
      if (id == "cuda:1") {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        throw arnoldweb::DeviceError(id, "cudaSetDevice", 2, "out of memory");
      }
      if (id == "cuda:2") throw std::runtime_error("cuda:2 broke");
      auto d = std::make_unique<FakeDevice>(id);
      std::this_thread::sleep_for(std::chrono::milliseconds(150));  // still opening when the others fail
      return d;
    };
    CHECK_THROWS_WITH_AS(arnoldweb::detail::open_at_once(ids, open), doctest::Contains("cuda:1"),
                         arnoldweb::DeviceError);
    CHECK(live == before);  // cpu and opencl:0 were opened, then closed
    // a failure of a later device alone is reported as it was thrown
    CHECK_THROWS_WITH_AS(arnoldweb::detail::open_at_once({"cpu", "cuda:2"}, open), "cuda:2 broke", std::runtime_error);
    CHECK(live == before);
    CHECK(arnoldweb::detail::open_at_once({}, open).empty());
  }
}
