// arnoldweb: work on untrusted bytes tried first in a child process (isolated.hpp).
#include "os/isolated.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace arnoldweb::detail {
namespace {

bool in_process() {
  const char* v = std::getenv("ARNOLDWEB_HDF5_IN_PROCESS");
  return v && std::string(v) == "1";
}

std::string why_ended(int status) {
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    const char* name = ::strsignal(sig);
    return "killed by signal " + std::to_string(sig) + (name ? std::string(" (") + name + ")" : std::string());
  }
  return "ended with exit status " + std::to_string(WEXITSTATUS(status));
}

}  // namespace

int seconds_for(std::uint64_t bytes) {
  return static_cast<int>(std::min<std::uint64_t>(120 + bytes / 50'000'000, 86400));
}

void try_in_child(const std::function<void()>& work, const std::function<void(const std::string&)>& died,
                  int seconds) {
  if (in_process()) return;
  int fds[2] = {-1, -1};  // the child's end closes when it ends: the parent waits on the pipe
  if (::pipe2(fds, O_CLOEXEC) != 0) return;
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return;
  }
  if (pid == 0) {
    ::close(fds[0]);
    const rlimit no_core{0, 0};  // a crash of the child leaves no core file behind
    ::setrlimit(RLIMIT_CORE, &no_core);
    try {
      work();
    } catch (...) {  // the parent's own try will throw it
    }
    ::_exit(0);  // _exit: nothing of the parent's is flushed or destroyed twice
  }
  ::close(fds[1]);
  bool timed_out = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno != EINTR) break;
    if (ready <= 0) continue;
    char c;
    const ssize_t n = ::read(fds[0], &c, 1);
    if (n < 0 && errno == EINTR) continue;
    break;  // 0: the child has ended (it writes nothing)
  }
  ::close(fds[0]);
  if (timed_out) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return;  // not ours to wait for (SIGCHLD ignored): nothing known against it
  }
  if (!timed_out && WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
  died(timed_out ? "did not finish within " + std::to_string(seconds) + " s (stopped)" : why_ended(status));
  throw std::logic_error("try_in_child: `died` returned");
}

}  // namespace arnoldweb::detail
