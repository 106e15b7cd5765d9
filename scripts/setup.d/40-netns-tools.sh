#!/usr/bin/env bash
# Tools of the bad-links suite (tests/interop/links): `ip` (network namespaces, veth,
# link down/up) and `tc` (tbf shaping), both from Debian's iproute2. Idempotent: installs
# only what is missing, waiting for another apt to release its lock.
set -euo pipefail
if command -v ip >/dev/null && command -v tc >/dev/null; then
    echo "netns tools ready: $(ip -V)"
    exit 0
fi
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
"${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 update
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 \
    install -y --no-install-recommends iproute2
echo "netns tools ready: $(ip -V)"
