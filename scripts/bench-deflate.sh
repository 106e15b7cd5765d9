#!/usr/bin/env bash
# permessage-deflate to viewers (issue 56), three figures in one run:
#
# 1. Bytes to a dashboard viewer of the demo robot view: `fleetlink demo`, two rosbridge
#    viewers at once subscribed to robot1's topics as the dashboard's robot view does
#    (pose and odometry as JSON, throttled; scan, cloud, camera and markers as CBOR), one
#    with permessage-deflate negotiated and one without; bytes read from each socket.
# 2. Hub CPU with 1 and with 10 deflate viewers of one topic (a robot's point cloud, CBOR,
#    from a separate agent so the hub process does only the relaying), and the same
#    without deflate: compression is done once per message, so 10 viewers must cost
#    little more than one.
# Hub CPU comes from /proc over the window (utime + stime); the hub runs on core 0 and the
# viewers (Python websockets) on core 1 when there are two cores. Rounds alternate the
# cases; the tables give medians.
#
#   cargo build --release -p fleetlink && scripts/bench-deflate.sh [ROUNDS] [SECONDS] [POINTS]
#   e.g. scripts/bench-deflate.sh 5 10 20000
#
# Env: FLEETLINK_BIN, PYTHON (a Python with `websockets`; default .venv/bin/python).
set -euo pipefail
. "$(dirname "$0")/bench-lib.sh"
rounds="${1:-3}"
seconds="${2:-10}"
points="${3:-20000}"
bench_init deflate
python="${PYTHON:-$root/.venv/bin/python}"
driver="$root/scripts/bench-deflate.py"
server_cpu=() gen_cpu=()
if [ "$(nproc)" -ge 2 ]; then server_cpu=(taskset -c 0); gen_cpu=(taskset -c 1); fi

wait_log() { # file regex
    for _ in $(seq 300); do
        v="$(sed -nE "s/$2/\1/p" "$1" | head -1)"
        [ -n "$v" ] && { echo "$v"; return 0; }
        sleep 0.05
    done
    echo "no line /$2/ in $1" >&2; cat "$1" >&2; exit 1
}
wait_topic() { # addr token topic
    for _ in $(seq 300); do
        curl -fsS -H "Authorization: Bearer $2" "http://$1/api/v1/robots" 2>/dev/null | grep -q "\"$3\"" && return 0
        sleep 0.05
    done
    echo "$3 not online" >&2; exit 1
}

# --- 1. bytes, demo robot view
demo_port="$(free_port)"
"${server_cpu[@]}" "$bin" demo --listen "127.0.0.1:$demo_port" --data-dir "$tmp/demo" >"$tmp/demo.log" 2>&1 &
demo_pid=$!; pids+=($demo_pid)
demo_token="$(wait_log "$tmp/demo.log" '^  the operator token \([^)]*\): (.+)$')"
wait_topic "127.0.0.1:$demo_port" "$demo_token" /robot1/points
view='[{"topic":"/robot1/pose","compression":"none","throttle_rate":50,"queue_length":1},
       {"topic":"/robot1/odom","compression":"none","throttle_rate":50,"queue_length":1},
       {"topic":"/robot1/markers","compression":"cbor","queue_length":10},
       {"topic":"/robot1/scan","compression":"cbor","queue_length":1},
       {"topic":"/robot1/points","compression":"cbor","queue_length":1},
       {"topic":"/robot1/camera","compression":"cbor","queue_length":1}]'
for round in $(seq "$rounds"); do
    "${gen_cpu[@]}" "$python" "$driver" bytes --url "ws://127.0.0.1:$demo_port/?token=$demo_token" \
        --subs "$view" --seconds "$seconds"
    echo "bytes round $round of $rounds done" >&2
done >"$tmp/bytes.jsonl"
kill "$demo_pid"; wait "$demo_pid" 2>/dev/null || true

