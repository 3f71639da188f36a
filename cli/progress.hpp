// arnoldweb CLI: progress of a run on stderr: a bar with rate and ETA on a
// terminal, plain lines otherwise (logs, CI).
#pragma once

#include <cstdint>

#include "arnoldweb/run.hpp"

namespace arnoldweb::cli {

class ConsoleProgress final : public Progress {
 public:
  ConsoleProgress(double steps_per_trajectory, bool quiet);
  void update(std::uint64_t done, std::uint64_t total, double seconds) override;
  void finish(std::uint64_t done, std::uint64_t total, double seconds) override;

 private:
  double steps_per_trajectory_;
  bool quiet_, tty_;
  double last_print_ = -1e9;
  int last_percent_ = -1;
};

}  // namespace arnoldweb::cli
