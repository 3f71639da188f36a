// NVRTC is opened at run time (backends/cuda/nvrtc_api.hpp), not linked: the
// library loads where no CUDA toolkit is installed (the wheel), and says where
// it looked when NVRTC is missing (ctest nvrtc, CUDA builds).
// (the loader is part of CUDA builds only: builds with ARNOLDWEB_CUDA=OFF, such as build-asan, skip this file)
#ifdef ARNOLDWEB_HAVE_CUDA
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>

#include "backends/cuda/nvrtc_loader.hpp"
#include "support.hpp"

using namespace arnoldweb;

TEST_SUITE("nvrtc") {
  TEST_CASE("NVRTC is found at run time, and ARNOLDWEB_NVRTC alone is tried when set") {
    std::string problem;
    const std::string path = detail::nvrtc_library(&problem);
    CHECK_MESSAGE(path.find("libnvrtc.so") != std::string::npos, problem);
    setenv("ARNOLDWEB_NVRTC", "/nonexistent/libnvrtc.so.13", 1);
    const auto only = detail::nvrtc_candidates();
    unsetenv("ARNOLDWEB_NVRTC");
    REQUIRE(only.size() == 1);
    CHECK(only[0] == "/nonexistent/libnvrtc.so.13");
    const auto all = detail::nvrtc_candidates();
    CHECK(all.front() == "libnvrtc.so.13");
    CHECK(all.size() > 4);
  }

  TEST_CASE("a missing or wrong library is a message naming what was tried") {
    const std::string missing = detail::nvrtc_check_candidates({"/nonexistent/libnvrtc.so.13"});
    CHECK(missing.find("NVRTC") != std::string::npos);
    CHECK(missing.find("/nonexistent/libnvrtc.so.13") != std::string::npos);
    CHECK(missing.find("ARNOLDWEB_NVRTC") != std::string::npos);
    const std::string wrong = detail::nvrtc_check_candidates({"libm.so.6"});
    CHECK(wrong.find("libm.so.6 (lacks a function the CUDA backend calls)") != std::string::npos);
    CHECK(detail::nvrtc_check_candidates({detail::nvrtc_library()}).empty());
  }
}

#endif  // ARNOLDWEB_HAVE_CUDA
