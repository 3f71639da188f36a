#!/usr/bin/env bash
# The continuous checks that need their own build (docs/reliability.md,
# "Continuous checks"); CI (.ci/run) runs them after scripts/test.sh, whose
# ctest run already holds the Oclgrind check (ctest oclgrind).
#
#   1. build-asan/: clang-14, ASan + UBSan on every target (the cpu kernel variants
#      only with --long), and the fuzz target
#      (scripts/build-asan.sh)
#   2. the fast suites under the sanitizers (scripts/check-sanitizers.sh)
#   3. the scene reader, what render and compare read back, and state files,
#      fuzzed for 60 s each (scripts/check-fuzz.sh)
#
#   scripts/check.sh            bounded, for CI (about 7 minutes on 2 cores)
#   scripts/check.sh --long     the fuzzer for an hour instead of a minute, and the cpu
#                               kernel variants sanitized too (ARNOLDWEB_SANITIZE_KERNELS)
#
# A check that cannot run here (a tool missing) reports itself SKIPPED with
# the reason; with ARNOLDWEB_REQUIRE_CHECKS=1 (set by .ci/run, where every
# tool is installed) a skipped check fails.
set -uo pipefail
cd "$(dirname "$0")/.."

fuzz_args=()
for arg in "$@"; do
  case "$arg" in
    --long) fuzz_args+=(--long); export ARNOLDWEB_SANITIZE_KERNELS=ON ;;
    *) echo "usage: $0 [--long]" >&2; exit 2 ;;
  esac
done

summary=()
failed=0
stage() {  # stage NAME COMMAND...
  local name="$1" start=$SECONDS status=0
  shift
  echo "=== check: $name"
  "$@" || status=$?
  local took=$((SECONDS - start))
  case "$status" in
    0) summary+=("passed   $name (${took} s)") ;;
    77)
      summary+=("SKIPPED  $name (${took} s): the reason is printed above")
      [ "${ARNOLDWEB_REQUIRE_CHECKS:-0}" = 1 ] && failed=1
      ;;
    *) summary+=("FAILED   $name (${took} s, exit $status)"); failed=1 ;;
  esac
  return "$status"
}

if stage "build-asan (clang-14, ASan+UBSan, fuzz targets)" \
     scripts/build-asan.sh arnoldweb_tests arnoldweb-cli arnoldweb_fuzz_scene arnoldweb_fuzz_saved_run \
       arnoldweb_fuzz_state_file; then
  stage "sanitizers (unit, parity and order on cpu and PoCL)" scripts/check-sanitizers.sh
  stage "fuzz (scene reader and --set; summary.json and map.h5 read back; state files)" \
    scripts/check-fuzz.sh "${fuzz_args[@]}"
else
  summary+=("SKIPPED  sanitizers, fuzz: build-asan did not build")
fi

echo "=== check: summary"
printf '  %s\n' "${summary[@]}"
exit "$failed"
