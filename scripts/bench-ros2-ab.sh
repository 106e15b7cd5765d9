#!/usr/bin/env bash
# Two builds of the agent bridging the same ROS 2 point-cloud stream at the same time:
# one Cyclone DDS writer (~1 MB sensor_msgs/msg/PointCloud2 at 10 Hz on /points, as in
# scripts/bench-ros2.sh), agent A and agent B each carrying it to a hub of its own build,
# each hub with a cbor-raw subscriber. Both agents see the same samples and the same
# machine load, so their CPU figures compare within one run; on a shared machine the
# spread between separate runs is larger than most changes.
#
#   scripts/bench-ros2-ab.sh BUILD_A BUILD_B [SECONDS] [ROUNDS]
#
# Each round starts both in turn order A, B and then B, A (the order the agents join the
# domain is swapped every round). Prints each agent's CPU (% of one core, from
# /proc/<pid>/stat over the measured window) and latency p50/p99 per round, then the
# medians. Runs in a network namespace of its own (DDS multicast stays in it): needs root.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
python="${PYTHON:-$root/.venv/bin/python}"
[ $# -ge 2 ] || { echo "usage: $0 BUILD_A BUILD_B [SECONDS] [ROUNDS]" >&2; exit 2; }
bin_a="$1" bin_b="$2" seconds="${3:-30}" rounds="${4:-2}"
for b in "$bin_a" "$bin_b"; do [ -x "$b" ] || { echo "not an executable: $b" >&2; exit 1; }; done
[ "$(id -u)" -eq 0 ] || { echo "needs root (network namespace): sudo $0" >&2; exit 1; }
"$python" -c 'import cyclonedds, cbor2, websockets' 2>/dev/null \
    || { echo "run scripts/setup.d/35-ros2-peers.sh first" >&2; exit 1; }

results="$(mktemp "${TMPDIR:-/tmp}/fleetlink-bench-ros2-ab.XXXXXX")"
trap 'rm -f "$results"' EXIT

one_round() { # first-build second-build first-label second-label
    local tmp ns
    tmp="$(mktemp -d "${TMPDIR:-/tmp}/fleetlink-bench-ros2-ab.XXXXXX")"
    ns="flbenchab-$$"
    # shellcheck disable=SC2064
    trap "ip netns pids $ns 2>/dev/null | xargs -r kill 2>/dev/null; sleep 1; \
          ip netns pids $ns 2>/dev/null | xargs -r kill -9 2>/dev/null; \
          ip netns del $ns 2>/dev/null; rm -rf $tmp" EXIT
    ip netns add "$ns"
    in_ns() { ip netns exec "$ns" "$@"; }
    in_ns ip link set lo up
    in_ns ip link set lo multicast on
    in_ns ip route add 224.0.0.0/4 dev lo
    export ROS_DOMAIN_ID=42 PYTHONPATH="$root/tests/interop/ros2"
    peer() { in_ns "$python" "$root/tests/interop/ros2/bench_peer.py" "$@"; }
    wait_line() { # file pattern
        for _ in $(seq 200); do grep -q "$2" "$1" 2>/dev/null && return 0; sleep 0.05; done
        echo "timed out waiting for '$2' in $1" >&2; cat "$1" >&2; exit 1
    }
    local i=0 bin label port op=() agent=() label_of=()
    for bin in "$1" "$2"; do
        label="$([ $i -eq 0 ] && echo "$3" || echo "$4")"
        port=$((18095 + i))
        "$bin" admin --data-dir "$tmp/hub$i" token robot robot1 2>/dev/null >"$tmp/robot$i.token"
        op[i]="$("$bin" admin --data-dir "$tmp/hub$i" token operator bench --group admin 2>/dev/null)"
        in_ns "$bin" hub --listen "127.0.0.1:$port" --data-dir "$tmp/hub$i" >"$tmp/hub$i.log" 2>&1 &
        wait_line "$tmp/hub$i.log" "listening on"
        cat >"$tmp/agent$i.yaml" <<EOF
hub: ws://127.0.0.1:$port/
name: robot1
token: $(cat "$tmp/robot$i.token")
local_rosbridge: { listen: "127.0.0.1:0" }
ros2:
  publish: { include: [/points] }
EOF
        in_ns "$bin" agent --config "$tmp/agent$i.yaml" >"$tmp/agent$i.log" 2>&1 &
        label_of[i]="$label"
        i=$((i + 1))
    done
    peer publish --seconds "$((seconds + 8))" --points 65536 >"$tmp/pub.log" 2>&1 &
    sleep 3
    for i in 0 1; do
        agent[i]="$(ip netns pids "$ns" | xargs -r ps -o pid=,args= -p \
            | awk -v want="agent --config $tmp/agent$i.yaml" 'index($0, want) {print $1; exit}')"
        [ -n "${agent[i]}" ] || { echo "agent $i not running:" >&2; cat "$tmp/agent$i.log" >&2; exit 1; }
    done
    local subs=()
    for i in 0 1; do
        peer hub-sub --url "ws://127.0.0.1:$((18095 + i))/?token=${op[i]}" --seconds "$seconds" \
            >"$tmp/sub$i.log" 2>&1 &
        subs+=($!)
    done
    wait_line "$tmp/sub0.log" "ready"
    wait_line "$tmp/sub1.log" "ready"
    ticks() { awk '{print $14 + $15}' "/proc/$1/stat"; }
    local t0 t1 c0=() c1=()
    t0=$(date +%s.%N); c0=("$(ticks "${agent[0]}")" "$(ticks "${agent[1]}")")
    wait "${subs[@]}" || true
    t1=$(date +%s.%N); c1=("$(ticks "${agent[0]}")" "$(ticks "${agent[1]}")")
    local hz; hz="$(getconf CLK_TCK)"
    for i in 0 1; do
        awk -v l="${label_of[i]}" -v a="${c0[i]}" -v b="${c1[i]}" -v t0="$t0" -v t1="$t1" \
            -v hz="$hz" -v lat="$(tail -n1 "$tmp/sub$i.log")" \
            'BEGIN {printf "%s %.2f %s\n", l, 100 * (b - a) / hz / (t1 - t0), lat}'
    done
}

echo "agents A ($bin_a) and B ($bin_b) bridging one PointCloud2 stream (1 MiB, 10 Hz), ${seconds} s a round"
echo "machine: $(nproc) cores, $(awk -F: '/model name/ {print $2; exit}' /proc/cpuinfo | sed 's/^ *//')"
for r in $(seq "$rounds"); do
    for order in AB BA; do
        if [ "$order" = AB ]; then out="$(one_round "$bin_a" "$bin_b" A B)"
        else out="$(one_round "$bin_b" "$bin_a" B A)"; fi
        echo "$out" >>"$results"
        echo "round $r, $order joined first: $(echo "$out" | awk '{printf "%s %s %%  ", $1, $2}')"
    done
done
python3 - "$results" <<'EOF'
import json, statistics, sys
rows = {"A": [], "B": []}
for line in open(sys.argv[1]):
    label, cpu, lat = line.split(" ", 2)
    rows[label].append((float(cpu), json.loads(lat)))
for label, rs in rows.items():
    cpus = [c for c, _ in rs]
    p50 = [l.get("p50_ms", float("nan")) for _, l in rs]
    p99 = [l.get("p99_ms", float("nan")) for _, l in rs]
    print(f"agent {label}: CPU median {statistics.median(cpus):.2f} % of one core "
          f"({', '.join(f'{c:.2f}' for c in cpus)}), latency p50 {statistics.median(p50):.1f} ms, "
          f"p99 {statistics.median(p99):.1f} ms")
EOF
