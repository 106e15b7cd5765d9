#!/usr/bin/env bash
# ROS Gateway's own experiment as a benchmark: an RGB camera (sensor_msgs/msg/Image rgb8,
# 0.31 MB) and a depth camera (16UC1, 0.2 MB) on a robot, at 30 Hz and then 60 Hz each,
# over a 100 Mbit/s uplink; what reaches a rosbridge subscriber at the hub, as a share of
# the ideal (min(source rate, link capacity / frame size), both cameras' bytes together),
# and the latency from publish to the subscriber (p50/p99).
#
#   sudo scripts/bench-rosgw.sh [--seconds 20] [--warmup 5] [--rates "30 60"]
#                               [--variants "defaults latest"] [--mbit 100]
#
# Two network namespaces joined by a veth pair (10.203.0.1/30 hub, .2 robot); the robot's
# egress (its uplink) goes through tbf: rate 100mbit, burst 125000 bytes (10 ms of the
# rate), latency 100 ms (the queue holds at most 100 ms of traffic, a modem's buffer), and
# leaves in wire-sized packets (no segmentation offload, as tests/interop/links/run.sh).
# The hub's direction is not shaped (it carries acknowledgements). scripts/bench-rosgw.py
# is the driver (hub, agent, camera publisher, subscriber; the tables) and says how the
# ideal is computed. Variants: `defaults` is the agent's QoS for sensor_msgs/Image (afr,
# queue 8, priority 2); any other word is a `policy:` for both cameras. Every variant
# sets `compression: none` (the data is random anyway).
#
# A benchmark, not a test: exits non-zero only when the setup fails. Before every run
# it waits while the bad-links suite runs (it shares the cores), and up to 10 minutes
# for rustc/cargo and for the machine to be quiet (under 30 % of one CPU busy); a run
# that had them beside it says so in the table, which also gives what the rest of the
# machine used during the window.
# On any exit every process in the two namespaces is killed and they are deleted.
#
# Env: FLEETLINK_BIN (default target/release/fleetlink), PYTHON (default .venv/bin/python),
#      ROSGW_KEEP (non-empty: keep the logs and results.json in the temp directory).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
seconds=20 warmup=5 rates="30 60" variants="defaults latest" mbit=100
while [ $# -gt 0 ]; do
    case "$1" in
        --seconds) seconds="$2"; shift 2 ;;
        --warmup) warmup="$2"; shift 2 ;;
        --rates) rates="$2"; shift 2 ;;
        --variants) variants="$2"; shift 2 ;;
        --mbit) mbit="$2"; shift 2 ;;
        *) echo "usage: $0 [--seconds S] [--warmup S] [--rates \"30 60\"] [--variants \"defaults latest\"] [--mbit 100]" >&2
           exit 2 ;;
    esac
done

[ "$(id -u)" -eq 0 ] || { echo "FAIL: needs root (network namespaces, tc)" >&2; exit 1; }
ip netns list >/dev/null 2>&1 || { echo "FAIL: needs \`ip netns\` (iproute2)" >&2; exit 1; }
command -v tc >/dev/null || { echo "FAIL: tc (iproute2) missing" >&2; exit 1; }
[ -x "$bin" ] || { echo "FAIL: fleetlink binary not found at $bin (set FLEETLINK_BIN)" >&2; exit 1; }
[ -x "$python" ] || { echo "FAIL: $python missing; run scripts/setup.d/10-python-venv.sh" >&2; exit 1; }
bin="$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")"

run_id="$$-$(od -An -N2 -tx2 /dev/urandom | tr -d ' ')"
hub_ns="frh-$run_id"
robot_ns="frr-$run_id"
hub_ip=10.203.0.1
robot_ip=10.203.0.2
tmp="$(mktemp -d "${TMPDIR:-/tmp}/fleetlink-bench-rosgw.XXXXXX")"
made=()    # namespaces this run created
driver=""  # pid of the driver

cleanup() {
    local rc=$?
    trap - EXIT INT TERM
    if [ -n "$driver" ] && kill -0 "$driver" 2>/dev/null; then
        kill -TERM "$driver" 2>/dev/null || true  # it stops its own processes
        for _ in $(seq 50); do kill -0 "$driver" 2>/dev/null || break; sleep 0.1; done
    fi
    for ns in "${made[@]}"; do
        # Only processes inside our own namespaces.
        for pid in $(ip netns pids "$ns" 2>/dev/null); do kill -KILL "$pid" 2>/dev/null || true; done
        ip netns del "$ns" 2>/dev/null || true
    done
    if [ -n "${ROSGW_KEEP:-}" ]; then echo "kept: $tmp" >&2; else rm -rf "$tmp"; fi
    exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

ip netns add "$hub_ns" && made+=("$hub_ns")
ip netns add "$robot_ns" && made+=("$robot_ns")
ip link add vh netns "$hub_ns" type veth peer name vr netns "$robot_ns"
ip -n "$hub_ns" addr add "$hub_ip/30" dev vh
ip -n "$robot_ns" addr add "$robot_ip/30" dev vr
for ns in "$hub_ns" "$robot_ns"; do ip -n "$ns" link set lo up; done
ip -n "$hub_ns" link set vh up
ip -n "$robot_ns" link set vr up
ip -n "$robot_ns" link set vr gso_max_size 1500 gso_max_segs 1
burst="$(awk -v m="$mbit" 'BEGIN { b = int(m * 1e6 / 8 * 0.010); print (b < 16000 ? 16000 : b) }')"
tbf=(rate "${mbit}mbit" burst "$burst" latency 100ms)
ip netns exec "$robot_ns" tc qdisc replace dev vr root tbf "${tbf[@]}"

echo "bench-rosgw: $(date -u +%Y-%m-%dT%H:%MZ); $("$bin" --version); $(nproc) CPUs," \
     "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "namespaces: $hub_ns (hub, vh $hub_ip) <-> $robot_ns (robot, vr $robot_ip);" \
     "robot egress: tbf ${tbf[*]}"

rc=0
export NO_COLOR=1 PYTHONDONTWRITEBYTECODE=1
# shellcheck disable=SC2086 # the lists are meant to split into arguments
ip netns exec "$hub_ns" "$python" "$here/bench-rosgw.py" drive \
    --hub-ns "$hub_ns" --robot-ns "$robot_ns" --hub-ip "$hub_ip" --robot-dev vr \
    --bin "$bin" --python "$python" --tmp "$tmp" --mbit "$mbit" \
    --rates $rates --variants $variants --seconds "$seconds" --warmup "$warmup" &
driver=$!
wait "$driver" || rc=$?
if [ "$rc" -ne 0 ]; then
    for f in "$tmp"/*-hub.out "$(ls "$tmp"/*-agent-*.out 2>/dev/null | tail -n1)"; do
        [ -f "$f" ] && { echo "--- last lines of $(basename "$f")"; tail -n 15 "$f"; } >&2
    done
fi
exit "$rc"
