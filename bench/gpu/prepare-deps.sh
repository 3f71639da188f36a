#!/usr/bin/env bash
# Here (the Debian machine), before any device call: .device-deps/ with the Debian
# packages the GPU machine's image lacks (toml++, Random123, xxHash, stb) and the
# shared recipe's device-setup.sh, which every script of bench/gpu/ sources there
# (docs/gpu.md). The one list of those packages: the build there needs each.
#   bash bench/gpu/prepare-deps.sh [SHARED]    (SHARED: ../shared beside the clone)
set -euo pipefail
cd "$(dirname "$0")/../.."
shared=${1:-../shared}
[ -x "$shared/gpu/fetch-debs.sh" ] || { echo "prepare-deps: no $shared/gpu/fetch-debs.sh (give the shared folder)" >&2; exit 2; }
packages=(libtomlplusplus-dev libtomlplusplus3 librandom123-dev libxxhash-dev libxxhash0 libstb-dev)
"$shared/gpu/fetch-debs.sh" .device-deps "${packages[@]}" >/dev/null
cp "$shared/gpu/device-setup.sh" .device-deps/
for p in "${packages[@]}"; do
  ls .device-deps/"$p"_*.deb >/dev/null 2>&1 || { echo "prepare-deps: $p was not fetched" >&2; exit 1; }
done
echo "prepare-deps: .device-deps/ ready ($(du -sh .device-deps | cut -f1)); carry [\".device-deps\"]"
