#!/usr/bin/env bash
# Fuzzes, with libFuzzer + ASan + UBSan for a bounded time each, and fails on
# any finding (a crash, an unexpected exception, a hang > 10 s for one input, a
# sanitizer report); prints the number of executions. Three targets:
#   scene   the scene reader and the --set parser (tests/fuzz/fuzz_scene.cpp)
#   saved   what render and compare read back: summary.json and map.h5
#           (tests/fuzz/fuzz_saved_run.cpp)
#   states  a state file (ensemble.file) as read_state_file reads it, written by
#           the harness from the input's description (tests/fuzz/fuzz_state_file.cpp)
# Builds build-asan/ first (scripts/build-asan.sh).
#
#   scripts/check-fuzz.sh              60 s per target (CI)
#   scripts/check-fuzz.sh --long       1 hour per target
#   ARNOLDWEB_FUZZ_SECONDS=600 scripts/check-fuzz.sh
#   ARNOLDWEB_FUZZ_RUNS=100000 scripts/check-fuzz.sh    a fixed number of inputs instead
#   ARNOLDWEB_FUZZ_TARGETS=saved scripts/check-fuzz.sh  one target
#   ARNOLDWEB_FUZZ_SEED=0 scripts/check-fuzz.sh         a random seed (libFuzzer's own)
#
# The bounded run (CI's) is reproducible: a fixed seed (ARNOLDWEB_FUZZ_SEED, 20261129) from
# the seeds alone (new inputs go to a corpus directory emptied first), so a fresh clone fuzzes
# the same inputs in the same order on every machine, a faster one further along the same
# sequence (libFuzzer is not exactly deterministic over a run: the same seed gave coverage
# within 1 % on two runs of 4,000 inputs). The long run (--long) takes a random seed and keeps
# its corpus (build-asan/fuzz-corpus*) between runs: it is the search for new findings.
#
# HDF5: arnoldweb reads the HDF5 files it cannot vouch for in a child process
# (lib/src/os/isolated.hpp), where a defect of HDF5 1.10.8's parser (tests/fuzz/hdf5-defects/)
# ends the child and is a refusal naming the file. The saved target's bounded run reads so (as a
# user's reader does): an input that crashes HDF5 is refused, and counted at the end (libFuzzer's
# handler in the child leaves it in build-asan/fuzz-artifacts/, a crash of HDF5, not of the
# run). Its long run, and the states target (whose files are well formed), read in this process
# (ARNOLDWEB_HDF5_IN_PROCESS=1): the fuzzer sees the readers' coverage, and a defect of HDF5 is a
# finding to look at (and to refuse before HDF5 opens the file where it can be recognised:
# lib/src/output/h5_heaps.hpp).
#
# Seeds: tests/fuzz/corpus (real and bad scenes, with overrides) and scenes/;
# tests/fuzz/corpus-saved (small output directories, made by
# tests/fuzz/make_saved_corpus.py); tests/fuzz/corpus-states (descriptions of state
# files, good and hostile, that the harness writes: tests/fuzz/make_state_corpus.py). New inputs go to build-asan/fuzz-corpus*
# (kept between local runs), findings to build-asan/fuzz-artifacts/. Scene
# inputs are at most 8192 bytes (-max_len): longer inputs reach known limits
# of the TOML parser (a dotted header of ~35,000 keys overflows its stack,
# multi-MB keys take minutes) that the scene reader must refuse before parsing
# (issue 12, item 7); saved-run and state-file inputs at most 65536 (the seeds
# are 1-32 kB).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${ARNOLDWEB_ASAN_BUILD_DIR:-build-asan}"

seconds="${ARNOLDWEB_FUZZ_SECONDS:-60}"
runs="${ARNOLDWEB_FUZZ_RUNS:--1}"
long=0 seed="${ARNOLDWEB_FUZZ_SEED:-20261129}"
for arg in "$@"; do
  case "$arg" in
    --long) seconds=3600 long=1 seed="${ARNOLDWEB_FUZZ_SEED:-0}" ;;
    *) echo "usage: $0 [--long]" >&2; exit 2 ;;
  esac
done
[ "$runs" != "-1" ] && seconds=0  # a fixed number of inputs, however long

targets="${ARNOLDWEB_FUZZ_TARGETS:-scene saved states}"
rc=0
scripts/build-asan.sh arnoldweb_fuzz_scene arnoldweb_fuzz_saved_run arnoldweb_fuzz_state_file || rc=$?
[ "$rc" -eq 0 ] || exit "$rc"
fuzzer="$build_dir/arnoldweb_fuzz_scene"

# The dictionary: every scene key of the key table (the fuzzer lists them), dotted and by its
# last name, then tests/fuzz/scene.dict (sections, values, syntax): a new key needs no edit here.
scene_dict="$build_dir/scene.dict"
ARNOLDWEB_FUZZ_LIST_KEYS=1 "$fuzzer" | awk '{ print "\"" $0 "\""; n = split($0, p, "."); print "\"" p[n] "\"" }' |
  sort -u >"$scene_dict"
if [ ! -s "$scene_dict" ]; then
  echo "check-fuzz: $fuzzer listed no scene keys" >&2
  exit 1
fi
cat tests/fuzz/scene.dict >>"$scene_dict"

