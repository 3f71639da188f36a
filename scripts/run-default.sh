#!/usr/bin/env bash
# Set up (scripts/bootstrap.sh) and run the default scene on the default
# device (a GPU if there is one, else PoCL on the CPU). Output: out/default/.
# Builds only what the run needs: the program (with the library) and the
# pictures' plugin; the tests are built by scripts/test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
ARNOLDWEB_BUILD_TARGETS="arnoldweb-cli arnoldweb_pictures" scripts/bootstrap.sh
exec build/arnoldweb run scenes/default.toml --force "$@"
