#include "stop_signals.hpp"

#include <signal.h>
#include <unistd.h>

namespace arnoldweb::cli {
namespace {

std::atomic<bool> g_stop{false};
volatile sig_atomic_t g_signal = 0;
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
struct sigaction g_previous[3];

extern "C" void on_stop_signal(int sig) {
  static_assert(std::atomic<bool>::is_always_lock_free, "the flag is set from a signal handler");
  const bool first = g_signal == 0;
  if (first) g_signal = sig;
  g_stop.store(true);
  // write(2) is async-signal-safe
  static const char kFirst[] =
      "\narnoldweb: stopping after the current chunk; what was computed will be written "
      "(Ctrl-\\ quits at once and loses it)\n";
  static const char kAgain[] = "\narnoldweb: still finishing; the results are being kept\n";
  const ssize_t rc = first ? ::write(STDERR_FILENO, kFirst, sizeof kFirst - 1)
                           : ::write(STDERR_FILENO, kAgain, sizeof kAgain - 1);
  (void)rc;
}

}  // namespace

StopSignals::StopSignals() {
  g_stop.store(false);
  g_signal = 0;
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &sa, &g_previous[i]);
  // a closed pipe on stdout makes writes fail (EPIPE) instead of killing us
  // before the results are written
  ::signal(SIGPIPE, SIG_IGN);
}

StopSignals::~StopSignals() {
  for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &g_previous[i], nullptr);
}

const std::atomic<bool>& StopSignals::flag() const { return g_stop; }
int StopSignals::signal() const { return g_signal; }
int StopSignals::exit_code() const { return 128 + g_signal; }

const char* StopSignals::name() const {
  switch (g_signal) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "a signal";
  }
}

}  // namespace arnoldweb::cli