symbolizer=/usr/lib/llvm-14/bin/llvm-symbolizer
[ -x "$symbolizer" ] && export ASAN_SYMBOLIZER_PATH="${ASAN_SYMBOLIZER_PATH:-$symbolizer}"

artifacts="$build_dir/fuzz-artifacts"
rm -rf "$artifacts"
mkdir -p "$artifacts"

# fuzz NAME FUZZER DICT MAX_LEN SEED_DIR...: one target for the bound; 0 if no finding.
# $asan_extra, $lsan_options and $fuzz_flags add sanitizer and libFuzzer options; $in_process (1 or 0)
# is ARNOLDWEB_HDF5_IN_PROCESS.
fuzz() {
  local name="$1" fuzzer="$2" dict="$3" max_len="$4"
  shift 4
  local corpus="$build_dir/fuzz-corpus-$name" log="$build_dir/fuzz-$name.log"
  if [ "$long" = 1 ]; then
    [ "$name" = scene ] && [ -d "$build_dir/fuzz-corpus" ] && corpus="$build_dir/fuzz-corpus"  # kept from before
  else
    corpus="$build_dir/fuzz-corpus-$name-bounded"  # from the seeds alone: reproducible
    rm -rf "$corpus"
  fi
  mkdir -p "$corpus"
  echo "check-fuzz: fuzzing $name for ${seconds} s (runs: $runs, seed: $seed), log $log"
  local start status=0
  start=$(date +%s)
  # -error_exitcode/-timeout_exitcode: libFuzzer's default 77 would read as "skipped"
  ASAN_OPTIONS="${ASAN_OPTIONS:-}:halt_on_error=1:detect_leaks=1:detect_stack_use_after_return=1$asan_extra" \
  LSAN_OPTIONS="${LSAN_OPTIONS:-}$lsan_options" \
  UBSAN_OPTIONS="${UBSAN_OPTIONS:-}:halt_on_error=1:print_stacktrace=1" ARNOLDWEB_HDF5_IN_PROCESS="$in_process" \
  "$fuzzer" "$corpus" "$@" \
    -dict="$dict" -max_len="$max_len" -timeout=10 -rss_limit_mb=2048 $fuzz_flags \
    -max_total_time="$seconds" -runs="$runs" -seed="$seed" \
    -error_exitcode=1 -timeout_exitcode=1 \
    -artifact_prefix="$artifacts/$name-" -print_final_stats=1 >"$log" 2>&1 || status=$?
  local elapsed=$(( $(date +%s) - start ))
  local execs cov
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  cov=$(grep -Eo 'cov: [0-9]+ ft: [0-9]+' "$log" | tail -1 || true)
  if [ "$status" -ne 0 ]; then
    tail -n 80 "$log"
    echo "check-fuzz: $name FAILED after ${elapsed} s and ${execs:-?} executions (exit $status); reproducer(s):"
    ls -1 "$artifacts" | sed "s|^|  $artifacts/|"
    echo "  replay one with: $fuzzer <file>"
    return 1
  fi
  local contained
  contained=$(find "$artifacts" -name "$name-*" | wc -l)
  if [ -z "$execs" ]; then
    tail -n 40 "$log"
    echo "check-fuzz: $name FAILED: libFuzzer printed no statistics"
    return 1
  fi
  echo "check-fuzz: $name passed: $execs executions in ${elapsed} s, 0 crashes ($cov, corpus $(ls "$corpus" | wc -l) inputs)"
  [ "$contained" -eq 0 ] ||
    echo "check-fuzz: $name: $contained input(s) crashed HDF5 in its child process and were refused (in $artifacts)"
}

failed=0
for t in $targets; do
  case "$t" in
    scene)
      asan_extra="" lsan_options="" fuzz_flags="" in_process=0
      fuzz scene "$fuzzer" "$scene_dict" 8192 tests/fuzz/corpus scenes || failed=1 ;;
    saved)
      # HDF5 sizes buffers by what a (malformed) file says: an allocation beyond
      # 2 GiB fails (HDF5 reports an error) instead of counting as a finding, and
      # HDF5's own leaks on a failed open are suppressed (tests/fuzz/hdf5.supp)
      asan_extra=":allocator_may_return_null=1:max_allocation_size_mb=2048"
      lsan_options=":suppressions=$PWD/tests/fuzz/hdf5.supp" fuzz_flags="-malloc_limit_mb=100000"
      in_process=$long
      fuzz saved "$build_dir/arnoldweb_fuzz_saved_run" tests/fuzz/saved.dict 65536 tests/fuzz/corpus-saved \
        || failed=1 ;;
    states)
      # the same HDF5 allowances (the files are well-formed; the reader bounds memory by their size)
      asan_extra=":allocator_may_return_null=1:max_allocation_size_mb=2048"
      lsan_options=":suppressions=$PWD/tests/fuzz/hdf5.supp" fuzz_flags="-malloc_limit_mb=100000"
      in_process=1
      fuzz states "$build_dir/arnoldweb_fuzz_state_file" tests/fuzz/states.dict 65536 tests/fuzz/corpus-states \
        || failed=1 ;;
    *) echo "check-fuzz: unknown target $t (scene, saved, states)" >&2; exit 2 ;;
  esac
done
exit "$failed"
