#!/usr/bin/env bash
# A robot's 1 MB point cloud at 30 Hz watched over the Foxglove WebSocket protocol and over
# rosbridge CBOR, through one hub, in the same run (issue 39's comparison): delivery ratio,
# latency from the cloud's header stamp to its arrival, and the hub's CPU per cloud from
# /proc. The robot is a `fleetlink.v1` link publishing CDR, as an agent on a ROS 2 robot
# does; Foxglove viewers get that CDR as it arrived, rosbridge CBOR viewers a conversion
# the hub makes once per cloud. Rounds alternate the protocols; the table gives medians.
#
#   cargo build --release -p fleetlink && scripts/bench-viewer.sh [ROUNDS] [VIEWERS] [SECONDS]
#
# Env: FLEETLINK_BIN (default target/release/fleetlink), SIZE (bytes of points, 1048576),
# RATE (Hz, 30).
set -euo pipefail
. "$(dirname "$0")/bench-lib.sh"
rounds="${1:-3}"
viewers="${2:-1 4}"
seconds="${3:-10}"
size="${SIZE:-1048576}" rate="${RATE:-30}"
bench_init viewer

token="$("$bin" admin --data-dir "$tmp/hub" token operator bench --group admin)"
port="$(free_port)"
"$bin" hub --listen "127.0.0.1:$port" --data-dir "$tmp/hub" --robot-network 127.0.0.0/8 >"$tmp/hub.log" 2>&1 &
hub_pid=$!; pids+=($hub_pid)
wait_port "$port"

for round in $(seq "$rounds"); do
    for n in $viewers; do
        for protocol in foxglove rosbridge-cbor; do
            FLEETLINK_TOKEN="$token" "$bin" bench viewer --protocol "$protocol" --hub "ws://127.0.0.1:$port" \
                --hub-pid "$hub_pid" --size "$size" --rate "$rate" --viewers "$n" --duration "$seconds" --json
        done
    done
    echo "round $round of $rounds done" >&2
done >"$tmp/results.jsonl"

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $("$bin" --version)"
python3 - "$tmp/results.jsonl" <<'PY'
import json, statistics, sys
rows = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
med = statistics.median
print(f"{'protocol':16} {'viewers':>7} {'size B':>9} {'Hz':>4} {'delivered':>10} {'p50 ms':>7} {'p99 ms':>7} {'hub CPU %':>9} {'hub ms/cloud':>12}")
for n in sorted({r["viewers"] for r in rows}):
    for proto in ("foxglove", "rosbridge-cbor"):
        rs = [r for r in rows if r["viewers"] == n and r["protocol"] == proto]
        if not rs:
            continue
        lat = [r["latency_ms"] for r in rs if r["latency_ms"]]
        print(f"{proto:16} {n:>7} {rs[0]['size']:>9} {rs[0]['rate']:>4g} "
              f"{med(r['delivery_ratio'] for r in rs) * 100:>9.1f}% "
              f"{med(l['p50'] for l in lat) if lat else float('nan'):>7.1f} "
              f"{med(l['p99'] for l in lat) if lat else float('nan'):>7.1f} "
              f"{med(r['hub_cpu_percent'] for r in rs):>9.1f} {med(r['hub_cpu_ms_per_cloud'] for r in rs):>12.2f}")
PY
