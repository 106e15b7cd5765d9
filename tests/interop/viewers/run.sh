#!/usr/bin/env bash
# Viewers suite (issue 56): rosbridge and Foxglove viewers that vanish without closing
# their connection — a cut link, a frozen process — are closed by the hub within its
# silence limit plus a second, and the robot's topic goes idle; a viewer behind a
# 256 kbit/s link is kept for two minutes; the agent's local listener releases a frozen
# local program. viewers_check.py drives the scenarios (see its docstring).
#
# Two network namespaces per run, flvh-<pid>-<random> (hub and agent) and flvv-... (the
# viewers), joined by a veth pair (10.202.0.1/30 hub, .2 viewers); no traffic leaves them.
# On any exit every process left in them is killed and they are deleted. Needs root and
# `ip netns`, otherwise SKIP. Bounded: the driver runs under `timeout` (6 minutes).
#
# Env: FLEETLINK_BIN (default target/release/fleetlink), PYTHON (default .venv/bin/python),
#      VIEWERS_SCENARIOS ("cut frozen foxglove slow local"), VIEWERS_KEEP (keep the logs).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
packages="$root/tests/interop/foxglove"
limit_s=360

if [ "$(id -u)" -ne 0 ]; then
    echo "SKIP: viewers suite needs root (network namespaces, tc)"; exit 0
fi
if ! command -v ip >/dev/null || ! ip netns list >/dev/null 2>&1; then
    echo "SKIP: viewers suite needs \`ip netns\` (iproute2)"; exit 0
fi
command -v tc >/dev/null || { echo "FAIL: tc (iproute2) missing" >&2; exit 1; }
command -v node >/dev/null || { echo "FAIL: node missing" >&2; exit 1; }
[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -x "$python" ] || { echo "FAIL: $python missing; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }
[ -f "$packages/node_modules/@foxglove/ws-protocol/package.json" ] ||
    { echo "FAIL: Foxglove packages missing; run scripts/setup.d/20-node-packages.sh" >&2; exit 1; }
bin="$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")"

run_id="$$-$(od -An -N2 -tx2 /dev/urandom | tr -d ' ')"
hub_ns="flvh-$run_id"
viewer_ns="flvv-$run_id"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/fleetlink-interop-viewers.XXXXXX")"
# The agent keeps its state in the suite's directory, never the user's (as lib.sh does).
export XDG_STATE_HOME="$tmp/state"
made=()
driver=""

cleanup() {
    local rc=$?
    trap - EXIT INT TERM
    if [ -n "$driver" ] && kill -0 "$driver" 2>/dev/null; then
        kill -TERM "$driver" 2>/dev/null || true
        for _ in $(seq 50); do kill -0 "$driver" 2>/dev/null || break; sleep 0.1; done
    fi
    for ns in "${made[@]}"; do
        for pid in $(ip netns pids "$ns" 2>/dev/null); do
            kill -CONT "$pid" 2>/dev/null || true
            kill -KILL "$pid" 2>/dev/null || true
        done
        ip netns del "$ns" 2>/dev/null || true
    done
    if [ "$rc" -ne 0 ]; then
        for f in hub agent; do
            [ -f "$tmp/$f.out" ] && { echo "--- last lines of $f log"; tail -n 15 "$tmp/$f.out"; } >&2
        done
    fi
    if [ -n "${VIEWERS_KEEP:-}" ]; then echo "kept: $tmp" >&2; else rm -rf "$tmp"; fi
    exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

ip netns add "$hub_ns" && made+=("$hub_ns")
ip netns add "$viewer_ns" && made+=("$viewer_ns")
ip link add vh netns "$hub_ns" type veth peer name vv netns "$viewer_ns"
ip -n "$hub_ns" addr add 10.202.0.1/30 dev vh
ip -n "$viewer_ns" addr add 10.202.0.2/30 dev vv
for ns in "$hub_ns" "$viewer_ns"; do ip -n "$ns" link set lo up; done
ip -n "$hub_ns" link set vh up
ip -n "$viewer_ns" link set vv up
# The hub's packets to the viewers leave at wire size, so tbf paces them as a slow link
# would (segmentation offload would hand it 64 KB at a time).
ip -n "$hub_ns" link set vh gso_max_size 1500 gso_max_segs 1
echo "namespaces: $hub_ns (hub, vh 10.202.0.1) <-> $viewer_ns (viewers, vv 10.202.0.2)"

rc=0
export NO_COLOR=1 PYTHONDONTWRITEBYTECODE=1
timeout --kill-after=10 "$limit_s" ip netns exec "$hub_ns" "$python" "$here/viewers_check.py" \
    --viewer-ns "$viewer_ns" --hub-ip 10.202.0.1 --viewer-dev vv --hub-dev vh \
    --bin "$bin" --python "$python" --tmp "$tmp" --node-packages "$packages" \
    --scenarios "${VIEWERS_SCENARIOS:-cut frozen foxglove slow local}" &
driver=$!
wait "$driver" || rc=$?
if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then
    echo "FAIL: viewers suite exceeded ${limit_s} s" >&2
fi
exit "$rc"
