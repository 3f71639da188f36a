#!/usr/bin/env bash
# Fuzzes the scene reader and the --set parser (tests/fuzz/fuzz_scene.cpp) with
# libFuzzer + ASan + UBSan for a bounded time, and fails on any finding: a
# crash, an unexpected exception, a hang (> 10 s for one input), a sanitizer
# report. Prints the number of executions. Builds build-asan/ first
# (scripts/build-asan.sh).
#
#   scripts/check-fuzz.sh              60 s (CI)
#   scripts/check-fuzz.sh --long       1 hour
#   ARNOLDWEB_FUZZ_SECONDS=600 scripts/check-fuzz.sh
#   ARNOLDWEB_FUZZ_RUNS=100000 scripts/check-fuzz.sh    a fixed number of inputs instead
#
# Seeds: tests/fuzz/corpus (real and bad scenes, with overrides) and scenes/.
# New inputs go to build-asan/fuzz-corpus (kept between local runs), findings
# to build-asan/fuzz-artifacts/. Inputs are at most 8192 bytes (-max_len):
# longer inputs reach known limits of the TOML parser (a dotted header of
# ~35,000 keys overflows its stack, multi-MB keys take minutes) that the
# scene reader must refuse before parsing (issue 12, item 7).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${ARNOLDWEB_ASAN_BUILD_DIR:-build-asan}"

seconds="${ARNOLDWEB_FUZZ_SECONDS:-60}"
runs="${ARNOLDWEB_FUZZ_RUNS:--1}"
for arg in "$@"; do
  case "$arg" in
    --long) seconds=3600 ;;
    *) echo "usage: $0 [--long]" >&2; exit 2 ;;
  esac
done
[ "$runs" != "-1" ] && seconds=0  # a fixed number of inputs, however long

rc=0
scripts/build-asan.sh arnoldweb_fuzz_scene || rc=$?
[ "$rc" -eq 0 ] || exit "$rc"
fuzzer="$build_dir/arnoldweb_fuzz_scene"

# The dictionary names every scene key.
missing=0
keys=0
while read -r key; do
  keys=$((keys + 1))
  if ! grep -Fqx "\"$key\"" tests/fuzz/scene.dict; then
    echo "check-fuzz: tests/fuzz/scene.dict lacks the scene key $key" >&2
    missing=1
  fi
done < <(ARNOLDWEB_FUZZ_LIST_KEYS=1 "$fuzzer")
if [ "$keys" -eq 0 ]; then
  echo "check-fuzz: $fuzzer listed no scene keys" >&2
  exit 1
fi
[ "$missing" -eq 0 ] || exit 1

symbolizer=/usr/lib/llvm-14/bin/llvm-symbolizer
[ -x "$symbolizer" ] && export ASAN_SYMBOLIZER_PATH="${ASAN_SYMBOLIZER_PATH:-$symbolizer}"

corpus="$build_dir/fuzz-corpus"
artifacts="$build_dir/fuzz-artifacts"
rm -rf "$artifacts"
mkdir -p "$corpus" "$artifacts"
log="$build_dir/fuzz.log"
echo "check-fuzz: fuzzing the scene reader for ${seconds} s (runs: $runs), log $log"
start=$(date +%s)
status=0
# -error_exitcode/-timeout_exitcode: libFuzzer's default 77 would read as "skipped"
ASAN_OPTIONS="${ASAN_OPTIONS:-}:halt_on_error=1:detect_leaks=1:detect_stack_use_after_return=1" \
UBSAN_OPTIONS="${UBSAN_OPTIONS:-}:halt_on_error=1:print_stacktrace=1" \
"$fuzzer" "$corpus" tests/fuzz/corpus scenes \
  -dict=tests/fuzz/scene.dict -max_len=8192 -timeout=10 -rss_limit_mb=2048 \
  -max_total_time="$seconds" -runs="$runs" \
  -error_exitcode=1 -timeout_exitcode=1 \
  -artifact_prefix="$artifacts/" -print_final_stats=1 >"$log" 2>&1 || status=$?
elapsed=$(( $(date +%s) - start ))

execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
cov=$(grep -Eo 'cov: [0-9]+ ft: [0-9]+' "$log" | tail -1 || true)
if [ "$status" -ne 0 ]; then
  tail -n 80 "$log"
  echo "check-fuzz: FAILED after ${elapsed} s and ${execs:-?} executions (exit $status); reproducer(s):"
  ls -1 "$artifacts" | sed "s|^|  $artifacts/|"
  echo "  replay one with: $fuzzer <file>"
  exit 1
fi
if [ -z "$execs" ]; then
  tail -n 40 "$log"
  echo "check-fuzz: FAILED: libFuzzer printed no statistics"
  exit 1
fi
echo "check-fuzz: passed: $execs executions in ${elapsed} s, 0 crashes ($cov, corpus $(ls "$corpus" | wc -l) inputs)"
