#include "stop_signals.hpp"

#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <string>

namespace arnoldweb::cli {
namespace {

std::atomic<bool> g_stop{false};
volatile sig_atomic_t g_signal = 0;
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
struct sigaction g_previous[3];
char g_first[256], g_again[256];

extern "C" void on_stop_signal(int sig) {
  static_assert(std::atomic<bool>::is_always_lock_free, "the flag is set from a signal handler");
  const bool first = g_signal == 0;
  if (first) g_signal = sig;
  g_stop.store(true);
  // write(2) is async-signal-safe; the texts are made before the run
  const ssize_t rc = first ? ::write(STDERR_FILENO, g_first, std::strlen(g_first))
                           : ::write(STDERR_FILENO, g_again, std::strlen(g_again));
  (void)rc;
}

std::string bytes_text(std::uint64_t bytes) {
  char b[32];
  const double v = static_cast<double>(bytes);
  if (v >= 1e9) std::snprintf(b, sizeof b, "%.1f GB", v / 1e9);
  else if (v >= 1e6) std::snprintf(b, sizeof b, "%.0f MB", v / 1e6);
  else std::snprintf(b, sizeof b, "%.0f kB", v / 1e3);
  return b;
}

}  // namespace

StopSignals::StopSignals(std::uint64_t bytes_to_write) {
  g_stop.store(false);
  g_signal = 0;
  // what a stop still does, so that the wait is expected: one chunk, then the writing
  const std::string size = bytes_to_write ? " (up to about " + bytes_text(bytes_to_write) + ")" : "";
  std::snprintf(g_first, sizeof g_first,
                "\narnoldweb: stopping after the current chunk; what was computed will be written%s "
                "(Ctrl-\\ quits at once and loses it)\n",
                size.c_str());
  std::snprintf(g_again, sizeof g_again,
                "\narnoldweb: still finishing; the results are being written%s (Ctrl-\\ quits at once)\n",
                size.c_str());
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
