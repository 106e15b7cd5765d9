#!/usr/bin/env bash
# The hub recording a robot's mixed topics to MCAP (issue 39's target: 50 MB/s with no
# recorder drops and the recorder thread at most 25 % of a core). One robot publishes CDR
# as an agent on a ROS 2 robot does: a point cloud at 30 Hz sized to make the rate, a
# 640x480 image at 15 Hz, a laser scan at 40 Hz, IMU at 200 Hz, odometry at 50 Hz. Each
# round starts a recording through the API, measures, stops and deletes it; the table
# gives medians. The recordings go to a scratch directory on the same disk as $TMPDIR.
#
#   cargo build --release -p fleetlink && scripts/bench-record.sh [ROUNDS] [MB/s] [SECONDS]
#
# Env: FLEETLINK_BIN (default target/release/fleetlink), COMPRESSION (zstd, lz4 or none).
set -euo pipefail
. "$(dirname "$0")/bench-lib.sh"
rounds="${1:-3}"
rate="${2:-50}"
seconds="${3:-20}"
compression="${COMPRESSION:-zstd}"
bench_init record

token="$("$bin" admin --data-dir "$tmp/hub" token operator bench --group admin)"
port="$(free_port)"
"$bin" hub --listen "127.0.0.1:$port" --data-dir "$tmp/hub" --robot-network 127.0.0.0/8 >"$tmp/hub.log" 2>&1 &
hub_pid=$!; pids+=($hub_pid)
wait_port "$port"

for round in $(seq "$rounds"); do
    FLEETLINK_TOKEN="$token" "$bin" bench record --hub "ws://127.0.0.1:$port" --hub-pid "$hub_pid" \
        --rate-mb "$rate" --duration "$seconds" --compression "$compression" --json
    echo "round $round of $rounds done" >&2
done >"$tmp/results.jsonl"

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $("$bin" --version)"
python3 - "$tmp/results.jsonl" <<'PY'
import json, statistics, sys
rows = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
med = statistics.median
print(f"{'offered MB/s':>12} {'rounds':>6} {'sent':>7} {'recorded':>8} {'dropped':>7} {'MB written':>10} {'ratio':>6} {'recorder %core':>14} {'hub %':>6}")
print(f"{med(r['offered_mb_per_s'] for r in rows):>12.1f} {len(rows):>6} {med(r['sent'] for r in rows):>7.0f} "
      f"{med(r['recorded'] for r in rows):>8.0f} {max(r['dropped'] for r in rows):>7} "
      f"{med(r['file_bytes'] for r in rows) / 1e6:>10.1f} {med(r['compression_ratio'] for r in rows):>6.2f} "
      f"{med(r['recorder_cpu_percent'] for r in rows):>14.1f} {med(r['hub_cpu_percent'] for r in rows):>6.1f}")
PY
