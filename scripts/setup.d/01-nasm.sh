#!/usr/bin/env bash
# The assembler for OpenH264's x86 assembly (crates/video builds OpenH264 from source):
# nasm, from Debian. Without it the build still works, with OpenH264's plain C++ paths,
# and a 640x480 frame takes about four times as long to encode (docs/video.md). Must
# come before the first build. Idempotent; waits for another apt's lock.
set -euo pipefail
if command -v nasm >/dev/null; then
    echo "nasm ready: $(nasm -v)"
    exit 0
fi
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
"${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 update
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 \
    install -y --no-install-recommends nasm
echo "nasm ready: $(nasm -v)"
