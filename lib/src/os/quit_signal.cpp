// arnoldweb: keeping Ctrl-\ quitting at once (quit_signal.hpp).
#include "os/quit_signal.hpp"

namespace arnoldweb::detail {

KeepQuitSignal::KeepQuitSignal() { known_ = ::sigaction(SIGQUIT, nullptr, &before_) == 0; }

KeepQuitSignal::~KeepQuitSignal() {
  struct sigaction now {};
  if (!known_ || ::sigaction(SIGQUIT, nullptr, &now) != 0) return;
  const bool same = now.sa_handler == before_.sa_handler && now.sa_flags == before_.sa_flags;
  if (!same) ::sigaction(SIGQUIT, &before_, nullptr);
}

}  // namespace arnoldweb::detail
