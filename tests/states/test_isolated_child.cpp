// The child process that HDF5 reads untrusted files in first (lib/src/os/isolated.hpp,
// try_in_child): a normal end lets the caller go on; a crash, another exit status or a child
// past its time is reported through `died`; and the same where this process ignores SIGCHLD
// (its children reaped at once, as some embedding programs set it), where waitpid finds no
// status: the child then reports its grandchild's. Before, with SIGCHLD ignored, a crash was
// not seen and the caller went on to read the file in its own process.
#include <doctest/doctest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "os/isolated.hpp"
#include "support.hpp"

using arnoldweb::detail::try_in_child;

namespace {

// try_in_child's answer: "" when the work ended well, else why the child died.
std::string outcome(const std::function<void()>& work, int seconds = 30) {
  try {
    try_in_child(work, [](const std::string& why) { throw std::runtime_error(why); }, seconds);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// SIGCHLD's disposition set for one scope, restored after.
struct ChildSignal {
  struct sigaction before {};
  explicit ChildSignal(void (*handler)(int), int flags = 0) {
    struct sigaction now {};
    now.sa_handler = handler;
    now.sa_flags = flags;
    sigemptyset(&now.sa_mask);
    ::sigaction(SIGCHLD, &now, &before);
  }
  ~ChildSignal() { ::sigaction(SIGCHLD, &before, nullptr); }
};

void ignore_signal(int) {}

void every_ending() {
  CHECK(outcome([] {}) == "");
  CHECK(outcome([] { throw std::runtime_error("the work's own error"); }) == "");  // the caller's try throws it
  CHECK(outcome([] {
          ::signal(SIGSEGV, SIG_DFL);  // (not doctest's handler, which would report a crash from the child)
          ::raise(SIGSEGV);
        }) == "killed by signal 11 (Segmentation fault)");
  CHECK(outcome([] { ::_exit(3); }) == "ended with exit status 3");
  CHECK(outcome([] { std::this_thread::sleep_for(std::chrono::seconds(30)); }, 1) ==
        "did not finish within 1 s (stopped)");
}

}  // namespace

// Under a sanitizer the child's deliberate crash is a report, which check-sanitizers.sh counts.
TEST_SUITE("states") {
  TEST_CASE("try_in_child: every way the child ends, SIGCHLD at its default" * doctest::skip(awtest::kSanitized)) {
    every_ending();
  }

  TEST_CASE("try_in_child: every way the child ends, SIGCHLD ignored or SA_NOCLDWAIT (the child reports)" *
            doctest::skip(awtest::kSanitized)) {
    {
      const ChildSignal ignored(SIG_IGN);
      every_ending();
    }
    {
      const ChildSignal no_wait(ignore_signal, SA_NOCLDWAIT);
      every_ending();
    }
  }

  TEST_CASE("try_in_child: the work stopped at its time limit does not go on (SIGCHLD ignored)" *
            doctest::skip(awtest::kSanitized)) {
    const ChildSignal ignored(SIG_IGN);
    const std::string mark = awtest::temp_dir("isolated-limit") + "/pid";
    CHECK(outcome(
              [&] {
                std::ofstream(mark) << ::getpid();
                std::this_thread::sleep_for(std::chrono::seconds(30));
              },
              1) == "did not finish within 1 s (stopped)");
    pid_t worker = 0;
    std::ifstream(mark) >> worker;
    REQUIRE(worker > 0);
    // the work's process is killed with its parent: gone, or a zombie waiting for init
    bool running = true;
    for (int i = 0; i < 50 && running; ++i) {
      std::ifstream stat("/proc/" + std::to_string(worker) + "/stat");
      std::string pid, name, state;
      running = static_cast<bool>(stat >> pid >> name >> state) && state != "Z";
      if (running) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    CHECK_FALSE(running);
  }
}
