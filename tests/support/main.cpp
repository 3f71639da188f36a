// arnoldweb tests: doctest main. Extra option --backend=cpu|opencl|cuda limits
// the device-bound suites to one backend and exits 77 (skipped) if it has no
// device here.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>

#include "support.hpp"

namespace awtest {
extern std::string g_backend;
}

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], "--backend=", 10) == 0) awtest::g_backend = argv[i] + 10;
  if (!awtest::g_backend.empty() && awtest::devices_under_test().empty()) {
    std::cout << "SKIPPED: no " << awtest::g_backend << " device on this machine";
    for (const auto& p : arnoldweb::backend_problems())
      if (p.rfind(awtest::g_backend, 0) == 0) std::cout << "\n  " << p;
    std::cout << std::endl;
    return 77;
  }
  doctest::Context context(argc, argv);
  const int status = context.run();
  // ARNOLDWEB_TEST_QUICK_EXIT=1 (set by tests/oclgrind/run.sh): end without
  // running static destructors. Oclgrind 21.10 frees its per-thread record of
  // API calls before the exit handlers run, so the programs that
  // Boost.Compute's global program cache releases at exit corrupt the heap
  // ("corrupted double-linked list") once a process has built two programs.
  if (const char* q = std::getenv("ARNOLDWEB_TEST_QUICK_EXIT"); q && std::string(q) == "1") {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    std::quick_exit(status);
  }
  return status;
}
