// arnoldweb: work on untrusted bytes tried first in a child process (isolated.hpp).
#include "os/isolated.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
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

// Whether this process's children are reaped as they end (SIGCHLD ignored, or SA_NOCLDWAIT, as
// some embedding programs set): then waitpid finds no status, and the child must report it.
bool children_reaped() {
  struct sigaction now {};
  if (::sigaction(SIGCHLD, nullptr, &now) != 0) return false;
  return now.sa_handler == SIG_IGN || (now.sa_flags & SA_NOCLDWAIT) != 0;
}

// In the child, where this process's children are reaped: the work in a grandchild, whose
// status the child (SIGCHLD back at its default, in the child only) waits for and writes into
// the pipe. The grandchild dies with the child (PR_SET_PDEATHSIG), so that killing the child
// at the time limit stops the work. Only async-signal-safe calls after the fork.
[[noreturn]] void report_from_grandchild(const std::function<void()>& work, int out) {
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  ::sigaction(SIGCHLD, &dfl, nullptr);
  const pid_t child = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) ::_exit(0);  // nothing tried: nothing known against the file
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != child) ::_exit(0);  // the child was already stopped
    try {
      work();
    } catch (...) {
    }
    ::_exit(0);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) ::_exit(0);
  if (::write(out, &status, sizeof status) != static_cast<ssize_t>(sizeof status)) ::_exit(0);
  ::_exit(0);
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
  const bool reported = children_reaped();  // the status comes through the pipe, not waitpid
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
    if (reported) report_from_grandchild(work, fds[1]);
    try {
      work();
    } catch (...) {  // the parent's own try will throw it
    }
    ::_exit(0);  // _exit: nothing of the parent's is flushed or destroyed twice
  }
  ::close(fds[1]);
  bool timed_out = false;
  int status = 0;
  std::size_t got = 0;  // bytes of a reported status
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
    const ssize_t n = ::read(fds[0], reinterpret_cast<char*>(&status) + got, sizeof status - got);
    if (n < 0 && errno == EINTR) continue;
    if (n > 0 && (got += static_cast<std::size_t>(n)) < sizeof status) continue;
    break;  // 0: the child has ended (it writes nothing unless `reported`)
  }
  ::close(fds[0]);
  if (timed_out) ::kill(pid, SIGKILL);
  if (reported) {  // the child is reaped by the system; its report is the grandchild's status
    if (!timed_out && got != sizeof status) return;  // no report: nothing known against the file
  } else {
    while (::waitpid(pid, &status, 0) < 0)
      if (errno != EINTR) return;  // not ours to wait for: nothing known against it
  }
  if (!timed_out && WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
  died(timed_out ? "did not finish within " + std::to_string(seconds) + " s (stopped)" : why_ended(status));
  throw std::logic_error("try_in_child: `died` returned");
}

}  // namespace arnoldweb::detail
