#!/usr/bin/env bash
# Bytes on the robots' links with interest (issue 37's benchmark): ROBOTS simulated robots
# (the simulator's five default sensors each) connect from one network namespace to a hub
# in another over a veth pair; one rosbridge client at the hub watches one topic of one
# robot (/robot1/pose). The robots' side of the veth counts what every uplink sends over
# SECONDS, first with the agents as they are (a topic goes up only while someone wants it),
# then with every topic `always: true` (what every robot sent before interest): same hub,
# same watcher, same run.
#
#   cargo build --release -p fleetlink && sudo scripts/bench-interest.sh [ROBOTS] [SECONDS]
#
# Needs root (`ip netns`). Env: FLEETLINK_BIN (default target/release/fleetlink), PYTHON
# (a venv with websockets; default .venv/bin/python).
set -euo pipefail
robots="${1:-10}"
seconds="${2:-10}"
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="${FLEETLINK_BIN:-$root/target/release/fleetlink}"
python="${PYTHON:-$root/.venv/bin/python}"
[ "$(id -u)" -eq 0 ] || { echo "needs root (network namespaces)" >&2; exit 1; }
[ -x "$bin" ] || { echo "build first: cargo build --release -p fleetlink" >&2; exit 1; }
bin="$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")"

id="$$"
hub_ns="fbh-$id" robot_ns="fbr-$id"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/fleetlink-bench-interest.XXXXXX")"
pids=()
cleanup() {
    for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
    wait 2>/dev/null || true
    for ns in "$hub_ns" "$robot_ns"; do
        for p in $(ip netns pids "$ns" 2>/dev/null); do kill -KILL "$p" 2>/dev/null || true; done
        ip netns del "$ns" 2>/dev/null || true
    done
    rm -rf "$tmp"
}
trap cleanup EXIT
ip netns add "$hub_ns"
ip netns add "$robot_ns"
ip link add vh netns "$hub_ns" type veth peer name vr netns "$robot_ns"
ip -n "$hub_ns" addr add 10.202.0.1/30 dev vh
ip -n "$robot_ns" addr add 10.202.0.2/30 dev vr
for ns in "$hub_ns" "$robot_ns"; do ip -n "$ns" link set lo up; done
ip -n "$hub_ns" link set vh up
ip -n "$robot_ns" link set vr up

data="$tmp/hub-data"
op_token="$("$bin" admin --data-dir "$data" token operator bench --group admin)"
ip netns exec "$hub_ns" "$bin" hub --listen 0.0.0.0:8080 --data-dir "$data" >"$tmp/hub.log" 2>&1 &
pids+=($!)
for _ in $(seq 100); do grep -q "listening" "$tmp/hub.log" && break; sleep 0.1; done

tx() { ip netns exec "$robot_ns" cat /sys/class/net/vr/statistics/tx_bytes; }

start_agents() { # always (true|false)
    agents=()
    for i in $(seq "$robots"); do
        local name="robot$i"
        local token
        token="$("$bin" admin --data-dir "$data" token robot "$name" 2>/dev/null)"
        {
            echo "hub: ws://10.202.0.1:8080/"
            echo "name: $name"
            echo "token: $token"
            echo "local_rosbridge: null"
            echo "sim: { seed: $i }"
            if [ "$1" = true ]; then
                echo "topics:"
                for t in /scan /odom /pose /points /camera/image/compressed; do
                    echo "  $t: { always: true }"
                done
            fi
        } >"$tmp/$name.yaml"
        ip netns exec "$robot_ns" "$bin" agent --config "$tmp/$name.yaml" >"$tmp/$name.log" 2>&1 &
        agents+=($!)
    done
    for i in $(seq "$robots"); do
        for _ in $(seq 100); do grep -q "connected to hub" "$tmp/robot$i.log" && break; sleep 0.1; done
    done
}

stop_agents() {
    for p in "${agents[@]}"; do kill "$p" 2>/dev/null || true; done
    for p in "${agents[@]}"; do wait "$p" 2>/dev/null || true; done
}

# The watcher: one rosbridge client at the hub on /robot1/pose, counting what it gets.
cat >"$tmp/watch.py" <<'EOF'
import json, sys, time
from websockets.sync.client import connect
url, token, secs = sys.argv[1], sys.argv[2], float(sys.argv[3])
with connect(url, additional_headers={"Authorization": f"Bearer {token}"}) as ws:
    ws.send(json.dumps({"op": "subscribe", "topic": "/robot1/pose", "id": "w"}))
    n, end = 0, time.monotonic() + secs
    while time.monotonic() < end:
        try:
            if '"publish"' in ws.recv(timeout=0.2):
                n += 1
        except TimeoutError:
            pass
    print(n)
EOF

measure() { # label always
    start_agents "$2"
    sleep 2 # connections made, topics announced
    ip netns exec "$hub_ns" "$python" "$tmp/watch.py" ws://127.0.0.1:8080/ "$op_token" \
        "$((seconds + 2))" >"$tmp/watch-$1.out" &
    local w=$!
    sleep 1
    local b0 t0 b1 t1
    b0="$(tx)"; t0="$(date +%s.%N)"
    sleep "$seconds"
    b1="$(tx)"; t1="$(date +%s.%N)"
    wait "$w" || true
    stop_agents
    python3 -c "
b = ($b1 - $b0) / ($t1 - $t0)
print(f'$1: {b:,.0f} B/s on the robots\' links ({b / $robots:,.0f} per robot); watcher got', open('$tmp/watch-$1.out').read().strip(), '/robot1/pose messages')
print(b, file=open('$tmp/rate-$1', 'w'))"
}

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $("$bin" --version)"
echo "$robots robots x 5 topics (simulator defaults), one watcher of /robot1/pose, ${seconds} s each"
measure interest false
measure always true
python3 -c "
a = float(open('$tmp/rate-always').read()); i = float(open('$tmp/rate-interest').read())
print(f'always / interest: {a / i:.1f}x fewer bytes with interest (target >= 20x)')"
