// arnoldweb CLI: SIGINT (Ctrl-C), SIGTERM (a batch scheduler, kill) and
// SIGHUP (a closed terminal) all mean "stop after the current chunk and keep
// what was computed". The first one asks the run to stop; later ones are held
// (they change nothing) so that the outputs are written completely. The exit
// code is then 128 + the first signal's number (130, 143, 129).
#pragma once

#include <atomic>
#include <cstdint>

namespace arnoldweb::cli {

class StopSignals {
 public:
  // Installs the handlers; the first signal's message says how much is still
  // to be written (0: not said).
  explicit StopSignals(std::uint64_t bytes_to_write = 0);
  ~StopSignals();  // puts the previous ones back
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  const std::atomic<bool>& flag() const;
  int signal() const;     // the first signal received, 0 if none
  int exit_code() const;  // 128 + signal()
  const char* name() const;  // "SIGINT", ...
};

}  // namespace arnoldweb::cli
