// arnoldweb: Ctrl-\ (SIGQUIT) quits at once, as documented, whatever runtime
// is loaded. PoCL's LLVM installs its own SIGQUIT handler when PoCL starts
// (and may again when it compiles a kernel); that handler removes itself and
// returns, so the first Ctrl-\ was swallowed and the run went on. A
// KeepQuitSignal around loading or using a runtime puts back the disposition
// that SIGQUIT had before.
#pragma once

#include <signal.h>

namespace arnoldweb::detail {

class KeepQuitSignal {
 public:
  KeepQuitSignal();
  ~KeepQuitSignal();  // puts the disposition found at construction back, if it changed
  KeepQuitSignal(const KeepQuitSignal&) = delete;
  KeepQuitSignal& operator=(const KeepQuitSignal&) = delete;

 private:
  struct sigaction before_ {};
  bool known_ = false;
};

}  // namespace arnoldweb::detail
