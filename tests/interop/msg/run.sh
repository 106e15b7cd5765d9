#!/usr/bin/env bash
# fleetlink-msg against the real peers (rosbags from PyPI, Debian's rospy):
#  1. regenerates the committed vectors with the peers and requires them unchanged;
#  2. drives the `fleetlink msg` binary over every vector: its bytes must equal the
#     peer's, the peer must decode them, and its JSON for the peer's bytes must match.
# Needs scripts/setup.d/30-msg-peers.sh to have run. Bounded by `timeout`.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
py="$here/.venv/bin/python"
[ -x "$py" ] || { echo "msg interop: $py missing; run scripts/setup.d/30-msg-peers.sh" >&2; exit 1; }

bin="${FLEETLINK_BIN:-}"
if [ -z "$bin" ]; then
    (cd "$root" && cargo build --quiet -p fleetlink)
    bin="$root/target/debug/fleetlink"
fi

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

echo "msg interop: regenerating vectors with rosbags and rospy"
timeout 300 "$py" "$here/gen_vectors.py" "$tmp/vectors" >/dev/null
if ! diff -r "$tmp/vectors" "$root/crates/msg/tests/vectors" >/dev/null; then
    echo "msg interop: committed vectors differ from what the peers produce now;" >&2
    echo "  regenerate: $py tests/interop/msg/gen_vectors.py" >&2
    diff -r "$tmp/vectors" "$root/crates/msg/tests/vectors" | head -5 >&2
    exit 1
fi
echo "msg interop: vectors are current"

echo "msg interop: fleetlink msg encode/decode against rosbags (CDR) and rospy (ROS 1)"
timeout 900 "$py" "$here/peer_check.py" "$bin"
echo "msg interop: passed"
