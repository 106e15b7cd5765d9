#!/usr/bin/env bash
# mold, Debian's fast linker: the test command links about thirty test binaries and the
# fleetlink binary, each holding the whole dependency tree, and GNU ld spends minutes on
# them. Builds use it through scripts/cc-link (see .cargo/config.toml) when it is
# installed, and the default linker when it is not. Idempotent; waits for apt's lock.
set -euo pipefail
if command -v mold >/dev/null; then
    echo "linker ready: $(mold --version)"
    exit 0
fi
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
"${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 update
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 \
    install -y --no-install-recommends mold
echo "linker ready: $(mold --version)"
