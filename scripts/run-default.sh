#!/usr/bin/env bash
# Set up (scripts/bootstrap.sh) and run the default scene on the default
# device (a GPU if there is one, else PoCL on the CPU). Output: out/default/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh
exec build/arnoldweb run scenes/default.toml --force "$@"
