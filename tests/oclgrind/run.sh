#!/usr/bin/env bash
# ctest `oclgrind`: runs the oclgrind suite (tests/test_oclgrind.cpp: every
# kernel variant on a tiny ensemble, compared bit for bit with the cpu
# backend) under Oclgrind, the OpenCL simulator, and fails on any error it
# reports.
#
#   tests/oclgrind/run.sh ARNOLDWEB_TESTS [OCLGRIND]
#
# Oclgrind comes as a wrapper command (Debian's oclgrind registers no ICD):
# `oclgrind PROGRAM` preloads its OpenCL runtime, so inside PROGRAM the only
# OpenCL platform is Oclgrind's and every other test run never sees it.
# Two passes:
#   1. every variant with --check-api (API misuse) and --data-races (global
#      and local memory); out-of-bounds and invalid accesses are always on;
#   2. the variants without energy tracking with --uninitialized (Oclgrind
#      21.10's plugin cannot follow frexp() into private memory, which the
#      energy histogram uses; see the test case's comment).
# Oclgrind writes its diagnostics to a log (--log); a non-empty log fails.
# Exit 77 (skipped) with the reason when oclgrind is not installed (exit 1
# instead when ARNOLDWEB_REQUIRE_CHECKS=1, as in CI).
set -euo pipefail
tests="${1:?usage: $0 ARNOLDWEB_TESTS [OCLGRIND]}"
oclgrind="${2:-}"
if [ -z "$oclgrind" ] || [ ! -x "$oclgrind" ]; then
  oclgrind="$(command -v oclgrind || true)"
fi
if [ -z "$oclgrind" ]; then
  echo "SKIPPED: oclgrind not found (Debian: apt-get install oclgrind)"
  # CI (.ci/run) installs it: there a missing oclgrind is a failure
  [ "${ARNOLDWEB_REQUIRE_CHECKS:-0}" = 1 ] && exit 1
  exit 77
fi

logs="$(mktemp -d "${TMPDIR:-/tmp}/arnoldweb-oclgrind-XXXXXX")"
trap 'rm -rf "$logs"' EXIT
failed=0

pass() {  # pass NAME TEST-CASE OCLGRIND-OPTIONS...
  local name="$1" case="$2"
  shift 2
  local log="$logs/$name.log"
  local start=$SECONDS status=0
  echo "oclgrind pass '$name': oclgrind $* --log $log ... -tc=\"$case\""
  # ARNOLDWEB_TEST_QUICK_EXIT: no static destructors (tests/main.cpp says why)
  ARNOLDWEB_TEST_QUICK_EXIT=1 "$oclgrind" "$@" --log "$log" \
    "$tests" -ts=oclgrind --no-skip --backend=opencl -tc="$case" || status=$?
  if [ "$status" -ne 0 ]; then
    echo "oclgrind pass '$name': FAILED (exit $status)"
    failed=1
  fi
  if [ -s "$log" ]; then
    echo "oclgrind pass '$name': Oclgrind reported errors:"
    head -n 200 "$log"
    failed=1
  fi
  echo "oclgrind pass '$name': $((SECONDS - start)) s, log $( [ -s "$log" ] && echo "$(wc -l <"$log") lines" || echo empty)"
}

pass memory-api-races "every kernel variant*" --check-api --data-races
pass uninitialized "kernel variants without energy tracking*" --check-api --uninitialized

[ "$failed" -eq 0 ] && echo "oclgrind: no errors reported"
exit "$failed"
