#!/usr/bin/env bash
# Configures and builds the checked build: clang-14 with AddressSanitizer and
# UndefinedBehaviorSanitizer on every target (ARNOLDWEB_SANITIZE) and the
# libFuzzer target of the scene reader (ARNOLDWEB_FUZZ), in build-asan/ (or
# $ARNOLDWEB_ASAN_BUILD_DIR). One build directory serves scripts/check-fuzz.sh
# and scripts/check-sanitizers.sh, so the library is compiled once for both.
#
#   scripts/build-asan.sh [TARGET...]      (default: every target)
#
# Parallel jobs: $ARNOLDWEB_JOBS (default 2, the cores CI has).
# ARNOLDWEB_SANITIZE_KERNELS=ON: the cpu kernel variants sanitized too (scripts/check.sh
# --long; about 20 CPU-minutes more on 2 cores; lib/CMakeLists.txt says why not in CI).
#
# Exits 77 (skipped) with the reason when clang-14 or its sanitizer runtimes
# are missing (Debian: clang-14 libclang-rt-14-dev libomp-14-dev).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${ARNOLDWEB_ASAN_BUILD_DIR:-build-asan}"

for tool in clang-14 clang++-14 cmake ninja; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "SKIPPED: $tool not found (Debian 12: apt-get install clang-14 libclang-rt-14-dev libomp-14-dev cmake ninja-build)"
    exit 77
  fi
done
rt_dir="$(clang-14 -print-resource-dir)/lib/linux"
for rt in libclang_rt.fuzzer-x86_64.a libclang_rt.asan-x86_64.a libclang_rt.ubsan_standalone-x86_64.a; do
  if [ ! -e "$rt_dir/$rt" ]; then
    echo "SKIPPED: $rt_dir/$rt not found (Debian 12: apt-get install libclang-rt-14-dev)"
    exit 77
  fi
done

# CUDA stays off: NVRTC and the CUDA runtime are not instrumented and there is
# no GPU in CI. The benchmarks are not needed here.
cmake -S . -B "$build_dir" -G Ninja \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
  -DARNOLDWEB_SANITIZE=address,undefined -DARNOLDWEB_FUZZ=ON \
  -DARNOLDWEB_CUDA=OFF -DARNOLDWEB_BENCH=OFF \
  -DARNOLDWEB_SANITIZE_KERNELS="${ARNOLDWEB_SANITIZE_KERNELS:-OFF}" \
  -DARNOLDWEB_CPU_ISAS= >/dev/null  # one set of cpu kernels (native): the sets give the same bits (ctest cpu.isa)
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$build_dir" -j"${ARNOLDWEB_JOBS:-2}" "${targets[@]}"
