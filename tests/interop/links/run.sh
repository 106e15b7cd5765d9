#!/usr/bin/env bash
# Bad-links reliability suite: a hub and an agent in two network namespaces joined by a
# veth pair; blackouts (link down/up), a tbf bandwidth ramp, kill -9 of the hub and of
# the agent, a slowloris attack, and a link cut while service calls cross it both ways,
# with real roslibpy peers on both sides; what the robot's link carries while nobody wants its
# topics (interest); what compression saves on it (a lidar cloud and a JPEG); and a data
# budget that holds the link to 400 kbit/s while the highest priorities keep their rates.
#
# This script owns the namespace plumbing; links_check.py drives the scenarios
# (links_scenarios.py) and asserts their outcomes (see its docstring and
# docs/benchmarks/log.md, "Bad links"); peers.py are the roslibpy/WebSocket peers;
# selftest.py checks the measurement helpers first. Needs root and `ip netns`;
# otherwise it prints SKIP and exits 0.
#
# Namespaces are named per run (flh-<pid>-<random>, flr-...), so parallel or leftover runs
# do not collide; the veth pair lives only inside them (10.201.0.1/30 hub, .2 robot) and no
# traffic leaves them. On any exit every process left in the namespaces is killed and
# the namespaces are deleted. Bounded: the driver runs under `timeout` (9 minutes).
#
# Env: FLEETLINK_BIN (default target/release/fleetlink), PYTHON (default .venv/bin/python),
#      LINKS_OUT (results directory, default target/interop-links),
#      LINKS_SCENARIOS ("1 2 3 4 5 6 7 8 9 10 11"), LINKS_OUTBOX (auto|1|0), LINKS_SLOWLORIS (force),
#      LINKS_KEEP (non-empty: keep the logs and records in the temp directory),
#      LINKS_IDLE_P99_FLOOR_MS (15: the ramp's latency bound is 2 x max(idle p99, floor)).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
out="${LINKS_OUT:-$root/target/interop-links}"
limit_s=540

if [ "$(id -u)" -ne 0 ]; then
    echo "SKIP: bad-links suite needs root (network namespaces, tc)"; exit 0
fi
if ! command -v ip >/dev/null || ! ip netns list >/dev/null 2>&1; then
    echo "SKIP: bad-links suite needs \`ip netns\` (iproute2)"; exit 0
fi
command -v tc >/dev/null || { echo "FAIL: tc (iproute2) missing" >&2; exit 1; }
[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -x "$python" ] || { echo "FAIL: $python missing; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }
bin="$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")"
PYTHONDONTWRITEBYTECODE=1 "$python" "$here/selftest.py"

# Unique per run: the pid, plus a random part in case a leftover of an old run with the
# same pid is still around (this run then makes its own, and only ever deletes those).
run_id="$$-$(od -An -N2 -tx2 /dev/urandom | tr -d ' ')"
hub_ns="flh-$run_id"
robot_ns="flr-$run_id"
hub_ip=10.201.0.1
robot_ip=10.201.0.2
tmp="$(mktemp -d "${TMPDIR:-/tmp}/fleetlink-interop-links.XXXXXX")"
# Agents keep their state in this run's directory, never the user's: each gets its own
# runtime_file (harness.py), and the default one would be under $tmp/state too.
export XDG_STATE_HOME="$tmp/state"
unset STATE_DIRECTORY

made=()     # namespaces this run created
driver=""   # pid of the driver (its `timeout`)

cleanup() {
    local rc=$?
    trap - EXIT INT TERM
    if [ -n "$driver" ] && kill -0 "$driver" 2>/dev/null; then
        # Interrupted: the driver stops its own processes on TERM; bounded wait.
        kill -TERM "$driver" 2>/dev/null || true
        for _ in $(seq 50); do kill -0 "$driver" 2>/dev/null || break; sleep 0.1; done
    fi
    for ns in "${made[@]}"; do
        # Whatever the driver left behind (it stops its own processes; this covers a
        # driver killed by the timeout). Only processes inside our own namespaces.
        for pid in $(ip netns pids "$ns" 2>/dev/null); do kill -KILL "$pid" 2>/dev/null || true; done
        ip netns del "$ns" 2>/dev/null || true
    done
    if [ "$rc" -ne 0 ]; then
        # The latest hub and agent logs (earlier ones belong to scenarios already reported).
        for kind in hub agent; do
            f="$(ls "$tmp"/*-"$kind".out 2>/dev/null | tail -n1)"
            [ -n "$f" ] && { echo "--- last lines of $(basename "$f")"; tail -n 15 "$f"; } >&2
        done
    fi
    if [ -n "${LINKS_KEEP:-}" ]; then echo "kept: $tmp" >&2; else rm -rf "$tmp"; fi
    exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

ip netns add "$hub_ns" && made+=("$hub_ns")
ip netns add "$robot_ns" && made+=("$robot_ns")
# The veth pair is created straight into the namespaces: nothing appears in the root one.
ip link add vh netns "$hub_ns" type veth peer name vr netns "$robot_ns"
ip -n "$hub_ns" addr add "$hub_ip/30" dev vh
ip -n "$robot_ns" addr add "$robot_ip/30" dev vr
for ns in "$hub_ns" "$robot_ns"; do ip -n "$ns" link set lo up; done
ip -n "$hub_ns" link set vh up
ip -n "$robot_ns" link set vr up
# The robot's uplink leaves in wire-sized packets, as it would over a radio. With
# segmentation offload a veth hands tbf packets of up to 64 KB; one already queued when the
# ramp lowers the rate (and with it the bucket) can be larger than the new bucket, which
# tbf then never sends, and everything behind it waits until the rate rises again.
ip -n "$robot_ns" link set vr gso_max_size 1500 gso_max_segs 1
echo "namespaces: $hub_ns (hub, vh $hub_ip) <-> $robot_ns (robot, vr $robot_ip)"

# The driver runs in the hub namespace (the hub is on its loopback) and starts the
# robot-side processes with `ip netns exec`.
# In the background and waited for, so a TERM or INT to this script is acted on at once.
rc=0
export NO_COLOR=1 PYTHONDONTWRITEBYTECODE=1 # plain fleetlink logs; no __pycache__ in the tree
timeout --kill-after=10 "$limit_s" ip netns exec "$hub_ns" "$python" "$here/links_check.py" \
    --hub-ns "$hub_ns" --robot-ns "$robot_ns" --hub-ip "$hub_ip" --robot-dev vr \
    --bin "$bin" --python "$python" --tmp "$tmp" --out "$out" &
driver=$!
wait "$driver" || rc=$?
if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then
    echo "FAIL: bad-links suite exceeded ${limit_s} s" >&2
fi
exit "$rc"
