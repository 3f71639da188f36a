#!/usr/bin/env bash
# Set up (scripts/bootstrap.sh) and run the whole test suite on every device
# present. Suites bound to a backend this machine lacks (e.g. cuda without a
# GPU) are reported as skipped, with the reason.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
scripts/bootstrap.sh
echo "test.sh: set-up and build took $((SECONDS - start)) s"
ctest --test-dir build --output-on-failure --timeout 1500 -j"$(nproc)" "$@"
