// arnoldweb: work on untrusted bytes in a child process (isolated.hpp).
#include "os/isolated.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <exception>
#include <stdexcept>

namespace arnoldweb::detail {
namespace {

bool write_all(int fd, const std::string& s) {
  for (std::size_t done = 0; done < s.size();) {
    const ssize_t n = ::write(fd, s.data() + done, s.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// The child's answer: 'O' and what work returned, or 'X' and an exception's what().
[[noreturn]] void child(int fd, const std::function<std::string()>& work) {
  std::string answer;
  try {
    answer = "O" + work();
  } catch (const std::exception& e) {
    answer = std::string("X") + e.what();
  } catch (...) {
    answer = "Xan exception of a type not derived from std::exception";
  }
  ::_exit(write_all(fd, answer) ? 0 : 1);  // _exit: nothing of the parent's is flushed or destroyed twice
}

std::string why_ended(int status) {
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    const char* name = ::strsignal(sig);
    return "killed by signal " + std::to_string(sig) + (name ? std::string(" (") + name + ")" : std::string());
  }
  return "ended with exit status " + std::to_string(WEXITSTATUS(status)) + " before it answered";
}

}  // namespace

bool isolating() {
  const char* v = std::getenv("ARNOLDWEB_HDF5_IN_PROCESS");
  return !(v && std::string(v) == "1");
}

std::string run_isolated(const std::function<std::string()>& work, const std::function<void(const std::string&)>& died,
                         int seconds) {
  int fds[2] = {-1, -1};
  if (!isolating() || ::pipe2(fds, O_CLOEXEC) != 0) return work();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return work();
  }
  if (pid == 0) {
    ::close(fds[0]);
    child(fds[1], work);
  }
  ::close(fds[1]);
  std::string answer;
  bool timed_out = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  char buf[1 << 16];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // the child closed its end: it has answered, or ended
    answer.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  if (timed_out) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (timed_out) died("did not answer within " + std::to_string(seconds) + " s (stopped)");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || answer.empty()) died(why_ended(status));
  if (timed_out || answer.empty()) throw std::logic_error("run_isolated: `died` returned");
  if (answer[0] == 'X') throw std::runtime_error(answer.substr(1));
  return answer.substr(1);
}

}  // namespace arnoldweb::detail
