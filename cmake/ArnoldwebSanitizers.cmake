# Checked builds (docs/reliability.md, "Continuous checks"):
#
#   ARNOLDWEB_SANITIZE=address,undefined   every target of the build compiled and
#       linked with these sanitizers; UBSan does not recover (the first report
#       ends the process), frame pointers kept for readable stacks.
#       scripts/check-sanitizers.sh uses it.
#   ARNOLDWEB_FUZZ=ON   the libFuzzer target for the scene reader (tests/fuzz);
#       needs clang (Debian: clang-14, libclang-rt-14-dev). scripts/check-fuzz.sh.
#
# Both go into one clang build directory (build-asan) in CI, so that the
# library is compiled once for both.
set(ARNOLDWEB_SANITIZE "" CACHE STRING
    "Sanitizers for every target, e.g. address,undefined (empty: none)")
option(ARNOLDWEB_SANITIZE_KERNELS "With ARNOLDWEB_SANITIZE: the cpu kernel variants sanitized too (slow: lib/CMakeLists.txt)" OFF)
option(ARNOLDWEB_FUZZ "Build the libFuzzer target of the scene reader (clang only)" OFF)

if(ARNOLDWEB_SANITIZE)
  add_compile_options(-fsanitize=${ARNOLDWEB_SANITIZE} -fno-sanitize-recover=all
                      -fno-omit-frame-pointer -g)
  add_link_options(-fsanitize=${ARNOLDWEB_SANITIZE})
  message(STATUS "arnoldweb: sanitizers ${ARNOLDWEB_SANITIZE} on every target")
endif()

if(ARNOLDWEB_FUZZ AND NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "ARNOLDWEB_FUZZ needs clang (libFuzzer): configure with "
                      "-DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_C_COMPILER=clang-14 "
                      "(Debian: clang-14, libclang-rt-14-dev)")
endif()