# --- 2. CPU, N viewers of one topic
token="$("$bin" admin --data-dir "$tmp/hub" token operator bench --group admin)"
robot_token="$("$bin" admin --data-dir "$tmp/hub" token robot robot1)"
hub_port="$(free_port)"
"${server_cpu[@]}" "$bin" hub --listen "127.0.0.1:$hub_port" --data-dir "$tmp/hub" >"$tmp/hub.log" 2>&1 &
hub_pid=$!; pids+=($hub_pid)
wait_port "$hub_port"
cat >"$tmp/agent.yaml" <<YAML
hub: ws://127.0.0.1:$hub_port/
name: robot1
token: $robot_token
local_rosbridge: null
sim:
  point_cloud: { rate_hz: 10, points: $points }
YAML
"${gen_cpu[@]}" "$bin" agent --config "$tmp/agent.yaml" >"$tmp/agent.log" 2>&1 &
pids+=($!)
wait_topic "127.0.0.1:$hub_port" "$token" /robot1/points
cloud='[{"topic":"/robot1/points","compression":"cbor","queue_length":1}]'
for round in $(seq "$rounds"); do
    for n in 1 10; do
        for deflate in 1 0; do
            "${gen_cpu[@]}" "$python" "$driver" cpu --url "ws://127.0.0.1:$hub_port/?token=$token" \
                --subs "$cloud" --viewers "$n" --deflate "$deflate" --hub-pid "$hub_pid" --seconds "$seconds"
        done
    done
    echo "cpu round $round of $rounds done" >&2
done >"$tmp/cpu.jsonl"

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "binary: $bin ($("$bin" --version)); $rounds rounds of $seconds s; cloud $points points at 10 Hz"
python3 - "$tmp/bytes.jsonl" "$tmp/cpu.jsonl" <<'PY'
import json, statistics as st, sys
rows = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
d = st.median(r["deflate_bytes_per_s"] for r in rows)
p = st.median(r["plain_bytes_per_s"] for r in rows)
ratios = [r["deflate_bytes_per_s"] / r["plain_bytes_per_s"] for r in rows]
print("\n1. demo robot view, one dashboard viewer (medians)")
print(f"   without deflate {p / 1e3:10.1f} kB/s")
print(f"   with deflate    {d / 1e3:10.1f} kB/s   ratio {st.median(ratios):.3f} ({min(ratios):.3f}-{max(ratios):.3f})")
rows = [json.loads(l) for l in open(sys.argv[2]) if l.strip()]
print("\n2. hub CPU, viewers of one point cloud topic (medians)")
print(f"   {'viewers':>7} {'deflate':>7} {'hub CPU':>8} {'µs/delivery':>12} {'kB/s to viewers':>16}")
med = {}
for n in (1, 10):
    for dfl in (True, False):
        rs = [r for r in rows if r["viewers"] == n and r["deflate"] == dfl]
        cpu = st.median(r["hub_cpu_percent"] for r in rs)
        med[(n, dfl)] = cpu
        us = st.median(r["hub_cpu_us_per_delivery"] for r in rs)
        print(f"   {n:>7} {str(dfl):>7} {cpu:>7.2f}% {us:>12.1f} {st.median(r['bytes_per_s'] for r in rs) / 1e3:>16.1f}")
for dfl in (True, False):
    per_round = []
    for i in range(len(rows) // 4):
        one = [r for r in rows[i * 4:(i + 1) * 4] if r["viewers"] == 1 and r["deflate"] == dfl][0]
        ten = [r for r in rows[i * 4:(i + 1) * 4] if r["viewers"] == 10 and r["deflate"] == dfl][0]
        per_round.append(ten["hub_cpu_percent"] / one["hub_cpu_percent"])
    print(f"   10 viewers / 1 viewer, deflate {dfl}: {st.median(per_round):.2f}x "
          f"(per round {', '.join(f'{x:.2f}' for x in per_round)})")
PY
