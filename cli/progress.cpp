#include "progress.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace arnoldweb::cli {
namespace {

std::string clock_time(double s) {
  if (!std::isfinite(s) || s < 0) return "--:--";
  long t = std::lround(s);
  char buf[32];
  if (t >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", t / 60, t % 60);
  return buf;
}

}  // namespace

ConsoleProgress::ConsoleProgress(double steps_per_trajectory, bool quiet)
    : steps_per_trajectory_(steps_per_trajectory), quiet_(quiet), tty_(isatty(STDERR_FILENO) != 0) {}

void ConsoleProgress::update(std::uint64_t done, std::uint64_t total, double seconds) {
  if (quiet_) return;
  const double frac = total ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
  const double rate = seconds > 0 ? static_cast<double>(done) * steps_per_trajectory_ / seconds : 0;
  const double eta = frac > 0 ? seconds * (1 - frac) / frac : NAN;
  const int percent = static_cast<int>(100 * frac);
  if (tty_) {
    if (seconds - last_print_ < 0.1 && done < total) return;
    last_print_ = seconds;
    const int width = 30;
    const int fill = static_cast<int>(width * frac);
    std::string bar(static_cast<std::size_t>(fill), '#');
    bar.resize(width, '.');
    std::fprintf(stderr, "\r[%s] %3d%%  %llu/%llu trajectories  %.3g steps/s  ETA %s  ", bar.c_str(),
                 percent, static_cast<unsigned long long>(done), static_cast<unsigned long long>(total),
                 rate, clock_time(eta).c_str());
    std::fflush(stderr);
  } else {
    // a line every 10% or every 10 s
    if (percent / 10 == last_percent_ / 10 && seconds - last_print_ < 10 && done < total) return;
    last_percent_ = percent;
    last_print_ = seconds;
    std::fprintf(stderr, "progress: %3d%%  %llu/%llu trajectories  %.3g steps/s  elapsed %s  ETA %s\n",
                 percent, static_cast<unsigned long long>(done), static_cast<unsigned long long>(total),
                 rate, clock_time(seconds).c_str(), clock_time(eta).c_str());
  }
}

void ConsoleProgress::finish(std::uint64_t, std::uint64_t, double) {
  if (quiet_) return;
  if (tty_) std::fprintf(stderr, "\n");
}

}  // namespace arnoldweb::cli
